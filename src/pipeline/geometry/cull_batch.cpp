// Stage: primitive assembly, culling several triangles a vector (see cull_batch.hpp). Highway
// compiles this file once per SIMD target (foreach_target.h re-includes it).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/geometry/cull_batch.cpp"
#include "pipeline/geometry/cull_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>

#include "core/simd_target.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/projected_load-inl.h"
#include "pipeline/setup/pixel_box-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DoubleTag = hn::ScalableTag<double>;
using FloatTag = hn::Rebind<float, DoubleTag>;
using UintTag = hn::Rebind<std::uint32_t, DoubleTag>;
using IntTag = hn::Rebind<std::int32_t, DoubleTag>;

// Lanes whose triangle needs no clipping (planes_to_clip(any) == 0, clip.hpp) and whose pixel
// box (setup_batch.cpp's, from the vertices' screen positions) holds no pixel.
HWY_INLINE hn::Mask<UintTag> EmptyBoxes(const CullInput& in, const hn::Vec<UintTag> index[3],
                                        hn::Vec<UintTag> any) {
  const FloatTag df;
  const UintTag du;
  const IntTag di;
  const auto zero = hn::Zero(du);
  const auto sides = hn::Set(du, kClipLeft | kClipRight | kClipBottom | kClipTop);
  const auto planes =
      hn::IfThenElse(hn::Ne(hn::And(any, sides), zero),
                     hn::And(hn::ShiftRight<kGuardCodeShift>(any), hn::Set(du, kFrustumCodes)),
                     hn::And(any, hn::Set(du, kClipNear | kClipFar | kClipUser)));
  const auto unclipped = hn::Eq(planes, zero);
  if (hn::AllFalse(du, unclipped)) return unclipped;
  hn::Vec<IntTag> x[3], y[3];
  for (int v = 0; v < 3; ++v) {
    hn::Vec<FloatTag> screen[4];  // x, y (the bits of integers), z, 1 / w
    LoadProjectedFields(df, in.projected, kScreenField, index[v], screen);
    x[v] = hn::BitCast(di, screen[0]), y[v] = hn::BitCast(di, screen[1]);
  }
  const auto reach = hn::Set(di, in.reach);
  const PixelSpans<IntTag> columns =
      SpanPixels(di, hn::Min(hn::Min(x[0], x[1]), x[2]), hn::Max(hn::Max(x[0], x[1]), x[2]), reach,
                 hn::Set(di, in.width - 1));
  const PixelSpans<IntTag> rows =
      SpanPixels(di, hn::Min(hn::Min(y[0], y[1]), y[2]), hn::Max(hn::Max(y[0], y[1]), y[2]), reach,
                 hn::Set(di, in.height - 1));
  const auto empty = hn::Or(hn::Gt(columns.first, columns.last), hn::Gt(rows.first, rows.last));
  return hn::And(unclipped, hn::RebindMask(du, empty));
}

void CullTriangles(const CullInput& in, CullSurvivors& out) {
  const DoubleTag dd;
  const FloatTag df;
  const UintTag du;
  constexpr std::size_t kLanes = hn::MaxLanes(dd);
  const int lanes = static_cast<int>(hn::Lanes(dd));
  const auto frustum = hn::Set(du, (1u << kClipPlaneCount) - 1);
  const auto not_finite = hn::Set(du, kNotFinite);
  const auto zero_u = hn::Zero(du);
  int kept = 0;
  for (int first = 0; first < in.count; first += lanes) {
    const int valid = std::min(lanes, in.count - first);
    hn::Vec<UintTag> index[3];
    if (valid == lanes) {
      hn::LoadInterleaved3(du, in.indices + 3 * first, index[0], index[1], index[2]);
    } else {  // the last few: the lanes past them repeat the first triangle, then drop out
      std::uint32_t padded[3 * kLanes];
      for (int l = 0; l < lanes; ++l) {
        const int t = l < valid ? first + l : first;
        for (int v = 0; v < 3; ++v) padded[3 * l + v] = in.indices[3 * t + v];
      }
      hn::LoadInterleaved3(du, padded, index[0], index[1], index[2]);
    }
    hn::Vec<DoubleTag> x[3], y[3], w[3];
    hn::Vec<UintTag> code[3];
    for (int v = 0; v < 3; ++v) {
      hn::Vec<FloatTag> clip[4];  // x, y, w and the codes' bits
      LoadProjectedFields(df, in.projected, 0, index[v], clip);
      x[v] = hn::PromoteTo(dd, clip[0]), y[v] = hn::PromoteTo(dd, clip[1]);
      w[v] = hn::PromoteTo(dd, clip[2]), code[v] = hn::BitCast(du, clip[3]);
    }
    // homogeneous_orientation (primitive.hpp), operation for operation.
    const auto orientation =
        hn::Add(hn::Sub(hn::Mul(x[0], hn::Sub(hn::Mul(y[1], w[2]), hn::Mul(w[1], y[2]))),
                        hn::Mul(y[0], hn::Sub(hn::Mul(x[1], w[2]), hn::Mul(w[1], x[2])))),
                hn::Mul(w[0], hn::Sub(hn::Mul(x[1], y[2]), hn::Mul(y[1], x[2]))));
    // Masks of the double lanes as masks of 32-bit lanes (1.0 or 0.0, demoted).
    const auto as_32_bits = [&](auto mask) {
      return hn::RebindMask(
          du, hn::Gt(hn::DemoteTo(df, hn::IfThenElseZero(mask, hn::Set(dd, 1.0))), hn::Zero(df)));
    };
    const auto front = as_32_bits(hn::Gt(orientation, hn::Zero(dd)));
    const auto degenerate = as_32_bits(hn::Eq(orientation, hn::Zero(dd)));
    const auto any = hn::Or(hn::Or(code[0], code[1]), code[2]);
    const auto all = hn::And(hn::And(code[0], code[1]), code[2]);
    auto culled = hn::Or(hn::Ne(hn::And(any, not_finite), zero_u),
                         hn::Or(hn::Ne(hn::And(all, frustum), zero_u), degenerate));
    if (in.culls_front) culled = hn::Or(culled, front);
    if (in.culls_back) culled = hn::Or(culled, hn::Not(front));
    if (in.drops_empty_boxes && !hn::AllTrue(du, culled)) {
      culled = hn::Or(culled, EmptyBoxes(in, index, any));
    }
    const auto keep = hn::AndNot(culled, hn::FirstN(du, static_cast<std::size_t>(valid)));
    hn::StoreU(hn::Compress(index[0], keep), du, out.i0 + kept);
    hn::StoreU(hn::Compress(index[1], keep), du, out.i1 + kept);
    hn::StoreU(hn::Compress(index[2], keep), du, out.i2 + kept);
    hn::StoreU(hn::Compress(any, keep), du, out.codes + kept);
    hn::StoreU(hn::Compress(hn::IfThenElseZero(front, hn::Set(du, 1u)), keep), du,
               out.front_facing + kept);
    if (in.positions) {
      hn::StoreU(hn::Compress(hn::Iota(du, static_cast<std::uint32_t>(first)), keep), du,
                 out.position + kept);
    }
    kept += static_cast<int>(hn::CountTrue(du, keep));
  }
  out.count = kept;
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(CullTriangles);

CullKernel cull_kernel(SimdTarget target) { return HWY_DISPATCH_TABLE(CullTriangles)[target]; }

}  // namespace facet::pipeline
#endif  // HWY_ONCE
