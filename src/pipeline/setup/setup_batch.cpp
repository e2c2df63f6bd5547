// Stage: setup of triangles (see setup_batch.hpp). Highway compiles this file once per SIMD
// target (foreach_target.h re-includes it); setup_batch_kernel() hands out the chosen target's
// kernel.
//
// The same bits on every target: each lane does PlaneSolver's (setup.hpp) double operations in
// its order (no fused multiply-add: -ffp-contract=off, and Highway's Mul/Sub/Div are single
// instructions), and its conversions are exact or correctly rounded. The integer products
// (signed area, edge constants) are done in double, where they are exact: snapped coordinates
// lie in the guard band (triangles that needed clipping were clipped to it), within +-2^22
// fixed-point units (fixed_point.hpp), so every product stays below 2^46 and every sum below
// 2^47 < 2^53.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/setup/setup_batch.cpp"
#include "pipeline/setup/setup_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <bit>
#include <limits>

#include "core/simd_target.hpp"
#include "pipeline/geometry/projected_load-inl.h"
#include "pipeline/setup/back_faces.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "pipeline/setup/pixel_box-inl.h"
#include "pipeline/setup/sample_positions.hpp"
#include "pipeline/setup/setup.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DoubleTag = hn::ScalableTag<double>;
using FloatTag = hn::Rebind<float, DoubleTag>;
using IntTag = hn::Rebind<std::int32_t, DoubleTag>;
using WideTag = hn::Rebind<std::int64_t, DoubleTag>;
using DoubleVec = hn::Vec<DoubleTag>;
using FloatVec = hn::Vec<FloatTag>;
using IntVec = hn::Vec<IntTag>;

// static_cast<float> of each lane. The portable targets' DemoteTo clamps values beyond the
// largest float to it, where C++ (and every x86 target) rounds them to infinity.
HWY_INLINE FloatVec ToFloat(DoubleVec v) {
  const FloatTag df;
#if HWY_TARGET == HWY_EMU128 || HWY_TARGET == HWY_SCALAR
  const DoubleTag dd;
  double in[hn::MaxLanes(dd)];
  float out[hn::MaxLanes(df)];
  hn::StoreU(v, dd, in);
  for (std::size_t i = 0; i < hn::Lanes(dd); ++i) out[i] = static_cast<float>(in[i]);
  return hn::LoadU(df, out);
#else
  return hn::DemoteTo(df, v);
#endif
}

HWY_INLINE DoubleVec ToDouble(FloatVec v) { return hn::PromoteTo(DoubleTag(), v); }

// PlaneSolver's coefficients (setup.hpp): one triangle's in every lane, or one per lane.
struct Coefficients {
  DoubleVec x1, y1, x2, y2, inv_det;

  // PlaneSolver::plane's dx and dy through values v0, v1, v2 at the three vertices.
  void solve(FloatVec v0, FloatVec v1, FloatVec v2, FloatVec& dx, FloatVec& dy) const {
    const DoubleVec d0 = ToDouble(v0);
    const DoubleVec d1 = hn::Sub(ToDouble(v1), d0), d2 = hn::Sub(ToDouble(v2), d0);
    dx = ToFloat(hn::Mul(hn::Sub(hn::Mul(d1, y2), hn::Mul(d2, y1)), inv_det));
    dy = ToFloat(hn::Mul(hn::Sub(hn::Mul(d2, x1), hn::Mul(d1, x2)), inv_det));
  }
  // Planes [k, k + lanes) through the vertices' varyings, stored as Planes (float triples).
  void solve_planes(const float* const v[3], int k, float* out) const {
    const FloatTag df;
    const FloatVec v0 = hn::LoadU(df, v[0] + k);
    FloatVec dx, dy;
    solve(v0, hn::LoadU(df, v[1] + k), hn::LoadU(df, v[2] + k), dx, dy);
    hn::StoreInterleaved3(v0, dx, dy, df, out);
  }
};

