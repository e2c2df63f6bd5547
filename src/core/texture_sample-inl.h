// Texture filtering on vectors of pixels: the one implementation of nearest, bilinear and
// trilinear sampling (OpenGL 4.6 §8.14), shared by Texture::sample (texture_sampler.cpp, at
// given levels of detail) and the shading stage's batch sampler (shading/texel_batch.cpp, levels
// of detail from each pixel's derivatives). Included inside each file's Highway target loop, the
// "-inl.h" way. Every target computes the same IEEE operations in the same order (no fused
// multiply-add; std::min/max as compare-and-select, which treat NaN as they do), so every target
// gives the same bits; texel_batch_test checks them against a plain scalar sampler.
//
// Orientation: texture coordinates follow OpenGL, v = 0 is the BOTTOM row of the image while
// levels store rows top first, so a wrapped row j is stored row height - 1 - j.
#if defined(FACET_CORE_TEXTURE_SAMPLE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_CORE_TEXTURE_SAMPLE_INL_H_
#undef FACET_CORE_TEXTURE_SAMPLE_INL_H_
#else
#define FACET_CORE_TEXTURE_SAMPLE_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

#include "core/texel.hpp"
#include "core/truncate_in_range-inl.h"
#include "facet/texture.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::sampling::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace simd = facet::simd::HWY_NAMESPACE;

// Pixels sampled per call at most: the shading stage's batch.
inline constexpr int kMaxPixels = 64;
// Eight lanes at most: batches are often a few pixels of a small triangle, where AVX-512's
// sixteen lanes mostly compute padding (and full batches gain nothing from them: BENCHMARKS.md
// §6).
constexpr int kMaxLanes = 8;
using FloatTag = hn::CappedTag<float, kMaxLanes>;
using IntTag = hn::RebindToSigned<FloatTag>;
using FloatV = hn::Vec<FloatTag>;
using IntV = hn::Vec<IntTag>;

// A texel-space coordinate made safe to convert to int: huge values are clamped to +-2^23
// (beyond it floats are whole numbers anyway, and +1 still fits in an int), NaN to -2^23.
// Highway's Max gives its second argument where the first is NaN, on every target.
HWY_INLINE FloatV Sanitize(FloatV x) {
  const FloatTag df;
  const FloatV limit = hn::Set(df, 8388608.0f);
  return hn::Min(hn::Max(x, hn::Neg(limit)), limit);
}
// Floor of a sanitized coordinate (exact; |x| <= 2^23 after Sanitize, so it fits an int).
HWY_INLINE IntV FloorToInt(FloatV x) { return simd::TruncateInRange(IntTag(), hn::Floor(x)); }

// i mod size, in [0, size). A power of two takes a mask (with two's complement the positive
// remainder even for i < 0); other sizes the floor of a float division, which is the true floor:
// |i| <= 2^23 + 1 and size are exact in floats, a quotient that is not whole lies at least
// 1 / size from the nearest integer, and half a float's spacing there is less than that.
HWY_INLINE IntV PositiveMod(IntV i, IntV size, bool power_of_two) {
  const FloatTag df;
  const IntTag di;
  if (power_of_two) return hn::And(i, hn::Sub(size, hn::Set(di, 1)));
  const IntV quotient = FloorToInt(hn::Div(hn::ConvertTo(df, i), hn::ConvertTo(df, size)));
  return hn::Sub(i, hn::Mul(quotient, size));
}

// Integer texel coordinate -> a coordinate inside [0, size), OpenGL 4.6 §8.14.2 (table 8.20).
// power_of_two: size is one (then so is twice it).
HWY_INLINE IntV WrapOne(Wrap mode, IntV i, IntV size, bool power_of_two) {
  const IntTag di;
  const IntV one = hn::Set(di, 1);
  switch (mode) {
    case Wrap::clamp_to_edge:
      return hn::Min(hn::Max(i, hn::Zero(di)), hn::Sub(size, one));
    case Wrap::mirrored_repeat: {  // period 2 size: forwards in [0, size), backwards after
      const IntV period = hn::Add(size, size);
      const IntV m = PositiveMod(i, period, power_of_two);
      return hn::IfThenElse(hn::Lt(m, size), m, hn::Sub(hn::Sub(period, one), m));
    }
    case Wrap::repeat:
    default:
      return PositiveMod(i, size, power_of_two);
  }
}

