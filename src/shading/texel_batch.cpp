// Batch texture sampling (see texel_batch.hpp). Highway compiles this file once per SIMD target
// (foreach_target.h re-includes it); the frame fetches the chosen target's kernel
// (pipeline/kernels.hpp). Each step repeats its scalar counterpart in texture.cpp / surface.cpp /
// portable_math.hpp with the same IEEE operations in the same order (no fused multiply-add;
// std::min/max as compare-and-select, which treat NaN as they do), so every target gives the scalar
// bits; texel_batch_test checks it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/texel_batch.cpp"
#include "shading/texel_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "core/portable_math.hpp"
#include "facet/texture.hpp"
#include "shading/batch_math-inl.h"
#include "shading/surface.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Eight lanes at most: batches are often a few pixels of a small triangle, where AVX-512's
// sixteen lanes mostly compute padding.
constexpr int kMaxLanes = 8;
using FloatTag = hn::CappedTag<float, kMaxLanes>;
using IntTag = hn::RebindToSigned<FloatTag>;
using FloatV = hn::Vec<FloatTag>;
using IntV = hn::Vec<IntTag>;

// sanitize() and floor_to_int() of texture.cpp.
HWY_INLINE FloatV Sanitize(FloatV x) {
  const FloatTag df;
  const FloatV limit = hn::Set(df, 8388608.0f);
  return hn::IfThenElse(hn::Gt(x, hn::Neg(limit)), StdMin(x, limit), hn::Neg(limit));
}
HWY_INLINE IntV FloorToInt(FloatV x) {
  const FloatTag df;
  const IntTag di;
  const IntV t = hn::ConvertTo(di, x);  // truncates; |x| <= 2^23 after Sanitize
  const auto above = hn::RebindMask(di, hn::Gt(hn::ConvertTo(df, t), x));
  return hn::IfThenElse(above, hn::Sub(t, hn::Set(di, 1)), t);
}

// wrap<mode>() of texture.cpp for power-of-two sizes (repeat and mirrored repeat) and any size
// (clamp to edge).
HWY_INLINE IntV WrapOne(Wrap mode, IntV i, IntV size) {
  const IntTag di;
  const IntV one = hn::Set(di, 1);
  switch (mode) {
    case Wrap::clamp_to_edge:
      return hn::Min(hn::Max(i, hn::Zero(di)), hn::Sub(size, one));
    case Wrap::mirrored_repeat: {
      const IntV period = hn::Add(size, size);
      const IntV m = hn::And(i, hn::Sub(period, one));
      return hn::IfThenElse(hn::Lt(m, size), m, hn::Sub(hn::Sub(period, one), m));
    }
    case Wrap::repeat:
    default:
      return hn::And(i, hn::Sub(size, one));
  }
}

struct Pair {
  IntV first, second;
};
// wrap_pair<mode>() of texture.cpp.
HWY_INLINE Pair WrapPair(Wrap mode, IntV i, IntV size) {
  const IntTag di;
  if (mode == Wrap::repeat) {
    const IntV first = WrapOne(mode, i, size);
    const IntV next = hn::Add(first, hn::Set(di, 1));
    return {first, hn::IfThenElse(hn::Eq(next, size), hn::Zero(di), next)};
  }
  return {WrapOne(mode, i, size), WrapOne(mode, hn::Add(i, hn::Set(di, 1)), size)};
}

// What the sampling steps share for one texture.
struct Source {
  const float* texels;
  const std::int32_t* offsets;  // padded: whole vectors may be loaded (Texture::LinearLevels)
  int levels, width, height;
  Wrap wrap_u, wrap_v;
};

