// Batch texture sampling (see texel_batch.hpp). Highway compiles this file once per SIMD target
// (foreach_target.h re-includes it); the frame fetches the chosen target's kernel
// (pipeline/kernels.hpp). The level of detail is computed here, the filtering is the texture's
// own (core/texture_sample-inl.h). Every target computes the same IEEE operations in the same
// order (no fused multiply-add; std::min/max as compare-and-select, which treat NaN as they do),
// so every target gives the same bits; texel_batch_test checks them against a scalar sampler.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/texel_batch.cpp"
#include "shading/texel_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "core/portable_math.hpp"
#include "core/texture_sample-inl.h"
#include "facet/texture.hpp"
#include "shading/batch_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

namespace hs = facet::sampling::HWY_NAMESPACE;

using FloatTag = hs::FloatTag;
using IntTag = hs::IntTag;
using FloatV = hs::FloatV;
using IntV = hs::IntV;
static_assert(hs::kMaxPixels == kTexelBatch);

// Fragment::ddx/ddy of a varying whose value is `value`: (V_x - value * W_x) * w.
HWY_INLINE FloatV Derivative(FloatV plane_slope, FloatV inv_w_slope, FloatV value, FloatV w) {
  return hn::Mul(hn::Sub(plane_slope, hn::Mul(value, inv_w_slope)), w);
}

// Plane slopes in TexelBatch::Slope order: one triangle's for every lane, or each lane's own.
struct Slopes {
  FloatV s[TexelBatch::kSlopes];
};
HWY_INLINE Slopes TriangleSlopes(const TexelBatch& batch) {
  const FloatTag df;
  Slopes out;
  for (int k = 0; k < TexelBatch::kSlopes; ++k) out.s[k] = hn::Set(df, batch.slope(k, 0));
  return out;
}
HWY_INLINE Slopes PixelSlopes(const TexelBatch& batch, int j) {
  const FloatTag df;
  Slopes out;
  for (int k = 0; k < TexelBatch::kSlopes; ++k) out.s[k] = hn::LoadU(df, batch.slopes[k] + j);
  return out;
}

// Row `row` of the map's linear part times (du, dv): derivatives transform by the linear part only.
HWY_INLINE FloatV LinearPart(const glm::mat3& m, int row, FloatV du, FloatV dv) {
  const FloatTag df;
  return hn::Add(hn::Mul(hn::Set(df, m[0][row]), du), hn::Mul(hn::Set(df, m[1][row]), dv));
}