// The wrapped pair (i, i + 1) of a bilinear footprint. For repeat the second follows from the
// first.
struct Pair {
  IntV first, second;
};
HWY_INLINE Pair WrapPair(Wrap mode, IntV i, IntV size, bool power_of_two) {
  const IntTag di;
  if (mode == Wrap::repeat && power_of_two) {
    const IntV mask = hn::Sub(size, hn::Set(di, 1));
    return {hn::And(i, mask), hn::And(hn::Add(i, hn::Set(di, 1)), mask)};
  }
  if (mode == Wrap::repeat) {
    const IntV first = WrapOne(mode, i, size, power_of_two);
    const IntV next = hn::Add(first, hn::Set(di, 1));
    return {first, hn::IfThenElse(hn::Eq(next, size), hn::Zero(di), next)};
  }
  return {WrapOne(mode, i, size, power_of_two),
          WrapOne(mode, hn::Add(i, hn::Set(di, 1)), size, power_of_two)};
}

// What the sampling steps share for one texture and sampler. The texels are read from the
// texture's linear float copy of all its levels where it keeps one (Texture::linear_levels),
// else from its levels one by one.
struct Source {
  const Texture* texture;
  const float* texels;          // the linear copy, or null
  const std::int32_t* offsets;  // its level offsets, padded: whole vectors may be loaded
  int levels, width, height;
  Wrap wrap_u, wrap_v;
  bool power_of_two_u, power_of_two_v;  // the base level's sides (then every level's)
  int log2_width;                       // where power_of_two_u
};

HWY_INLINE Source SourceOf(const Texture& texture, const Sampler& sampler) {
  const Texture::LinearLevels linear = texture.linear_levels();
  const int width = texture.width(), height = texture.height();
  return {&texture,
          linear.texels,
          linear.offsets,
          texture.level_count(),
          width,
          height,
          sampler.wrap_u,
          sampler.wrap_v,
          (width & (width - 1)) == 0,
          (height & (height - 1)) == 0,
          std::countr_zero(static_cast<unsigned>(width))};
}