// src.offsets[level] per lane (0 <= level < src.levels) with permutes of the offsets' vectors
// instead of a gather (slow on this project's machines). The offsets are read a vector at a
// time from their start; a lane takes its entry from the last vector that starts at or before
// its level.
HWY_INLINE IntV LevelOffset(const Source& src, IntV level) {
  const IntTag di;
  const int lanes = static_cast<int>(hn::Lanes(di));
  static_assert(Texture::kLevelOffsetsPadding % kMaxLanes == 0);
  const IntV in_vector = hn::Set(di, lanes - 1);
  IntV offset = hn::Zero(di);
  for (int first = 0; first < src.levels; first += lanes) {
    const IntV part = hn::LoadU(di, src.offsets + first);
    const IntV index = hn::And(hn::Sub(level, hn::Set(di, first)), in_vector);
    const IntV picked = hn::TableLookupLanes(part, hn::IndicesFromVec(di, index));
    offset = hn::IfThenElse(hn::Gt(level, hn::Set(di, first - 1)), picked, offset);
  }
  return offset;
}

// Level sizes: each side halved per level, at least 1 (as texture.cpp builds them).
HWY_INLINE IntV LevelSize(int base, IntV level) {
  const IntTag di;
  return hn::Max(hn::Shr(hn::Set(di, base), level), hn::Set(di, 1));
}

// Where each lane's texels are: the float offsets of the bilinear footprint's four texels
// (x0 r0, x1 r0, x0 r1, x1 r1) and the blend weights along x (a) and y (b).
struct Footprint {
  IntV texel[4];
  FloatV a, b;
};

// Offset of texel (x, row) in the levels, whose level starts at offset (per lane).
HWY_INLINE IntV TexelOffset(IntV level_offset, IntV width, IntV x, IntV row) {
  return hn::Add(level_offset, hn::ShiftLeft<2>(hn::Add(hn::Mul(row, width), x)));
}

// sample_bilinear() of texture.cpp at each lane's level, up to the texel fetches.
HWY_INLINE Footprint Bilinear(const Source& src, IntV level, FloatV u, FloatV v) {
  const FloatTag df;
  const IntTag di;
  const IntV w = LevelSize(src.width, level), h = LevelSize(src.height, level);
  const FloatV half = hn::Set(df, 0.5f);
  const FloatV x = Sanitize(hn::Sub(hn::Mul(u, hn::ConvertTo(df, w)), half));
  const FloatV y = Sanitize(hn::Sub(hn::Mul(v, hn::ConvertTo(df, h)), half));
  const IntV i0 = FloorToInt(x), j0 = FloorToInt(y);
  Footprint fp;
  fp.a = hn::Sub(x, hn::ConvertTo(df, i0));
  fp.b = hn::Sub(y, hn::ConvertTo(df, j0));
  const Pair xs = WrapPair(src.wrap_u, i0, w), ys = WrapPair(src.wrap_v, j0, h);
  const IntV last_row = hn::Sub(h, hn::Set(di, 1));
  const IntV r0 = hn::Sub(last_row, ys.first), r1 = hn::Sub(last_row, ys.second);
  const IntV offset = LevelOffset(src, level);
  fp.texel[0] = TexelOffset(offset, w, xs.first, r0);
  fp.texel[1] = TexelOffset(offset, w, xs.second, r0);
  fp.texel[2] = TexelOffset(offset, w, xs.first, r1);
  fp.texel[3] = TexelOffset(offset, w, xs.second, r1);
  return fp;
}

// Every pixel's footprint, stored a vector at a time for the per-pixel blend.
struct StoredFootprints {
  alignas(32) std::int32_t texel[4][kTexelBatch];
  alignas(32) float a[kTexelBatch], b[kTexelBatch];
  void store(int j, const Footprint& fp) {
    const FloatTag df;
    const IntTag di;
    for (int t = 0; t < 4; ++t) hn::Store(fp.texel[t], di, texel[t] + j);
    hn::Store(fp.a, df, a + j);
    hn::Store(fp.b, df, b + j);
  }
};

// One texel, one lane per channel: GCC's vector extension as in texture.cpp (SSE on x86, on
// every target, including Highway's SCALAR which has no four-lane vectors).
using Texel = float __attribute__((vector_size(16)));

HWY_INLINE Texel LoadTexel(const float* p) {
  Texel t;
  std::memcpy(&t, p, sizeof t);
  return t;
}

// a * (1 - f) + b * f per channel, as the Texel arithmetic of texture.cpp.
HWY_INLINE Texel Lerp(Texel a, Texel b, float f) { return a * (1.0f - f) + b * f; }

