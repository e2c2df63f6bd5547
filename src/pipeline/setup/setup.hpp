// Stage: setup, its definitions. Triangles are set up by the setup kernel (setup_batch.hpp),
// segments by setup_line and points by setup_point here: all project (to_screen), snap to fixed
// point (fixed_point.hpp) and write SetupTriangle / SetupLine / SetupPoint records (and the
// triangles' plane equations) into the Frame for binning (bin/). What the kernel and the reference
// rasterizer share is here: the viewport transform, the signed area, the fill rule, the plane
// solver, the pixel-centre bounds.
#pragma once

#include <algorithm>
#include <cstdint>

#include "pipeline/frame.hpp"
#include "pipeline/geometry/primitive_sink.hpp"
#include "pipeline/setup/fixed_point.hpp"

namespace facet::pipeline {

// Signed doubled area in fixed-point units. With y down, front faces (counter-clockwise in
// OpenGL's y-up NDC) have negative area.
inline std::int64_t signed_area(const ScreenVertex& v0, const ScreenVertex& v1,
                                const ScreenVertex& v2) {
  return std::int64_t{v1.x - v0.x} * (v2.y - v0.y) - std::int64_t{v1.y - v0.y} * (v2.x - v0.x);
}

// Top-left rule (D3D11 functional spec 3.4.2.1; GL 4.6 14.6.1 leaves it to the
// implementation): for a triangle wound clockwise on a y-down screen (positive signed_area),
// an edge from (x0, y0) to (x1, y1) is a top edge when horizontal and pointing right, a left
// edge when pointing up. Pixels whose centre lies exactly on an edge belong to the triangle
// only if that edge is top or left, so a shared edge is covered exactly once.
inline bool is_top_left(std::int32_t dx, std::int32_t dy) { return (dy == 0 && dx > 0) || dy < 0; }

// Planes through three screen points (pixels): value = at_ref + dx*(x - x0) + dy*(y - y0).
// The 2x2 system is the same for every attribute of a triangle, so it is inverted once
// (Cramer's rule, in double: it can be badly conditioned for slivers) and each plane then
// costs a few multiplications.
class PlaneSolver {
 public:
  // The 2x2 system, vertex 0 at the origin, and the inverse of its determinant.
  struct Coefficients {
    double x1, y1, x2, y2, inv_det;
  };

  explicit PlaneSolver(const Coefficients& c) : c_(c) {}
  PlaneSolver(const float x[3], const float y[3]) {
    c_.x1 = double{x[1]} - x[0];
    c_.y1 = double{y[1]} - y[0];
    c_.x2 = double{x[2]} - x[0];
    c_.y2 = double{y[2]} - y[0];
    c_.inv_det = 1.0 / (c_.x1 * c_.y2 - c_.x2 * c_.y1);
  }

  Plane plane(const float value[3]) const { return plane(value[0], value[1], value[2]); }
  Plane plane(float value0, float value1, float value2) const {
    double v1 = double{value1} - value0, v2 = double{value2} - value0;
    Plane p;
    p.at_ref = value0;
    p.dx = static_cast<float>((v1 * c_.y2 - v2 * c_.y1) * c_.inv_det);
    p.dy = static_cast<float>((v2 * c_.x1 - v1 * c_.x2) * c_.inv_det);
    return p;
  }

