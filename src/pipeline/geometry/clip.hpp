// Homogeneous clipping (Sutherland-Hodgman in clip space). Read by primitive.cpp (the fast
// path) and reference.cpp. A triangle is clipped against near and far always and against the
// sides only when a vertex leaves the guard band (fixed_point.hpp), where fixed point would
// overflow; inside the guard band the rasterizer's bounding box does the side clipping. A
// frame may add a plane of its own (ClipBounds::user_plane: a planar reflection's mirror).
#pragma once

#include <glm/vec4.hpp>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

enum ClipPlane : unsigned {
  kClipNear = 1u << 0,
  kClipFar = 1u << 1,
  kClipLeft = 1u << 2,
  kClipRight = 1u << 3,
  kClipBottom = 1u << 4,
  kClipTop = 1u << 5,
  kClipUser = 1u << 6,  // ClipBounds::user_plane, in frames that have one
};
inline constexpr int kClipPlaneCount = 7;

// The frustum's outcode bits of ProjectedVertex::codes.
inline constexpr unsigned kFrustumCodes = (1u << kClipPlaneCount) - 1;

// The planes a triangle whose vertices' codes or-ed are `codes` must be clipped against (none:
// its screen vertices are meaningful, and setup takes it as it is). Near, far and a user plane
// are the same planes in both bounds; the guard band's sides only need checking when a vertex is
// outside the frustum's sides (the guard band contains them).
inline unsigned planes_to_clip(unsigned codes) {
  const unsigned any_out = codes & kFrustumCodes;
  if (any_out & (kClipLeft | kClipRight | kClipBottom | kClipTop)) {
    return codes >> kGuardCodeShift & kFrustumCodes;
  }
  return any_out & (kClipNear | kClipFar | kClipUser);
}

// Sutherland-Hodgman adds at most one vertex per plane: 3 + 7.
inline constexpr int kMaxClipVertices = 3 + kClipPlaneCount;

struct ClipPolygon {
  ClipVertex vertices[kMaxClipVertices];
  int count = 0;
};

// Side planes sit at x = +-gx * w and y = +-gy * w: the guard band for the frame size
// (gx = gy = 1 gives the view frustum itself).
struct ClipBounds {
  float gx = 1.0f;
  float gy = 1.0f;
  // A plane in clip space (a, b, c, d), inside where user_plane_distance >= 0, tested only when
  // clips_user_plane: a reflection pass's mirror plane, behind which nothing may be seen.
  bool clips_user_plane = false;
  glm::vec4 user_plane{0.0f};
};

// The signed distance of clip position c to a user plane, in the order every test of it uses
// (the vertex pass's SIMD lanes included): (a x + b y) + (c z + d w).
inline float user_plane_distance(const glm::vec4& plane, const glm::vec4& c) {
  return (plane.x * c.x + plane.y * c.y) + (plane.z * c.z + plane.w * c.w);
}

// The guard band for the frame size, with the frame's own plane (Frame::clip_plane) if any.
ClipBounds guard_band_bounds(int width, int height);
ClipBounds guard_band_bounds(const Frame& frame);

// Clips the polygon against each plane in `planes`; interpolates `varyings` floats.
// Leaves count < 3 when nothing remains.
void clip_polygon(ClipPolygon& polygon, unsigned planes, const ClipBounds& bounds, int varyings);

// Clips a segment in place; returns false when nothing remains.
bool clip_segment(glm::vec4& a, glm::vec4& b, unsigned planes, const ClipBounds& bounds);

}  // namespace facet::pipeline