// The bilinear blend of lane k's footprint (sample_bilinear()'s last three lines).
HWY_INLINE Texel Blend(const float* texels, const StoredFootprints& fp, int k) {
  const Texel bottom =
      Lerp(LoadTexel(texels + fp.texel[0][k]), LoadTexel(texels + fp.texel[1][k]), fp.a[k]);
  const Texel top =
      Lerp(LoadTexel(texels + fp.texel[2][k]), LoadTexel(texels + fp.texel[3][k]), fp.a[k]);
  return Lerp(bottom, top, fp.b[k]);
}

#if HWY_ARCH_X86 && HWY_MAX_BYTES >= 64  // AVX-512: 512-bit vectors exist
// Blend() and the blend toward the next level for pixels k .. k + 3 in one 16-lane vector
// (lanes 4p .. 4p + 3 are pixel k + p's channels), for the whole groups of four of the batch;
// returns how many pixels it did. The same operations per lane as the scalar blends; a pixel
// whose fraction is 0 keeps its level's blend (a select: the scalar code skips the lerp).
HWY_INLINE int BlendFours(const float* texels, const StoredFootprints& near,
                          const StoredFootprints& far, const float* fraction, int count,
                          float (*rgba)[4]) {
  // A group of four pixels lies in one of phase 2's vectors, so where one of them blends
  // toward the next level, all four have their next-level footprints stored.
  static_assert(hn::MaxLanes(FloatTag()) % 4 == 0);
  const hn::Full512<float> d;
  const hn::Full256<float> d8;
  const hn::Full128<float> d4;
  const hn::RebindToSigned<decltype(d)> di;
  alignas(64) static constexpr std::int32_t kPixelOfLane[16] = {0, 0, 0, 0, 1, 1, 1, 1,
                                                                2, 2, 2, 2, 3, 3, 3, 3};
  const auto spread = hn::IndicesFromVec(d, hn::Load(di, kPixelOfLane));
  const auto one = hn::Set(d, 1.0f);
  // Each of the four pixels' value at k + p, spread to its four lanes.
  auto per_pixel = [&](const float* values) HWY_ATTR {
    const auto four = hn::LoadDup128(d, values);
    return hn::TableLookupLanes(four, spread);
  };
  // Lerp() of texture.cpp, lane by lane.
  auto lerp = [&](auto a, auto b, auto f) HWY_ATTR {
    const auto from_a = hn::Mul(a, hn::Sub(one, f));
    return hn::Add(from_a, hn::Mul(b, f));
  };
  // Footprint texel t of pixels k .. k + 3, one pixel's RGBA in each quarter of the vector.
  auto texel = [&](const StoredFootprints& fp, int t, int k) HWY_ATTR {
    const auto low = hn::Combine(d8, hn::LoadU(d4, texels + fp.texel[t][k + 1]),
                                 hn::LoadU(d4, texels + fp.texel[t][k]));
    const auto high = hn::Combine(d8, hn::LoadU(d4, texels + fp.texel[t][k + 3]),
                                  hn::LoadU(d4, texels + fp.texel[t][k + 2]));
    return hn::Combine(d, high, low);
  };
  auto blend = [&](const StoredFootprints& fp, int k) HWY_ATTR {
    const auto a = per_pixel(fp.a + k);
    const auto bottom = lerp(texel(fp, 0, k), texel(fp, 1, k), a);
    const auto top = lerp(texel(fp, 2, k), texel(fp, 3, k), a);
    return lerp(bottom, top, per_pixel(fp.b + k));
  };
  int k = 0;
  for (; k + 4 <= count; k += 4) {
    auto color = blend(near, k);
    const auto f = per_pixel(fraction + k);
    const auto blends = hn::Gt(f, hn::Zero(d));
    if (!hn::AllFalse(d, blends)) {
      color = hn::IfThenElse(blends, lerp(color, blend(far, k), f), color);
    }
    hn::StoreU(color, d, rgba[k]);
  }
  return k;
}
#endif

