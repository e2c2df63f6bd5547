// Homogeneous clipping (Sutherland-Hodgman in clip space). Read by primitive.cpp (the fast
// path) and reference.cpp. A triangle is clipped against near and far always and against the
// sides only when a vertex leaves the guard band (fixed_point.hpp), where fixed point would
// overflow; inside the guard band the rasterizer's bounding box does the side clipping.
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
};
inline constexpr int kClipPlaneCount = 6;

// Sutherland-Hodgman adds at most one vertex per plane: 3 + 6.
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
};

ClipBounds guard_band_bounds(int width, int height);

// Clips the polygon against each plane in `planes`; interpolates `varyings` floats.
// Leaves count < 3 when nothing remains.
void clip_polygon(ClipPolygon& polygon, unsigned planes, const ClipBounds& bounds, int varyings);

// Clips a segment in place; returns false when nothing remains.
bool clip_segment(glm::vec4& a, glm::vec4& b, unsigned planes, const ClipBounds& bounds);

}  // namespace facet::pipeline
