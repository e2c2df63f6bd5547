// The reference rasterizer (see reference.hpp). Read this file first to learn the pipeline:
// every step the fast path takes is here in its plainest form.
#include "pipeline/reference.hpp"

#include <algorithm>
#include <cmath>

#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/primitive.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {
namespace {

// Coverage of one pixel centre by an edge from p to q of a triangle wound clockwise on screen.
bool inside_edge(const ScreenVertex& p, const ScreenVertex& q, std::int64_t cx, std::int64_t cy) {
  std::int64_t e = (std::int64_t{q.x} - p.x) * (cy - p.y) - (std::int64_t{q.y} - p.y) * (cx - p.x);
  return e > 0 || (e == 0 && is_top_left(q.x - p.x, q.y - p.y));
}

void rasterize(ScreenVertex s[3], bool front_facing, ReferenceImage& image) {
  std::int64_t area = signed_area(s[0], s[1], s[2]);
  if (area == 0 || (area < 0) != front_facing) return;  // degenerate once snapped
  if (area < 0) std::swap(s[1], s[2]);
  float px[3], py[3], z[3];
  for (int i = 0; i < 3; ++i) {
    px[i] = static_cast<float>(s[i].x) / kSubpixelScale;
    py[i] = static_cast<float>(s[i].y) / kSubpixelScale;
    z[i] = s[i].z;
  }
  Plane depth = make_plane(px, py, z);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::int64_t cx = pixel_centre(x), cy = pixel_centre(y);
      if (!inside_edge(s[0], s[1], cx, cy) || !inside_edge(s[1], s[2], cx, cy) ||
          !inside_edge(s[2], s[0], cx, cy)) {
        continue;
      }
      std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      ++image.coverage[i];
      float d = evaluate(depth, px[0], py[0], x + 0.5f, y + 0.5f);
      if (d < image.depth[i]) image.depth[i] = d;
    }
  }
}

}  // namespace

ReferenceImage reference_rasterize(const std::vector<glm::vec3>& positions,
                                   const glm::mat4& model_view_projection, CullMode cull, int width,
                                   int height) {
  ReferenceImage image{width, height, std::vector<int>(std::size_t(width) * height, 0),
                       std::vector<float>(std::size_t(width) * height, 1.0f)};
  const ClipBounds frustum{1.0f, 1.0f};
  const ClipBounds guard = guard_band_bounds(width, height);
  for (std::size_t t = 0; t + 2 < positions.size(); t += 3) {
    ClipPolygon polygon;
    polygon.count = 3;
    bool finite = true;
    for (int i = 0; i < 3; ++i) {
      glm::vec4 c = model_view_projection * glm::vec4(positions[t + i], 1.0f);
      polygon.vertices[i].clip = c;
      finite = finite && std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) &&
               std::isfinite(c.w);
    }
    const ClipVertex* v = polygon.vertices;
    if (!finite) continue;
    if (outcode(v[0].clip, frustum) & outcode(v[1].clip, frustum) & outcode(v[2].clip, frustum)) {
      continue;
    }
    double orientation = homogeneous_orientation(v[0].clip, v[1].clip, v[2].clip);
    bool front = orientation > 0.0;
    if (orientation == 0.0 || (cull == CullMode::back && !front) ||
        (cull == CullMode::front && front)) {
      continue;
    }
    unsigned planes =
        outcode(v[0].clip, guard) | outcode(v[1].clip, guard) | outcode(v[2].clip, guard);
    if (planes) clip_polygon(polygon, planes, guard, 0);
    for (int i = 1; i + 1 < polygon.count; ++i) {
      ScreenVertex s[3] = {to_screen(v[0].clip, width, height), to_screen(v[i].clip, width, height),
                           to_screen(v[i + 1].clip, width, height)};
      rasterize(s, front, image);
    }
  }
  return image;
}

}  // namespace facet::pipeline
