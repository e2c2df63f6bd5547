// Stage: setup. Reads clipped triangles/segments (clip space) from primitive.cpp, projects
// them, snaps to fixed point (fixed_point.hpp), culls by facing, and writes SetupTriangle /
// SetupLine records plus their plane equations into the Frame for binning (bin.cpp).
#pragma once

#include <algorithm>
#include <cstdint>

#include "pipeline/frame.hpp"
#include "pipeline/geometry/primitive_sink.hpp"
#include "pipeline/setup/fixed_point.hpp"

namespace facet::pipeline {

// Perspective divide and viewport transform. Inline: the vertex stage runs it once per vertex.
inline ScreenVertex to_screen(const glm::vec4& clip, int width, int height) {
  float inv_w = 1.0f / clip.w;
  float ndc_x = clip.x * inv_w;
  float ndc_y = clip.y * inv_w;
  float ndc_z = clip.z * inv_w;
  float sx = (ndc_x * 0.5f + 0.5f) * static_cast<float>(width);
  float sy = (0.5f - ndc_y * 0.5f) * static_cast<float>(height);
  return {snap(sx), snap(sy), ndc_z * 0.5f + 0.5f, inv_w};
}

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

  // out[k] = plane(values[0][k], values[1][k], values[2][k]) for k < count, bit for bit, several
  // k at a time on SIMD targets (setup_planes.cpp).
  void planes(const float* const values[3], int count, Plane* out) const;

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
// cover none of its pixel centres (covers_a_centre): they would draw nothing, yet be written,
// binned and visited by every tile they touch. In `million`, 16 % of the small triangles'
// tile visits found no pixel, their boxes 3.5 pixels on average.
inline constexpr int kProbedBoxSide = 4;
// ... and whose vertices span less than this many fixed-point units (64 pixels) a side, which
// a box of at most kProbedBoxSide centres a side does unless the frame's edge clamped it: the
// batch kernel's probe then computes in 32 bits (setup_batch.cpp).
inline constexpr std::int32_t kProbedSpan = 1 << 14;

// Whether triangle t, its edges and pixel box set, covers the centre of a pixel of its box.
inline bool covers_a_centre(const SetupTriangle& t) {
  for (int y = t.min_y; y <= t.max_y; ++y) {
    for (int x = t.min_x; x <= t.max_x; ++x) {
      if (edge_at_centre(t, 0, x, y) >= 0 && edge_at_centre(t, 1, x, y) >= 0 &&
          edge_at_centre(t, 2, x, y) >= 0) {
        return true;
      }
    }
  }
  return false;
}

// Sets up one triangle (already clipped to the guard band and in front of the eye) of draw
// `draw`. `front_facing` is its facing as decided before clipping; the snapped triangle is
// dropped if it is degenerate, its snapped winding disagrees or, small, it covers no pixel
// centre (kProbedBoxSide). Returns true if appended.
bool setup_triangle(PrimitiveSink& out, int width, int height, std::uint32_t draw,
                    const ClipVertex* const v[3], int varyings, bool front_facing);

// The same from vertices already projected (to_screen) with their varyings already multiplied
// by inv_w (over_w[i] points at vertex i's `varyings` floats): the fast path for triangles that
// need no clipping, whose vertices the vertex stage projected once for all their triangles.
// Always inline (it is too big for GCC to inline by itself) so that primitive assembly's
// arrays reach it in registers: passed through memory they were written as 8-byte stores and
// read back as 16-byte loads, which stall store forwarding (a fifth of setup's time).
[[gnu::always_inline]] inline bool setup_projected_triangle(PrimitiveSink& out, int width,
                                                            int height, std::uint32_t draw,
                                                            const ScreenVertex screen[3],
                                                            const float* const over_w[3],
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
  if (t.max_x - t.min_x < kProbedBoxSide && t.max_y - t.min_y < kProbedBoxSide &&
      max_x - min_x < kProbedSpan && max_y - min_y < kProbedSpan && !covers_a_centre(t)) {
    return false;
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

// Sets up one clipped segment; returns true if it touches the framebuffer.
bool setup_line(PrimitiveSink& out, int width, int height, const glm::vec4& a, const glm::vec4& b,
                const glm::vec4& color);

}  // namespace facet::pipeline