// sample_nearest() of texture.cpp (base level): the texel's offset.
HWY_INLINE IntV Nearest(const Source& src, FloatV u, FloatV v) {
  const FloatTag df;
  const IntTag di;
  const IntV w = hn::Set(di, src.width), h = hn::Set(di, src.height);
  const IntV i = FloorToInt(Sanitize(hn::Mul(u, hn::ConvertTo(df, w))));
  const IntV j = FloorToInt(Sanitize(hn::Mul(v, hn::ConvertTo(df, h))));
  const IntV row = hn::Sub(hn::Sub(h, hn::Set(di, 1)), WrapOne(src.wrap_v, j, h));
  return TexelOffset(hn::Zero(di), w, WrapOne(src.wrap_u, i, w), row);
}

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

// Row `row` of the map's linear part times (du, dv), as sample_map_at() transforms derivatives.
HWY_INLINE FloatV LinearPart(const glm::mat3& m, int row, FloatV du, FloatV dv) {
  const FloatTag df;
  return hn::Add(hn::Mul(hn::Set(df, m[0][row]), du), hn::Mul(hn::Set(df, m[1][row]), dv));
}

// sample_map_at()'s level of detail: exact derivatives, the map's linear part, then
// Texture::lod() (footprint in base texels, the longer squared edge, half its log2), for the W
// vectors of pixels from pixel j on. Each step is done for all W before the next, so that the
// CPU overlaps the vectors' chains of some 40 dependent operations.
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

