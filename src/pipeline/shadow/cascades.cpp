// A sun's cascades: their count, splits and blend bands (see cascades.hpp).
#include "pipeline/shadow/cascades.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "shading/shadow_map.hpp"

namespace facet::pipeline {
namespace {

// A convex polygon clipped by planes: in exact arithmetic a quad gains at most one vertex per
// plane, and it is clipped by six (4 + 6). Rounding can make a face lying almost in a plane
// alternate sides and gain more; vertices past the room are dropped (only the depths' extremes
// are wanted, and those vertices lie on the plane, by the ones kept).
struct Polygon {
  static constexpr int kMaxVertices = 10;
  glm::vec3 v[kMaxVertices];
  int count = 0;
  void add(const glm::vec3& p) {
    if (count < kMaxVertices) v[count++] = p;
  }
};

// The part of `polygon` where dot(plane, (p, 1)) >= 0 (Sutherland-Hodgman, one plane).
Polygon clip(const Polygon& polygon, glm::vec4 plane) {
  Polygon out;
  for (int i = 0; i < polygon.count; ++i) {
    const glm::vec3 a = polygon.v[i], b = polygon.v[(i + 1) % polygon.count];
    const float da = glm::dot(plane, glm::vec4(a, 1.0f)), db = glm::dot(plane, glm::vec4(b, 1.0f));
    if (da >= 0.0f) out.add(a);
    if ((da >= 0.0f) != (db >= 0.0f)) out.add(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// Face f (0..5) of a hexahedron whose corners are numbered as WorldBox::corner's: the four
// corners with bit f / 2 equal to f % 2, in order around the face.
Polygon face(const glm::vec3 (&corners)[8], int f) {
  const int axis = f / 2, side = (f % 2) << axis;
  const int u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3);
  Polygon p;
  for (const int c : {0, u, u | v, v}) p.v[p.count++] = corners[side | c];
  return p;
}

// Adds to `depths` the view depths of each face of `solid` clipped to the six half-spaces of
// `inside`.
void add_clipped_faces(const glm::vec3 (&solid)[8], const glm::vec4 (&inside)[6],
                       const glm::mat4& camera_view, ViewDepths& depths) {
  for (int f = 0; f < 6; ++f) {
    Polygon p = face(solid, f);
    for (int k = 0; k < 6 && p.count > 0; ++k) p = clip(p, inside[k]);
    for (int i = 0; i < p.count; ++i) {
      const float depth = -(camera_view * glm::vec4(p.v[i], 1.0f)).z;
      depths.nearest = std::min(depths.nearest, depth);
      depths.farthest = std::max(depths.farthest, depth);
    }
  }
}

}  // namespace

ViewDepths scene_depths(const Camera& view, const WorldBox& scene) {
  if (scene.empty()) return {1.0f, 0.0f};
  float nearest = 1e30f, farthest = -1e30f;
  const glm::mat4 camera_view = view.view();
  for (int corner = 0; corner < 8; ++corner) {
    const float depth = -(camera_view * glm::vec4(scene.corner(corner), 1.0f)).z;
    nearest = std::min(nearest, depth), farthest = std::max(farthest, depth);
  }
  return {std::max(nearest, view.near_plane), std::min(farthest, view.far_plane)};
}

ViewDepths seen_depths(const Camera& view, const WorldBox& scene) {
  ViewDepths depths{1e30f, -1e30f};
  if (scene.empty()) return depths;
  // Depth is linear in world position, so its extremes over the intersection of the box and the
  // frustum (both convex) lie on the intersection's boundary: on the box's faces within the
  // frustum or on the frustum's faces within the box.
  const glm::mat4 view_projection = view.view_projection();
  glm::vec3 box[8], frustum[8];
  glm::vec4 in_box[6], in_frustum[6];
  for (int corner = 0; corner < 8; ++corner) box[corner] = scene.corner(corner);
  frustum_corners(view, frustum);
  // Within the frustum: -w <= x, y, z <= w in clip space (rows of the view-projection).
  const glm::mat4 rows = glm::transpose(view_projection);
  for (int axis = 0; axis < 3; ++axis) {
    in_frustum[2 * axis] = rows[3] + rows[axis];
    in_frustum[2 * axis + 1] = rows[3] - rows[axis];
    glm::vec4 low(0.0f), high(0.0f);
    low[axis] = 1.0f, low.w = -scene.low[axis];
    high[axis] = -1.0f, high.w = scene.high[axis];
    in_box[2 * axis] = low, in_box[2 * axis + 1] = high;
  }
  const glm::mat4 camera_view = view.view();
  add_clipped_faces(box, in_frustum, camera_view, depths);
  add_clipped_faces(frustum, in_box, camera_view, depths);
  return depths;
}

int automatic_cascade_count(const Camera& view, const WorldBox& scene) {
  if (view.projection_kind != Projection::perspective) return 1;
  const ViewDepths depths = seen_depths(view, scene);
  if (!(depths.nearest <= depths.farthest)) return 1;
  const float nearest = std::max(depths.nearest, view.near_plane);
  float reach = nearest * kCascadeDepthRatio;
  int count = 1;
  while (count < shading::kMaxShadowCascades && !(depths.farthest <= reach)) {
    reach *= kCascadeDepthRatio;
    ++count;
  }
  return count;
}

void cascade_splits(ViewDepths depths, int count, float* split) {
  constexpr float kLogarithmic = 0.8f;
  // A perspective view's nearest depth is positive; an orthographic one's may be 0, where the
  // logarithmic steps would all be 0: start those at a thousandth of the far depth.
  const float near = std::max(depths.nearest, depths.farthest * 1e-3f), far = depths.farthest;
  split[0] = depths.nearest;
  for (int i = 1; i < count; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(count);
    const float logarithmic = near * std::pow(far / near, t);
    const float even = depths.nearest + (far - depths.nearest) * t;
    split[i] = kLogarithmic * logarithmic + (1.0f - kLogarithmic) * even;
  }
  split[count] = far;
}

float cascade_blend_start(const float* split, int i) {
  return split[i + 1] - kCascadeBlendShare * (split[i + 1] - split[i]);
}

}  // namespace facet::pipeline