// The level of detail (OpenGL 4.6 §8.14.1, equation 8.4, without anisotropy): the exact
// derivatives through the map's linear part, measured in base-level texels; log2 of the longer
// footprint edge, from squared lengths as half the log2 (lod_log2: within a thousandth of a
// level, the same bits on every CPU). For the W vectors of pixels from pixel j on. Each step is
// done for all W before the next, so that the CPU overlaps the vectors' chains of some 40 dependent
// operations.
template <int W>
HWY_INLINE void LevelsOfDetail(const Texture& texture, const glm::mat3& m, const TexelBatch& batch,
                               const Slopes& triangle, int j, FloatV* lod) {
  const FloatTag df;
  const int lanes = static_cast<int>(hn::Lanes(df));
  using S = TexelBatch;
  const FloatV size_u = hn::Set(df, static_cast<float>(texture.width()));
  const FloatV size_v = hn::Set(df, static_cast<float>(texture.height()));
  FloatV xu[W], xv[W], yu[W], yv[W];
  for (int k = 0; k < W; ++k) {
    const int at = j + k * lanes;
    const Slopes slopes = batch.slopes ? PixelSlopes(batch, at) : triangle;
    const FloatV* s = slopes.s;
    const FloatV u = hn::LoadU(df, batch.u + at), v = hn::LoadU(df, batch.v + at);
    const FloatV w = hn::LoadU(df, batch.w + at);
    const FloatV dux = Derivative(s[S::u_dx], s[S::inv_w_dx], u, w);
    const FloatV dvx = Derivative(s[S::v_dx], s[S::inv_w_dx], v, w);
    const FloatV duy = Derivative(s[S::u_dy], s[S::inv_w_dy], u, w);
    const FloatV dvy = Derivative(s[S::v_dy], s[S::inv_w_dy], v, w);
    xu[k] = hn::Mul(LinearPart(m, 0, dux, dvx), size_u);
    xv[k] = hn::Mul(LinearPart(m, 1, dux, dvx), size_v);
    yu[k] = hn::Mul(LinearPart(m, 0, duy, dvy), size_u);
    yv[k] = hn::Mul(LinearPart(m, 1, duy, dvy), size_v);
  }
  for (int k = 0; k < W; ++k) {
    const FloatV rho2 = StdMax(hn::Add(hn::Mul(xu[k], xu[k]), hn::Mul(xv[k], xv[k])),
                               hn::Add(hn::Mul(yu[k], yu[k]), hn::Mul(yv[k], yv[k])));
    // Magnified everywhere (a footprint of at most one texel): the logarithm would be at most
    // 0 (lod_log2 never exceeds 0 up to 1: PortableMath.LodLog2IsNotPositiveUpToOne), which
    // the caller takes as level 0 all the same, so it is skipped.
    if (hn::AllTrue(df, hn::Le(rho2, hn::Set(df, 1.0f)))) {
      lod[k] = hn::Zero(df);
      continue;
    }
    lod[k] = hn::Mul(hn::Set(df, 0.5f), LodLog2(rho2));
  }
}

// The largest bound MagnifiedEverywhere accepts: below 1 by a margin that covers the float
// rounding of the bound and of LevelsOfDetail's rho2 (a few parts in a million).
constexpr float kMagnifiedBound = 0.98f;

// Whether every pixel of a batch of one triangle is magnified (a footprint of at most one texel:
// level 0 and no blend toward level 1), from a bound on LevelsOfDetail's rho2 taken over the
// batch's largest |u|, |v| and |w| instead of pixel by pixel: |(U_x - u W_x) w| is at most
// (|U_x| + max|u| |W_x|) max|w|, and so on through the map's linear part in absolute values.
// Where it holds, trilinear filtering gives bilinear filtering's bits. Infinite values fail it.
HWY_INLINE bool MagnifiedEverywhere(const Texture& texture, const glm::mat3& m,
                                    const TexelBatch& batch) {
  const FloatTag df;
  const int lanes = static_cast<int>(hn::Lanes(df));
  FloatV most_u = hn::Zero(df), most_v = hn::Zero(df), most_w = hn::Zero(df);
  // A NaN is left out (Highway's Max gives its second argument where the first is NaN, on every
  // target), which is right: LevelsOfDetail gives a NaN level of detail level 0 (StoreLevel).
  auto take = [&](int j, auto in_batch) HWY_ATTR {
    auto most = [&](FloatV so_far, const float* values) HWY_ATTR {
      return hn::Max(in_batch(hn::Abs(hn::LoadU(df, values + j))), so_far);
    };
    most_u = most(most_u, batch.u), most_v = most(most_v, batch.v), most_w = most(most_w, batch.w);
  };
  int j = 0;
  for (; j + lanes <= batch.count; j += lanes) take(j, [](FloatV x) HWY_ATTR { return x; });
  if (j < batch.count) {  // the lanes past the batch left out
    const auto in_batch = hn::FirstN(df, static_cast<std::size_t>(batch.count - j));
    take(j, [&](FloatV x) HWY_ATTR { return hn::IfThenElseZero(in_batch, x); });
  }
  const float u = hn::GetLane(hn::MaxOfLanes(df, most_u));
  const float v = hn::GetLane(hn::MaxOfLanes(df, most_v));
  const float w = hn::GetLane(hn::MaxOfLanes(df, most_w));
  using S = TexelBatch;
  auto derivative = [&](int slope, float value, int inv_w_slope) {
    return (std::abs(batch.slope(slope, 0)) + value * std::abs(batch.slope(inv_w_slope, 0))) * w;
  };
  const float dux = derivative(S::u_dx, u, S::inv_w_dx), dvx = derivative(S::v_dx, v, S::inv_w_dx);
  const float duy = derivative(S::u_dy, u, S::inv_w_dy), dvy = derivative(S::v_dy, v, S::inv_w_dy);
  auto texels = [&](int row, float du, float dv, int size) {
    return (std::abs(m[0][row]) * du + std::abs(m[1][row]) * dv) * static_cast<float>(size);
  };
  const float xu = texels(0, dux, dvx, texture.width()), xv = texels(1, dux, dvx, texture.height());
  const float yu = texels(0, duy, dvy, texture.width()), yv = texels(1, duy, dvy, texture.height());
  const float rho2 = std::max(xu * xu + xv * xv, yu * yu + yv * yv);
  return rho2 < kMagnifiedBound;  // NaN fails
}