// For the lanes in `probed`, whose boxes are at most kProbedBoxSide pixels a side and whose
// triangles span less than kProbedSpan: whether each covers one of its box's pixel centres, that
// is whether at one of them no edge function is negative. Edge i from vertex (x_i, y_i) at centre
// (X, Y) is a_i (X - x_i) + b_i (Y - y_i) + bias_i, the value a_i X + b_i Y + c_i of the
// triangle's edge function, exactly in 32 bits: |a|, |b| and |X - x_i| stay below 2^15, the
// products below 2^30. The centres visited are the largest probed box's; the sign bit marks those
// past a lane's own box. (In 32-bit integers, not double: comparisons per centre and edge in
// double would make the probe a large part of the kernel.)
// Under MSAA (samples > 1, pattern: sample_pattern) the points tested are the pixels' samples
// instead of their centres: a sample adds a * offset x + b * offset y (sixteenths of a pixel, at
// most half a pixel: the products stay below 2^24, the sums inside 32 bits, as the boxes, widened
// by the samples' reach, stay within kProbedBoxSide). Exact, so a triangle dropped covers no
// sample.
HWY_INLINE hn::Mask<IntTag> CoversACentre(const IntVec x[3], const IntVec y[3], const IntVec a[3],
                                          const IntVec b[3], const IntVec bias[3], IntVec box_x0,
                                          IntVec box_y0, IntVec box_width, IntVec box_height,
                                          hn::Mask<IntTag> probed, const SampleOffset* pattern,
                                          int samples) {
  const IntTag di;
  const int columns = hn::GetLane(hn::MaxOfLanes(di, hn::IfThenElseZero(probed, box_width))) + 1;
  const int rows = hn::GetLane(hn::MaxOfLanes(di, hn::IfThenElseZero(probed, box_height))) + 1;
  const IntVec half = hn::Set(di, kHalfPixel);
  const IntVec centre_x = hn::Add(hn::ShiftLeft<kSubpixelBits>(box_x0), half);
  const IntVec centre_y = hn::Add(hn::ShiftLeft<kSubpixelBits>(box_y0), half);
  const IntVec outside = hn::Set(di, std::numeric_limits<std::int32_t>::min());
  IntVec column_limit[kProbedBoxSide];  // the sign bit past the lane's box, else 0
  for (int column = 0; column < columns; ++column) {
    column_limit[column] = hn::IfThenElseZero(hn::Gt(hn::Set(di, column), box_width), outside);
  }
  IntVec row[3], step_x[3], step_y[3];
  for (int i = 0; i < 3; ++i) {
    row[i] = hn::Add(
        hn::Add(hn::Mul(a[i], hn::Sub(centre_x, x[i])), hn::Mul(b[i], hn::Sub(centre_y, y[i]))),
        bias[i]);
    step_x[i] = hn::ShiftLeft<kSubpixelBits>(a[i]), step_y[i] = hn::ShiftLeft<kSubpixelBits>(b[i]);
  }
  // Each sample's step of each edge (zero at one sample: the centre).
  IntVec sample_step[3][kMaxSamples];
  for (int i = 0; i < 3; ++i) {
    for (int s = 0; s < samples; ++s) {
      sample_step[i][s] = hn::Add(hn::Mul(a[i], hn::Set(di, pattern[s].x * kSampleUnit)),
                                  hn::Mul(b[i], hn::Set(di, pattern[s].y * kSampleUnit)));
    }
  }
  // The sign bit stays set in a lane while every point so far has a negative edge.
  IntVec all_outside = hn::Set(di, -1);
  for (int r = 0; r < rows; ++r) {
    IntVec e[3] = {row[0], row[1], row[2]};
    IntVec row_outside = hn::IfThenElseZero(hn::Gt(hn::Set(di, r), box_height), outside);
    for (int column = 0; column < columns; ++column) {
      const IntVec limits = hn::Or(column_limit[column], row_outside);
      if (samples == 1) {
        const IntVec signs = hn::Or(hn::Or(e[0], e[1]), hn::Or(e[2], limits));
        all_outside = hn::And(all_outside, signs);
      } else {
        for (int s = 0; s < samples; ++s) {
          const IntVec signs =
              hn::Or(hn::Or(hn::Add(e[0], sample_step[0][s]), hn::Add(e[1], sample_step[1][s])),
                     hn::Or(hn::Add(e[2], sample_step[2][s]), limits));
          all_outside = hn::And(all_outside, signs);
        }
      }
      for (int i = 0; i < 3; ++i) e[i] = hn::Add(e[i], step_x[i]);
    }
    for (int i = 0; i < 3; ++i) row[i] = hn::Add(row[i], step_y[i]);
  }
  return hn::Not(hn::Lt(all_outside, hn::Zero(di)));
}

// Up to this many varyings, a triangle's planes are solved in scalars.
constexpr int kFewVaryings = 3;