void SampleBatch(const TextureMap& map, TexelBatch& batch) {
  const FloatTag df;
  const IntTag di;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const Texture& texture = *map.texture;
  const Texture::LinearLevels linear = texture.linear_levels();
  const Source src{linear.texels,    linear.offsets,     texture.level_count(), texture.width(),
                   texture.height(), map.sampler.wrap_u, map.sampler.wrap_v};
  const glm::mat3& m = map.transform;
  const Filter filter = map.sampler.filter;
  const FloatV top = hn::Set(df, static_cast<float>(texture.level_count() - 1));
  // The level of detail's plane slopes when every pixel is of one triangle.
  const Slopes triangle =
      filter == Filter::trilinear && !batch.slopes ? TriangleSlopes(batch) : Slopes{};
  // transform_texcoord() of the pixels from j
  auto transformed = [&](int j) HWY_ATTR {
    const FloatV u = hn::LoadU(df, batch.u + j), v = hn::LoadU(df, batch.v + j);
    return std::pair{
        hn::Add(hn::Add(hn::Mul(hn::Set(df, m[0][0]), u), hn::Mul(hn::Set(df, m[1][0]), v)),
                hn::Set(df, m[2][0])),
        hn::Add(hn::Add(hn::Mul(hn::Set(df, m[0][1]), u), hn::Mul(hn::Set(df, m[1][1]), v)),
                hn::Set(df, m[2][1]))};
  };
  if (filter == Filter::nearest) {
    for (int j = 0; j < batch.count; j += lanes) {
      const auto [ut, vt] = transformed(j);
      alignas(32) std::int32_t texel[kMaxLanes];
      hn::Store(Nearest(src, ut, vt), di, texel);
      for (int k = 0; k < std::min(lanes, batch.count - j); ++k) {
        std::memcpy(batch.rgba[j + k], src.texels + texel[k], 4 * sizeof(float));
      }
    }
    return;
  }
  // Three passes over the batch, each a short loop of independent vectors, so that the CPU
  // overlaps one vector's long dependency chains (the level of detail's logarithm above all)
  // with the next one's. In one loop, each vector's per-pixel blends would stand between them.
  //
  // 1. Each pixel's mip level and the fraction toward the next (sample_levels(): clamp to the
  // chain, blend the two nearest levels); level 0 and no fraction for bilinear.
  alignas(32) std::int32_t level[kTexelBatch];
  alignas(32) float fraction[kTexelBatch];
  if (filter == Filter::bilinear) {
    std::fill_n(level, kTexelBatch, 0);
    std::fill_n(fraction, kTexelBatch, 0.0f);
  }
  // Whole groups of kWays vectors, then single vectors up to the batch's last one.
  constexpr int kWays = 4;
  auto levels = [&](auto ways, int j) HWY_ATTR {
    constexpr int W = decltype(ways)::value;
    FloatV lod[W];
    LevelsOfDetail<W>(texture, m, batch, triangle, j, lod);
    for (int k = 0; k < W; ++k) {
      const FloatV l =
          hn::IfThenElse(hn::Gt(lod[k], hn::Zero(df)), StdMin(lod[k], top), hn::Zero(df));
      const IntV l0 = hn::ConvertTo(di, l);
      hn::Store(l0, di, level + j + k * lanes);
      hn::Store(hn::Sub(l, hn::ConvertTo(df, l0)), df, fraction + j + k * lanes);
    }
  };
  if (filter == Filter::trilinear) {
    int j = 0;
    for (; j + kWays * lanes <= batch.count; j += kWays * lanes) {
      levels(std::integral_constant<int, kWays>(), j);
    }
    for (; j < batch.count; j += lanes) levels(std::integral_constant<int, 1>(), j);
  }
  // 2. Each pixel's footprint in its level, and in the next one where it blends.
  StoredFootprints near, far;
  const IntV top_level = hn::Set(di, texture.level_count() - 1);
  for (int j = 0; j < batch.count; j += lanes) {
    const auto [ut, vt] = transformed(j);
    const IntV l0 = hn::Load(di, level + j);
    near.store(j, Bilinear(src, l0, ut, vt));
    if (!hn::AllFalse(df, hn::Gt(hn::Load(df, fraction + j), hn::Zero(df)))) {
      const IntV l1 = hn::Min(hn::Add(l0, hn::Set(di, 1)), top_level);
      far.store(j, Bilinear(src, l1, ut, vt));
    }
  }
  // 3. Each pixel's blend: four pixels a vector where it has sixteen lanes, then one at a time.
  int k = 0;
#if HWY_ARCH_X86 && HWY_MAX_BYTES >= 64  // AVX-512: 512-bit vectors exist
  k = BlendFours(src.texels, near, far, fraction, batch.count, batch.rgba);
#endif
  for (; k < batch.count; ++k) {
    Texel texel = Blend(src.texels, near, k);
    if (fraction[k] > 0.0f) texel = Lerp(texel, Blend(src.texels, far, k), fraction[k]);
    std::memcpy(batch.rgba[k], &texel, sizeof texel);
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(SampleBatch);

namespace {

// What SampleBatch handles: textures with their levels as one linear float array, and
// repeating wraps only on power-of-two sides (their remainders are masks).
bool simd_samples(const TextureMap& map) {
  const Texture& texture = *map.texture;
  if (texture.linear_levels().texels == nullptr) return false;
  auto wraps_as_mask = [](Wrap mode, int size) {
    return mode == Wrap::clamp_to_edge || (size & (size - 1)) == 0;
  };
  return wraps_as_mask(map.sampler.wrap_u, texture.width()) &&
         wraps_as_mask(map.sampler.wrap_v, texture.height());
}

}  // namespace

SampleBatchKernel sample_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(SampleBatch)[target];
}

void sample_batch(SampleBatchKernel kernel, const TextureMap& map, TexelBatch& batch) {
  if (simd_samples(map)) {
    kernel(map, batch);
    return;
  }
  for (int j = 0; j < batch.count; ++j) {  // Fragment::ddx/ddy, then sample_map_at()
    const float u = batch.u[j], v = batch.v[j], w = batch.w[j];
    using S = TexelBatch;
    float s[S::kSlopes];
    for (int k = 0; k < S::kSlopes; ++k) s[k] = batch.slope(k, j);
    const glm::vec2 dx{(s[S::u_dx] - u * s[S::inv_w_dx]) * w,
                       (s[S::v_dx] - v * s[S::inv_w_dx]) * w};
    const glm::vec2 dy{(s[S::u_dy] - u * s[S::inv_w_dy]) * w,
                       (s[S::v_dy] - v * s[S::inv_w_dy]) * w};
    const glm::vec4 texel = sample_map_at(map, {u, v}, dx, dy);
    for (int c = 0; c < 4; ++c) batch.rgba[j][c] = texel[c];
  }
}

}  // namespace facet::shading
#endif  // HWY_ONCE