// src.offsets[level] per lane (0 <= level < src.levels) with permutes of the offsets' vectors
// instead of a gather (slow on this project's machines). The offsets are read a vector at a
// time from their start; a lane takes its entry from the last vector that starts at or before
// its level. Zero without a linear copy: texels are then found per level.
HWY_INLINE IntV LevelOffset(const Source& src, IntV level) {
  const IntTag di;
  if (src.texels == nullptr) return hn::Zero(di);
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

// Level sizes: each side halved per level, at least 1 (as the texture builds them).
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

// The level of every lane, where they share one: then its sizes and offset are scalars; the base
// level's are the same for every vector.
struct SharedLevel {
  int level;
};
struct BaseLevel {};

// The start of each lane's row in its level (row * the level's width); where one level serves
// every lane (SharedLevel, BaseLevel) and the sides are powers of two, by a shift. (A shift per
// lane is itself a multiplication before AVX2.)
HWY_INLINE IntV RowStart(const Source&, IntV /*level*/, IntV width, IntV row) {
  return hn::Mul(row, width);
}
HWY_INLINE IntV RowStart(const Source& src, SharedLevel level, IntV width, IntV row) {
  if (!src.power_of_two_u) return hn::Mul(row, width);
  return hn::ShiftLeftSame(row, std::max(src.log2_width - level.level, 0));
}
HWY_INLINE IntV RowStart(const Source& src, BaseLevel, IntV width, IntV row) {
  if (!src.power_of_two_u) return hn::Mul(row, width);
  return hn::ShiftLeftSame(row, src.log2_width);
}
HWY_INLINE IntV LevelSize(int base, SharedLevel level) {
  return hn::Set(IntTag(), std::max(base >> level.level, 1));
}
HWY_INLINE IntV LevelSize(int base, BaseLevel) { return hn::Set(IntTag(), base); }
HWY_INLINE IntV LevelOffset(const Source& src, SharedLevel level) {
  return hn::Set(IntTag(), src.texels == nullptr ? 0 : src.offsets[level.level]);
}
HWY_INLINE IntV LevelOffset(const Source&, BaseLevel) { return hn::Zero(IntTag()); }

// The bilinear filter (OpenGL 4.6 §8.14.2) at each lane's level, up to the texel fetches: texel
// centres sit at integer + 0.5, so the four texels around uv * size - 0.5 are blended by the
// fractional part of that position.
template <class Level>
HWY_INLINE Footprint Bilinear(const Source& src, Level level, FloatV u, FloatV v) {
  const FloatTag df;
  const IntTag di;
  const IntV w = LevelSize(src.width, level), h = LevelSize(src.height, level);
  const FloatV half = hn::Set(df, 0.5f);
  const FloatV x = Sanitize(hn::Sub(hn::Mul(u, hn::ConvertTo(df, w)), half));
  const FloatV y = Sanitize(hn::Sub(hn::Mul(v, hn::ConvertTo(df, h)), half));
  // Exact; x and y are never -0 (u * w - 0.5 rounds to +0 at worst), whose floor's sign
  // differs between targets.
  const FloatV floor_x = hn::Floor(x), floor_y = hn::Floor(y);
  const IntV i0 = simd::TruncateInRange(di, floor_x), j0 = simd::TruncateInRange(di, floor_y);
  Footprint fp;
  fp.a = hn::Sub(x, floor_x);  // in [0, 1)
  fp.b = hn::Sub(y, floor_y);
  const Pair xs = WrapPair(src.wrap_u, i0, w, src.power_of_two_u);
  const Pair ys = WrapPair(src.wrap_v, j0, h, src.power_of_two_v);
  const IntV last_row = hn::Sub(h, hn::Set(di, 1));
  const IntV r0 = hn::Sub(last_row, ys.first), r1 = hn::Sub(last_row, ys.second);
  const IntV offset = LevelOffset(src, level);
  const IntV row0 = RowStart(src, level, w, r0), row1 = RowStart(src, level, w, r1);
  fp.texel[0] = hn::Add(offset, hn::ShiftLeft<2>(hn::Add(row0, xs.first)));
  fp.texel[1] = hn::Add(offset, hn::ShiftLeft<2>(hn::Add(row0, xs.second)));
  fp.texel[2] = hn::Add(offset, hn::ShiftLeft<2>(hn::Add(row1, xs.first)));
  fp.texel[3] = hn::Add(offset, hn::ShiftLeft<2>(hn::Add(row1, xs.second)));
  return fp;
}

// The nearest texel of the base level: its offset.
HWY_INLINE IntV Nearest(const Source& src, FloatV u, FloatV v) {
  const FloatTag df;
  const IntTag di;
  const IntV w = hn::Set(di, src.width), h = hn::Set(di, src.height);
  const IntV i = FloorToInt(Sanitize(hn::Mul(u, hn::ConvertTo(df, w))));
  const IntV j = FloorToInt(Sanitize(hn::Mul(v, hn::ConvertTo(df, h))));
  const IntV row =
      hn::Sub(hn::Sub(h, hn::Set(di, 1)), WrapOne(src.wrap_v, j, h, src.power_of_two_v));
  const IntV x = WrapOne(src.wrap_u, i, w, src.power_of_two_u);
  return hn::ShiftLeft<2>(hn::Add(RowStart(src, BaseLevel{}, w, row), x));
}

// Every pixel's footprint, stored a vector at a time for the per-pixel blend.
struct StoredFootprints {
  alignas(32) std::int32_t texel[4][kMaxPixels];
  alignas(32) float a[kMaxPixels], b[kMaxPixels];
  void store(int j, const Footprint& fp) {
    const FloatTag df;
    const IntTag di;
    for (int t = 0; t < 4; ++t) hn::Store(fp.texel[t], di, texel[t] + j);
    hn::Store(fp.a, df, a + j);
    hn::Store(fp.b, df, b + j);
  }
};

// The texel at offset `offset` of level `level`, linear RGBA, from each kind of storage: the
// linear copy (offsets count from its start), float RGBA levels, one-float levels, and 8-bit
// levels decoded by table.
struct LinearCopy {
  const float* texels;
  HWY_INLINE Texel operator()(int /*level*/, std::int32_t offset) const {
    return load_texel(texels + offset);
  }
};
struct FloatLevels {
  const Texture* texture;
  HWY_INLINE Texel operator()(int level, std::int32_t offset) const {
    return load_texel(texture->level(level).rgba32f.data() + offset);
  }
};
struct R32fLevels {  // one float a texel: offsets count four a texel, as for RGBA
  const Texture* texture;
  HWY_INLINE Texel operator()(int level, std::int32_t offset) const {
    const float v = texture->level(level).r32f[static_cast<std::size_t>(offset >> 2)];
    return Texel{v, v, v, 1.0f};
  }
};
struct Rgba8Levels {
  const Texture* texture;
  const float* color;  // decode table for r, g, b: sRGB or unorm
  const float* alpha;  // for alpha: always unorm
  HWY_INLINE Texel operator()(int level, std::int32_t offset) const {
    return decode_rgba8(texture->level(level).rgba8.data() + offset, color, alpha);
  }
};

// a * (1 - f) + b * f per channel.
HWY_INLINE Texel Lerp(Texel a, Texel b, float f) { return a * (1.0f - f) + b * f; }

// The bilinear blend of lane k's footprint at `level`.
template <class Fetch>
HWY_INLINE Texel Blend(const Fetch& fetch, int level, const StoredFootprints& fp, int k) {
  const Texel bottom = Lerp(fetch(level, fp.texel[0][k]), fetch(level, fp.texel[1][k]), fp.a[k]);
  const Texel top = Lerp(fetch(level, fp.texel[2][k]), fetch(level, fp.texel[3][k]), fp.a[k]);
  return Lerp(bottom, top, fp.b[k]);
}

#if HWY_ARCH_X86 && HWY_MAX_BYTES >= 32  // AVX2 and AVX-512: 256-bit vectors exist
// Blend() and the blend toward the next level for the whole groups of four pixels of the batch,
// from the linear copy, two pixels a 256-bit vector (lanes 4p .. 4p + 3 are pixel p's channels:
// a texel is one 128-bit load); returns how many pixels it did. The same operations per lane as
// the per-pixel blends; a pixel whose fraction is 0 keeps its level's blend (a select: the
// per-pixel code skips the lerp). (Sixteen lanes hold four pixels, but building them from
// 128-bit loads takes more shuffles than they save: BENCHMARKS.md §6.)
HWY_INLINE int BlendFours(const float* texels, const StoredFootprints& near,
                          const StoredFootprints& far, const float* fraction, int count,
                          float (*rgba)[4]) {
  // A group of four pixels lies in one vector of the footprint pass, so where one of them
  // blends toward the next level, all four have their next-level footprints stored.
  static_assert(hn::MaxLanes(FloatTag()) % 4 == 0);
  const hn::Full256<float> d;
  const hn::Full128<float> d4;
  const hn::RebindToSigned<decltype(d)> di;
  alignas(32) static constexpr std::int32_t kPixelOfLane[2][8] = {{0, 0, 0, 0, 1, 1, 1, 1},
                                                                  {2, 2, 2, 2, 3, 3, 3, 3}};
  const auto spread_low = hn::IndicesFromVec(d, hn::Load(di, kPixelOfLane[0]));
  const auto spread_high = hn::IndicesFromVec(d, hn::Load(di, kPixelOfLane[1]));
  const auto one = hn::Set(d, 1.0f);
  // Lerp(), lane by lane.
  auto lerp = [&](auto a, auto b, auto f) HWY_ATTR {
    const auto from_a = hn::Mul(a, hn::Sub(one, f));
    return hn::Add(from_a, hn::Mul(b, f));
  };
  // Pixels k + 2h and k + 2h + 1 (h: the half of the group).
  auto blend_half = [&](const StoredFootprints& fp, int k, int h, auto four_a, auto four_b,
                        auto spread) HWY_ATTR {
    auto texel = [&](int t) HWY_ATTR {
      return hn::Combine(d, hn::LoadU(d4, texels + fp.texel[t][k + 2 * h + 1]),
                         hn::LoadU(d4, texels + fp.texel[t][k + 2 * h]));
    };
    const auto a = hn::TableLookupLanes(four_a, spread);
    const auto bottom = lerp(texel(0), texel(1), a);
    const auto top = lerp(texel(2), texel(3), a);
    return lerp(bottom, top, hn::TableLookupLanes(four_b, spread));
  };
  int k = 0;
  for (; k + 4 <= count; k += 4) {
    const auto four_f = hn::LoadDup128(d, fraction + k);
    const auto blends = hn::Gt(four_f, hn::Zero(d));  // the four pixels', twice
    const bool any = !hn::AllFalse(d, blends);
    for (int h = 0; h < 2; ++h) {
      const auto spread = h == 0 ? spread_low : spread_high;
      auto color = blend_half(near, k, h, hn::LoadDup128(d, near.a + k),
                              hn::LoadDup128(d, near.b + k), spread);
      if (any) {
        const auto f = hn::TableLookupLanes(four_f, spread);
        const auto next = blend_half(far, k, h, hn::LoadDup128(d, far.a + k),
                                     hn::LoadDup128(d, far.b + k), spread);
        color = hn::IfThenElse(hn::Gt(f, hn::Zero(d)), lerp(color, next, f), color);
      }
      hn::StoreU(color, d, rgba[k + 2 * h]);
    }
  }
  return k;
}
#endif

// Each pixel's blend at its level, and toward the next where its fraction is above 0, from k on.
template <class Fetch>
HWY_INLINE void BlendPixels(const Fetch& fetch, const Source& src, const StoredFootprints& near,
                            const StoredFootprints& far, const std::int32_t* level,
                            const float* fraction, int k, int count, float (*rgba)[4]) {
  for (; k < count; ++k) {
    Texel texel = Blend(fetch, level[k], near, k);
    if (fraction[k] > 0.0f) {
      texel =
          Lerp(texel, Blend(fetch, std::min(level[k] + 1, src.levels - 1), far, k), fraction[k]);
    }
    std::memcpy(rgba[k], &texel, sizeof texel);
  }
}

// A level of detail clamped to the chain (negative is magnification, the base level; NaN too)
// as the level to sample and the fraction toward the next, stored at level + j, fraction + j.
HWY_INLINE void StoreLevel(FloatV lod, FloatV top, std::int32_t* level, float* fraction, int j) {
  const FloatTag df;
  const IntTag di;
  const FloatV below_top = hn::IfThenElse(hn::Lt(top, lod), top, lod);
  const FloatV l = hn::IfThenElse(hn::Gt(lod, hn::Zero(df)), below_top, hn::Zero(df));
  const IntV l0 = simd::TruncateInRange(di, l);
  hn::Store(l0, di, level + j);
  hn::Store(hn::Sub(l, hn::ConvertTo(df, l0)), df, fraction + j);
}

// Samples `count` pixels (at most kMaxPixels) of src with `filter` into rgba: coords(j) gives the
// texture coordinates (u, v) of the vector of pixels from j. Trilinear reads each pixel's
// level and fraction (StoreLevel); bilinear and nearest read the base level. Arrays are read a
// whole vector at a time up to the vector holding pixel count - 1.
template <class Coords>
HWY_INLINE void SamplePixels(const Source& src, Filter filter, const Coords& coords,
                             const std::int32_t* level, const float* fraction, int count,
                             float (*rgba)[4]) {
  const FloatTag df;
  const IntTag di;
  const int lanes = static_cast<int>(hn::Lanes(df));
  if (filter == Filter::nearest) {
    alignas(32) std::int32_t texel[kMaxPixels];
    for (int j = 0; j < count; j += lanes) {
      const auto [u, v] = coords(j);
      hn::Store(Nearest(src, u, v), di, texel + j);
    }
    if (src.texels != nullptr) {
      for (int k = 0; k < count; ++k) std::memcpy(rgba[k], src.texels + texel[k], 16);
      return;
    }
    auto store = [&](const auto& fetch) {
      for (int k = 0; k < count; ++k) {
        const Texel t = fetch(0, texel[k]);
        std::memcpy(rgba[k], &t, sizeof t);
      }
    };
    if (src.texture->format() == Texture::Format::rgba32f) {
      store(FloatLevels{src.texture});
    } else if (src.texture->format() == Texture::Format::r32f) {
      store(R32fLevels{src.texture});
    } else {
      const TexelDecode& decode = texel_decode();
      store(Rgba8Levels{src.texture, decode.color(src.texture->srgb()), decode.unorm.data()});
    }
    return;
  }
  alignas(32) static constexpr std::int32_t kBaseLevels[kMaxPixels] = {};
  alignas(32) static constexpr float kNoFractions[kMaxPixels] = {};
  if (filter == Filter::bilinear) level = kBaseLevels, fraction = kNoFractions;
  // Each pixel's footprint in its level, and in the next one where it blends.
  StoredFootprints near, far;
  const IntV top_level = hn::Set(di, src.levels - 1);
  for (int j = 0; j < count; j += lanes) {
    const auto [u, v] = coords(j);
    if (filter == Filter::bilinear) {
      near.store(j, Bilinear(src, BaseLevel{}, u, v));
      continue;
    }
    // The lanes of a vector mostly share their level.
    const IntV l0 = hn::Load(di, level + j);
    const int first = level[j];
    const bool shared = hn::AllTrue(di, hn::Eq(l0, hn::Set(di, first)));
    if (shared && first == 0) {
      near.store(j, Bilinear(src, BaseLevel{}, u, v));
    } else if (shared) {
      near.store(j, Bilinear(src, SharedLevel{first}, u, v));
    } else {
      near.store(j, Bilinear(src, l0, u, v));
    }
    if (!hn::AllFalse(df, hn::Gt(hn::Load(df, fraction + j), hn::Zero(df)))) {
      if (shared) {
        far.store(j, Bilinear(src, SharedLevel{std::min(first + 1, src.levels - 1)}, u, v));
      } else {
        far.store(j, Bilinear(src, hn::Min(hn::Add(l0, hn::Set(di, 1)), top_level), u, v));
      }
    }
  }
  // Each pixel's blend: from the linear copy whole groups of four pixels in 256-bit vectors
  // where they exist, then one at a time.
  if (src.texels != nullptr) {
    int k = 0;
#if HWY_ARCH_X86 && HWY_MAX_BYTES >= 32  // AVX2 and AVX-512
    k = BlendFours(src.texels, near, far, fraction, count, rgba);
#endif
    BlendPixels(LinearCopy{src.texels}, src, near, far, level, fraction, k, count, rgba);
  } else if (src.texture->format() == Texture::Format::rgba32f) {
    BlendPixels(FloatLevels{src.texture}, src, near, far, level, fraction, 0, count, rgba);
  } else if (src.texture->format() == Texture::Format::r32f) {
    BlendPixels(R32fLevels{src.texture}, src, near, far, level, fraction, 0, count, rgba);
  } else {
    const TexelDecode& decode = texel_decode();
    BlendPixels(Rgba8Levels{src.texture, decode.color(src.texture->srgb()), decode.unorm.data()},
                src, near, far, level, fraction, 0, count, rgba);
  }
}

}  // namespace facet::sampling::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_CORE_TEXTURE_SAMPLE_INL_H_
