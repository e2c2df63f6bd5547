// Stage: setup (see setup.hpp).
#include "pipeline/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "pipeline/fixed_point.hpp"

namespace facet::pipeline {
namespace {

// Pixels whose centre may be covered by something spanning [lo, hi] (fixed point):
// first centre >= lo and last centre <= hi.
int first_centre_at_or_after(std::int64_t lo) {
  return static_cast<int>(floor_div(lo - kHalfPixel + kSubpixelScale - 1, kSubpixelScale));
}
int last_centre_at_or_before(std::int64_t hi) {
  return static_cast<int>(floor_div(hi - kHalfPixel, kSubpixelScale));
}

}  // namespace

Plane make_plane(const float x[3], const float y[3], const float value[3]) {
  return PlaneSolver(x, y).plane(value);
}

bool setup_projected_triangle(PrimitiveSink& out, int width, int height, std::uint32_t draw,
                              const ScreenVertex screen[3], const float* const over_w[3],
                              int varyings, bool front_facing) {
  ScreenVertex s[3] = {screen[0], screen[1], screen[2]};
  const float* values[3] = {over_w[0], over_w[1], over_w[2]};
  std::int64_t area = signed_area(s[0], s[1], s[2]);
  // Degenerate after snapping, or snapping flipped a sliver: no pixel centres to cover.
  if (area == 0 || (area < 0) != front_facing) return false;
  if (area < 0) {  // make the winding clockwise on screen (positive area) for the edge tests
    std::swap(s[1], s[2]);
    std::swap(values[1], values[2]);
  }

  SetupTriangle t;
  std::int64_t min_x = std::min({s[0].x, s[1].x, s[2].x}),
               max_x = std::max({s[0].x, s[1].x, s[2].x});
  std::int64_t min_y = std::min({s[0].y, s[1].y, s[2].y}),
               max_y = std::max({s[0].y, s[1].y, s[2].y});
  t.min_x = std::max(0, first_centre_at_or_after(min_x));
  t.min_y = std::max(0, first_centre_at_or_after(min_y));
  t.max_x = std::min(width - 1, last_centre_at_or_before(max_x));
  t.max_y = std::min(height - 1, last_centre_at_or_before(max_y));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return false;

  for (int i = 0; i < 3; ++i) {
    const ScreenVertex& p = s[i];
    const ScreenVertex& q = s[(i + 1) % 3];
    // E(X, Y) = (qx - px)(Y - py) - (qy - py)(X - px): positive inside a clockwise triangle.
    t.a[i] = p.y - q.y;
    t.b[i] = q.x - p.x;
    const std::int64_t bias = is_top_left(q.x - p.x, q.y - p.y) ? 0 : -1;
    t.c[i] = -(std::int64_t{t.a[i]} * p.x + std::int64_t{t.b[i]} * p.y) + bias;
  }

  float px[3], py[3];
  for (int i = 0; i < 3; ++i) {
    px[i] = static_cast<float>(s[i].x) / kSubpixelScale;
    py[i] = static_cast<float>(s[i].y) / kSubpixelScale;
  }
  t.ref_x = px[0];
  t.ref_y = py[0];
  const PlaneSolver solver(px, py);
  t.z = solver.plane(s[0].z, s[1].z, s[2].z);
  t.inv_w = solver.plane(s[0].inv_w, s[1].inv_w, s[2].inv_w);
  const TriangleSlot slot = out.add_triangle(t);
  solver.planes(values, varyings, slot.planes);
  t.varying_planes = slot.plane_index;
  t.draw = draw;
  *slot.triangle = t;
  return true;
}

bool setup_triangle(PrimitiveSink& out, int width, int height, std::uint32_t draw,
                    const ClipVertex* const v[3], int varyings, bool front_facing) {
  ScreenVertex s[3];
  float over_w[3][kMaxVaryings];
  for (int i = 0; i < 3; ++i) {
    s[i] = to_screen(v[i]->clip, width, height);
    for (int k = 0; k < varyings; ++k) over_w[i][k] = v[i]->varyings[k] * s[i].inv_w;
  }
  const float* values[3] = {over_w[0], over_w[1], over_w[2]};
  return setup_projected_triangle(out, width, height, draw, s, values, varyings, front_facing);
}

bool setup_line(PrimitiveSink& out, int width, int height, const glm::vec4& a, const glm::vec4& b,
                const glm::vec4& color) {
  ScreenVertex s0 = to_screen(a, width, height);
  ScreenVertex s1 = to_screen(b, width, height);
  if (s0.x == s1.x && s0.y == s1.y) return false;
  SetupLine l;
  l.x0 = s0.x, l.y0 = s0.y, l.x1 = s1.x, l.y1 = s1.y;
  l.z0 = s0.z, l.z1 = s1.z;
  l.min_x = std::max(0, static_cast<int>(floor_div(std::min(l.x0, l.x1), kSubpixelScale)));
  l.min_y = std::max(0, static_cast<int>(floor_div(std::min(l.y0, l.y1), kSubpixelScale)));
  l.max_x = std::min(width - 1, static_cast<int>(floor_div(std::max(l.x0, l.x1), kSubpixelScale)));
  l.max_y = std::min(height - 1, static_cast<int>(floor_div(std::max(l.y0, l.y1), kSubpixelScale)));
  if (l.min_x > l.max_x || l.min_y > l.max_y) return false;
  l.color = color;
  out.add_line(l.min_x, l.min_y, l.max_x, l.max_y) = l;
  return true;
}

}  // namespace facet::pipeline