void SampleBatch(const TextureMap& map, TexelBatch& batch) {
  const FloatTag df;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const Texture& texture = *map.texture;
  const glm::mat3& m = map.transform;
  // Trilinear filtering where every pixel is magnified is bilinear filtering: the levels of
  // detail are not computed.
  const bool magnified = map.sampler.filter == Filter::trilinear && batch.slopes == nullptr &&
                         MagnifiedEverywhere(texture, m, batch);
  const Filter filter = magnified ? Filter::bilinear : map.sampler.filter;
  // The map's transform of the texture coordinates of the pixels from j; the identity leaves
  // them as they are (TextureMap).
  const bool identity = m == glm::mat3(1.0f);
  auto transformed = [&](int j) HWY_ATTR {
    const FloatV u = hn::LoadU(df, batch.u + j), v = hn::LoadU(df, batch.v + j);
    if (identity) return std::pair{u, v};
    return std::pair{
        hn::Add(hn::Add(hn::Mul(hn::Set(df, m[0][0]), u), hn::Mul(hn::Set(df, m[1][0]), v)),
                hn::Set(df, m[2][0])),
        hn::Add(hn::Add(hn::Mul(hn::Set(df, m[0][1]), u), hn::Mul(hn::Set(df, m[1][1]), v)),
                hn::Set(df, m[2][1]))};
  };
  // Each pixel's mip level and the fraction toward the next, for trilinear filtering. A pass of
  // its own, a short loop of independent vectors, so that the CPU overlaps one vector's long
  // dependency chains (the level of detail's logarithm above all) with the next one's; the
  // filtering's passes follow.
  alignas(32) std::int32_t level[kTexelBatch];
  alignas(32) float fraction[kTexelBatch];
  if (filter == Filter::trilinear) {
    const FloatV top = hn::Set(df, static_cast<float>(texture.level_count() - 1));
    const Slopes triangle = batch.slopes ? Slopes{} : TriangleSlopes(batch);
    // Whole groups of kWays vectors, then single vectors up to the batch's last one.
    constexpr int kWays = 4;
    auto levels = [&](auto ways, int j) HWY_ATTR {
      constexpr int W = decltype(ways)::value;
      FloatV lod[W];
      LevelsOfDetail<W>(texture, m, batch, triangle, j, lod);
      for (int k = 0; k < W; ++k) hs::StoreLevel(lod[k], top, level, fraction, j + k * lanes);
    };
    int j = 0;
    for (; j + kWays * lanes <= batch.count; j += kWays * lanes) {
      levels(std::integral_constant<int, kWays>(), j);
    }
    for (; j < batch.count; j += lanes) levels(std::integral_constant<int, 1>(), j);
  }
  hs::SamplePixels(hs::SourceOf(texture, map.sampler), filter, transformed, level, fraction,
                   batch.count, batch.rgba);
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(SampleBatch);

SampleBatchKernel sample_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(SampleBatch)[target];
}

}  // namespace facet::shading
#endif  // HWY_ONCE