 private:
  Coefficients c_;
};

// One plane through three (x, y, value) points (a PlaneSolver used once).
Plane make_plane(const float x[3], const float y[3], const float value[3]);

// Evaluated as (row part) + (column part) so the rasterizer can compute the row part once per
// row with bit-identical results (evaluate_row then evaluate_in_row).
inline float evaluate_row(const Plane& p, float ref_y, float py) {
  return p.at_ref + p.dy * (py - ref_y);
}
inline float evaluate_in_row(float row, const Plane& p, float ref_x, float px) {
  return row + p.dx * (px - ref_x);
}
inline float evaluate(const Plane& p, float ref_x, float ref_y, float px, float py) {
  return evaluate_in_row(evaluate_row(p, ref_y, py), p, ref_x, px);
}

// Smallest and largest depth a triangle's plane takes at the pixel centres of the pixel
// rectangle [x0, x1] x [y0, y1] (inclusive). The per-pixel depth (evaluate_row, then
// evaluate_in_row) is monotonic in x and in y, as each of its rounding steps is, so both ends
// are at corners, computed here with the same operations: exact bounds, no margin needed.
struct DepthRange {
  float nearest, farthest;  // NaN when the plane gives NaN at a corner
};
inline DepthRange depth_range_over(const SetupTriangle& t, int x0, int y0, int x1, int y1) {
  const float left = static_cast<float>(x0) + 0.5f, right = static_cast<float>(x1) + 0.5f;
  const float top = static_cast<float>(y0) + 0.5f, bottom = static_cast<float>(y1) + 0.5f;
  const float z[4] = {evaluate(t.z, t.ref_x, t.ref_y, left, top),
                      evaluate(t.z, t.ref_x, t.ref_y, right, top),
                      evaluate(t.z, t.ref_x, t.ref_y, left, bottom),
                      evaluate(t.z, t.ref_x, t.ref_y, right, bottom)};
  DepthRange range{z[0], z[0]};
  for (float v : z) {
    if (v != v) return {v, v};  // NaN
    range.nearest = v < range.nearest ? v : range.nearest;
    range.farthest = v > range.farthest ? v : range.farthest;
  }
  return range;
}

// Pixels whose centre may be covered by something spanning [lo, hi] (fixed point):
// first centre >= lo and last centre <= hi.
inline int first_centre_at_or_after(std::int64_t lo) {
  return static_cast<int>(floor_div(lo - kHalfPixel + kSubpixelScale - 1, kSubpixelScale));
}
inline int last_centre_at_or_before(std::int64_t hi) {
  return static_cast<int>(floor_div(hi - kHalfPixel, kSubpixelScale));
}

// Triangles whose pixel box is at most this many pixels a side are dropped at setup when they
// cover none of its pixel centres: they would draw nothing, yet be written, binned and visited
// by every tile they touch, and scenes of tiny triangles have many such.
inline constexpr int kProbedBoxSide = 4;
// ... and whose vertices span less than this many fixed-point units (64 pixels) a side, which
// a box of at most kProbedBoxSide centres a side does unless the frame's edge clamped it: the
// batch kernel's probe then computes in 32 bits (setup_batch.cpp).
inline constexpr std::int32_t kProbedSpan = 1 << 14;

// Sets up one clipped segment between screen vertices s0 and s1 (the vertex stage's projection,
// ProjectToScreenKernel); returns true if it touches the framebuffer.
bool setup_line(PrimitiveSink& out, int width, int height, const ScreenVertex& s0,
                const ScreenVertex& s1, const glm::vec4& color);

// The pixels a point covers along one axis: those whose centre lies in the half-open span
// [centre - half, centre + half) (fixed point), as [first, last]; first > last when none.
// A side of n whole pixels (half = n * kHalfPixel) covers exactly n pixels wherever the centre
// is, and points spaced n pixels apart tile without gaps or doubled pixels.
struct PixelSpan {
  int first, last;
};
inline PixelSpan point_span(std::int32_t centre, std::int32_t half) {
  const std::int64_t lo = std::int64_t{centre} - half, hi = std::int64_t{centre} + half;
  return {first_centre_at_or_after(lo), last_centre_at_or_before(hi - 1)};
}

// Half a point's side in fixed point, from its size in pixels (Material::point_size).
inline std::int32_t point_half_side(float size_pixels) { return snap(size_pixels * 0.5f); }

// Sets up one point centred at s (inside the frustum: its screen position is finite and within
// the frame, its depth in [0, 1]) with the given half side (fixed point); returns true if it
// covers a pixel of the framebuffer. Fill rule: point.cpp.
bool setup_point(PrimitiveSink& out, int width, int height, const ScreenVertex& s,
                 std::int32_t half, const glm::vec4& color);

}  // namespace facet::pipeline