int SetupBatchLanes(const SetupBatch& b, const SetupBatchTarget& target) {
  const DoubleTag dd;
  const FloatTag df;
  const IntTag di;
  const WideTag dl;
  constexpr std::size_t kLanes = hn::MaxLanes(dd);
  const int lanes = static_cast<int>(hn::Lanes(dd));
  const IntVec zero = hn::Zero(di);
  const IntVec last_x = hn::Set(di, target.width - 1), last_y = hn::Set(di, target.height - 1);
  const FloatVec to_pixels = hn::Set(df, 1.0f / static_cast<float>(kSubpixelScale));
  const int samples = target.out.frame().samples;
  const IntVec reach = hn::Set(di, sample_reach(samples));
  // One vector of triangles' results, for the per-triangle part.
  alignas(64) std::int32_t swapped[kLanes];
  alignas(64) std::int32_t a[3][kLanes], bx[3][kLanes];
  alignas(64) std::int64_t c[3][kLanes];
  alignas(64) std::int32_t min_x[kLanes], min_y[kLanes], max_x[kLanes], max_y[kLanes];
  alignas(64) float ref_x[kLanes], ref_y[kLanes];
  alignas(64) float z0[kLanes], z_dx[kLanes], z_dy[kLanes];
  alignas(64) float inv_w0[kLanes], inv_w_dx[kLanes], inv_w_dy[kLanes];
  alignas(64) double x1[kLanes], y1[kLanes], x2[kLanes], y2[kLanes], inv_det[kLanes];
  int dropped = 0;
  const hn::RebindToUnsigned<IntTag> du;
  for (int first = 0; first < b.count; first += lanes) {
    // The lanes past the batch read vertex 0 (the slack's indices are not vertices).
    const auto valid = hn::FirstN(du, static_cast<std::size_t>(b.count - first));
    alignas(64) std::uint32_t vertex[3][kLanes];
    IntVec x[3], y[3];
    FloatVec z[3], inv_w[3];
    for (int i = 0; i < 3; ++i) {
      const auto index = hn::IfThenElseZero(valid, hn::LoadU(du, b.vertex[i] + first));
      hn::Store(index, du, vertex[i]);
      hn::Vec<FloatTag> screen[4];  // x, y (the bits of integers), z, 1 / w
      LoadProjectedFields(df, target.projected, kScreenField, index, screen);
      x[i] = hn::BitCast(di, screen[0]), y[i] = hn::BitCast(di, screen[1]);
      z[i] = screen[2], inv_w[i] = screen[3];
    }
    // signed_area, exactly; then its sign and whether it is zero as 32-bit lanes (a whole number
    // keeps both as a float).
    const DoubleVec area = hn::Sub(
        hn::Mul(hn::PromoteTo(dd, hn::Sub(x[1], x[0])), hn::PromoteTo(dd, hn::Sub(y[2], y[0]))),
        hn::Mul(hn::PromoteTo(dd, hn::Sub(y[1], y[0])), hn::PromoteTo(dd, hn::Sub(x[2], x[0]))));
    const FloatVec area_sign = hn::DemoteTo(df, area);
    const auto negative = hn::RebindMask(di, hn::Lt(area_sign, hn::Zero(df)));
    const auto front =
        hn::RebindMask(di, hn::Ne(hn::LoadU(du, b.front_facing + first), hn::Zero(du)));
    // Degenerate after snapping, or snapping flipped a sliver: dropped.
    auto keep =
        hn::AndNot(hn::Xor(negative, front), hn::RebindMask(di, hn::Ne(area_sign, hn::Zero(df))));
    // A counter-clockwise winding becomes clockwise: vertices 1 and 2 swap.
    const auto swap = [](auto mask, auto& v1, auto& v2) {
      const auto first_value = v1;
      v1 = hn::IfThenElse(mask, v2, v1);
      v2 = hn::IfThenElse(mask, first_value, v2);
    };
    const auto negative_float = hn::RebindMask(df, negative);
    swap(negative, x[1], x[2]), swap(negative, y[1], y[2]);
    swap(negative_float, z[1], z[2]), swap(negative_float, inv_w[1], inv_w[2]);
    hn::Store(hn::VecFromMask(di, negative), di, swapped);

    // The pixel box (under MSAA, of the pixels whose samples the triangle may cover: widened by
    // the samples' reach, sample_positions.hpp), clamped to the frame.
    const IntVec low_x = hn::Min(hn::Min(x[0], x[1]), x[2]);
    const IntVec low_y = hn::Min(hn::Min(y[0], y[1]), y[2]);
    const IntVec high_x = hn::Max(hn::Max(x[0], x[1]), x[2]);
    const IntVec high_y = hn::Max(hn::Max(y[0], y[1]), y[2]);
    const PixelSpans<IntTag> columns = SpanPixels(di, low_x, high_x, reach, last_x);
    const PixelSpans<IntTag> rows = SpanPixels(di, low_y, high_y, reach, last_y);
    const IntVec box_x0 = columns.first, box_x1 = columns.last;
    const IntVec box_y0 = rows.first, box_y1 = rows.last;
    keep = hn::AndNot(hn::Or(hn::Gt(box_x0, box_x1), hn::Gt(box_y0, box_y1)), keep);
    hn::Store(box_x0, di, min_x), hn::Store(box_y0, di, min_y);
    hn::Store(box_x1, di, max_x), hn::Store(box_y1, di, max_y);

    // Edge i from p = vertex i to q = vertex i + 1: a = p.y - q.y, b = q.x - p.x, and c with
    // the fill rule's bias: -1 unless the edge is top (a = 0, b > 0) or left (a > 0).
    IntVec edge_a[3], edge_b[3], bias[3];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const IntVec ai = hn::Sub(y[i], y[j]), bi = hn::Sub(x[j], x[i]);
      const auto top_left = hn::Or(hn::Gt(ai, zero), hn::And(hn::Eq(ai, zero), hn::Gt(bi, zero)));
      edge_a[i] = ai, edge_b[i] = bi, bias[i] = hn::VecFromMask(di, hn::Not(top_left));
      const DoubleVec products = hn::Add(hn::Mul(hn::PromoteTo(dd, ai), hn::PromoteTo(dd, x[i])),
                                         hn::Mul(hn::PromoteTo(dd, bi), hn::PromoteTo(dd, y[i])));
      hn::Store(ai, di, a[i]), hn::Store(bi, di, bx[i]);
      hn::Store(hn::ConvertTo(dl, hn::Sub(hn::PromoteTo(dd, bias[i]), products)), dl, c[i]);
    }
    // Small triangles covering no pixel centre (under MSAA, no sample): dropped.
    const IntVec box_width = hn::Sub(box_x1, box_x0), box_height = hn::Sub(box_y1, box_y0);
    const IntVec side = hn::Set(di, kProbedBoxSide), span = hn::Set(di, kProbedSpan);
    const auto probed = hn::And(
        hn::And(keep, hn::And(hn::Lt(box_width, side), hn::Lt(box_height, side))),
        hn::And(hn::Lt(hn::Sub(high_x, low_x), span), hn::Lt(hn::Sub(high_y, low_y), span)));
    if (!hn::AllFalse(di, probed)) {
      const auto covers = CoversACentre(x, y, edge_a, edge_b, bias, box_x0, box_y0, box_width,
                                        box_height, probed, sample_pattern(samples), samples);
      keep = hn::AndNot(hn::AndNot(covers, probed), keep);
    }
    // The kept lanes as bits, visited lowest first below, so that the loop over them has no
    // branch on a dropped lane.
    static_assert(kLanes <= 8);  // one byte of mask bits
    std::uint8_t kept = 0;
    hn::StoreMaskBits(di, hn::And(keep, hn::RebindMask(di, valid)), &kept);

    // PlaneSolver over the vertices in pixels, and the depth and 1 / w planes.
    FloatVec px[3], py[3];
    for (int i = 0; i < 3; ++i) {
      px[i] = hn::Mul(hn::ConvertTo(df, x[i]), to_pixels);
      py[i] = hn::Mul(hn::ConvertTo(df, y[i]), to_pixels);
    }
    hn::Store(px[0], df, ref_x), hn::Store(py[0], df, ref_y);
    Coefficients solver;
    solver.x1 = hn::Sub(ToDouble(px[1]), ToDouble(px[0]));
    solver.y1 = hn::Sub(ToDouble(py[1]), ToDouble(py[0]));
    solver.x2 = hn::Sub(ToDouble(px[2]), ToDouble(px[0]));
    solver.y2 = hn::Sub(ToDouble(py[2]), ToDouble(py[0]));
    solver.inv_det = hn::Div(hn::Set(dd, 1.0),
                             hn::Sub(hn::Mul(solver.x1, solver.y2), hn::Mul(solver.x2, solver.y1)));
    hn::Store(solver.x1, dd, x1), hn::Store(solver.y1, dd, y1);
    hn::Store(solver.x2, dd, x2), hn::Store(solver.y2, dd, y2);
    hn::Store(solver.inv_det, dd, inv_det);
    FloatVec dx, dy;
    solver.solve(z[0], z[1], z[2], dx, dy);
    hn::Store(z[0], df, z0), hn::Store(dx, df, z_dx), hn::Store(dy, df, z_dy);
    solver.solve(inv_w[0], inv_w[1], inv_w[2], dx, dy);
    hn::Store(inv_w[0], df, inv_w0), hn::Store(dx, df, inv_w_dx), hn::Store(dy, df, inv_w_dy);

    // Each kept triangle in order: its record, then its varying planes (a vector at a time, or
    // in scalars when they are few).
    dropped += std::min(lanes, b.count - first) - std::popcount(kept);
    for (; kept != 0; kept &= static_cast<std::uint8_t>(kept - 1)) {
      const int l = std::countr_zero(kept);
      const TriangleSlot slot = target.out.reserve_triangle();
      SetupTriangle& t = *slot.triangle;
      for (int i = 0; i < 3; ++i) t.a[i] = a[i][l], t.b[i] = bx[i][l], t.c[i] = c[i][l];
      t.min_x = min_x[l], t.min_y = min_y[l], t.max_x = max_x[l], t.max_y = max_y[l];
      t.ref_x = ref_x[l], t.ref_y = ref_y[l];
      t.z = {z0[l], z_dx[l], z_dy[l]};
      t.inv_w = {inv_w0[l], inv_w_dx[l], inv_w_dy[l]};
      t.varying_planes = slot.plane_index;
      t.draw = target.draw;
      target.out.add_reserved_triangle(slot);
      if (target.varyings == 0) continue;  // (slot.planes may then be null)

      const bool swaps = swapped[l] != 0;
      const int n = target.varyings;
      const float* const v[3] = {target.over_w + std::size_t{vertex[0][l]} * n,
                                 target.over_w + std::size_t{vertex[swaps ? 2 : 1][l]} * n,
                                 target.over_w + std::size_t{vertex[swaps ? 1 : 2][l]} * n};
      float* planes = &slot.planes[0].at_ref;
      if (n <= kFewVaryings) {
        // In scalars: a vector would hold these few planes in a few of its lanes and store a
        // whole vector's worth.
        const PlaneSolver one({x1[l], y1[l], x2[l], y2[l], inv_det[l]});
        for (int k = 0; k < n; ++k) slot.planes[k] = one.plane(v[0][k], v[1][k], v[2][k]);
      } else {
        const Coefficients one{hn::Set(dd, x1[l]), hn::Set(dd, y1[l]), hn::Set(dd, x2[l]),
                               hn::Set(dd, y2[l]), hn::Set(dd, inv_det[l])};
        const int whole = n - n % lanes;
        int k = 0;
        for (; k < whole; k += lanes) one.solve_planes(v, k, planes + 3 * k);
        // The last few planes: a whole vector's worth where the room past them is scratch;
        // otherwise (the next planes may be another chunk's, which another thread writes)
        // through a buffer.
        if (k < n) {
          if (target.out.plane_room(slot) >= static_cast<std::uint32_t>(whole + lanes)) {
            one.solve_planes(v, k, planes + 3 * k);
          } else {
            alignas(64) float rest[3 * kLanes];
            one.solve_planes(v, k, rest);
            for (int f = 0; f < 3 * (n - k); ++f) planes[3 * k + f] = rest[f];
          }
        }
      }
      if (target.back_face_normal >= 0) {
        const float* const over_w[3] = {target.over_w + std::size_t{vertex[0][l]} * n,
                                        target.over_w + std::size_t{vertex[1][l]} * n,
                                        target.over_w + std::size_t{vertex[2][l]} * n};
        const float one_over_w[3] = {target.projected[vertex[0][l]].screen.inv_w,
                                     target.projected[vertex[1][l]].screen.inv_w,
                                     target.projected[vertex[2][l]].screen.inv_w};
        if (reverses_normal(over_w, one_over_w, target.back_face_position, target.back_face_normal,
                            b.front_facing[first + l] != 0)) {
          float* normal = planes + 3 * target.back_face_normal;
          for (int f = 0; f < 9; ++f) normal[f] = -normal[f];
        }
      }
    }
  }
  return dropped;
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(SetupBatchLanes);

SetupBatchKernel setup_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(SetupBatchLanes)[target];
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
