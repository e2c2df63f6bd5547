// 8-bit encoding a row at a time (see srgb_row.hpp). Highway compiles this file once per SIMD
// target; callers fetch the chosen target's kernel (encode_srgb_row_kernel below).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/srgb_row.cpp"
#include "core/srgb_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>
#include <span>
#include <string>

#include "core/color.hpp"
#include "core/truncate_in_range-inl.h"
#include "facet/color.hpp"
#include "facet/error.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace simd = facet::simd::HWY_NAMESPACE;

using FloatTag = hn::ScalableTag<float>;
using IntTag = hn::RebindToSigned<FloatTag>;

// Floats in the widest vector of any target.
constexpr int kMaxFloatLanes = HWY_MAX_BYTES / sizeof(float);

using FloatV = hn::Vec<FloatTag>;
using IntV = hn::Vec<IntTag>;
using Tables = SrgbTables;

// Each channel's factor, (scale, scale, scale, 1) over and over, count of them: the exposure
// scales red, green and blue, not alpha. A vector starting at float j reads it from j % 4 on,
// which covers targets with fewer than four lanes.
void FillFactors(float scale, int count, float* factor) {
  for (int j = 0; j < count; ++j) factor[j] = j % 4 == 3 ? 1.0f : scale;
}

// x clamped to [0, 1], NaN to 0.
HWY_INLINE FloatV Clamped(FloatV x) {
  const FloatTag df;
  return hn::Min(hn::IfThenElseZero(hn::Gt(x, hn::Zero(df)), x), hn::Set(df, 1.0f));
}

// The 8-bit rounding of c in [0, 1]: c * 255 + 0.5 truncated, a multiplication then an
// addition, not fused.
HWY_INLINE IntV Rounded(FloatV c) {
  const FloatTag df;
  return simd::TruncateInRange(IntTag(),
                               hn::Add(hn::Mul(c, hn::Set(df, 255.0f)), hn::Set(df, 0.5f)));
}

// The encode's lines (color.hpp's SrgbTables::encode_lines) of the lanes' entries, taken
// modulo 128 (line_entry): from registers with AVX-512 (eight vectors of sixteen entries, two
// at a time by entry bit 4, then chosen by bits 5 and 6; the permutes read bits 0 to 4 alone),
// else by a gather (a load a lane where the target has none).
HWY_INLINE IntV EncodeLines(const std::uint32_t* lines, IntV entry) {
  const IntTag di;
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
  static_assert(hn::MaxLanes(di) == 16 && Tables::kEncodeEntries == 128);
  auto table = [&](int first) HWY_ATTR {
    return hn::Load(di, reinterpret_cast<const std::int32_t*>(lines) + first).raw;
  };
  auto pair = [&](int first) HWY_ATTR {
    return _mm512_permutex2var_epi32(table(first), entry.raw, table(first + 16));
  };
  const __mmask16 bit5 = _mm512_test_epi32_mask(entry.raw, _mm512_set1_epi32(32));
  const __mmask16 bit6 = _mm512_test_epi32_mask(entry.raw, _mm512_set1_epi32(64));
  const __m512i low = _mm512_mask_blend_epi32(bit5, pair(0), pair(32));
  const __m512i high = _mm512_mask_blend_epi32(bit5, pair(64), pair(96));
  return IntV{_mm512_mask_blend_epi32(bit6, low, high)};
#else
  return hn::GatherIndex(di, reinterpret_cast<const std::int32_t*>(lines),
                         hn::And(entry, hn::Set(di, Tables::kEncodeEntries - 1)));
#endif
}

// The codes of the color channels of c, clamped to [0, 1] (NaN to 0): color.hpp's encode by
// lines.
HWY_INLINE IntV SrgbCodes(const std::uint32_t* lines, FloatV c) {
  const IntTag di;
  // To [2^-13, the float below 1]: as integers, the order of the floats of [0, 1].
  const IntV bits = hn::Min(
      hn::Max(hn::BitCast(di, c), hn::Set(di, static_cast<std::int32_t>(Tables::kEncodeBase))),
      hn::Set(di, static_cast<std::int32_t>(Tables::kEncodeTop)));
  const IntV line = EncodeLines(lines, hn::ShiftRight<Tables::kEncodeLineShift>(bits));
  const IntV t = hn::ShiftRight<Tables::kEncodePointShift>(bits);  // t in the low 8 bits
  // (line >> 16) * 512 + (line & 0xFFFF) * t: the line's 16-bit halves times (512, t), each pair
  // of products added, in one multiply-add (both halves below 2^15, so no sign; the sum below
  // 2^25). One-lane targets have no halves to pair.
#if HWY_TARGET == HWY_SCALAR
  const IntV start = hn::ShiftLeft<9>(hn::ShiftRight<16>(line));
  const IntV along = hn::Mul(hn::And(line, hn::Set(di, 0xFFFF)), hn::And(t, hn::Set(di, 0xFF)));
  return hn::ShiftRight<16>(hn::Add(start, along));
#else
  const IntV t_and_512 = hn::OrAnd(hn::Set(di, 512 << 16), t, hn::Set(di, 0xFF));
  const hn::Repartition<std::int16_t, IntTag> d16;
  IntV odd = hn::Zero(di);
  const IntV even = hn::ReorderWidenMulAccumulate(di, hn::BitCast(d16, line),
                                                  hn::BitCast(d16, t_and_512), hn::Zero(di), odd);
  return hn::ShiftRight<16>(hn::RearrangeToOddPlusEven(even, odd));
#endif
}

// The low bytes of v's lanes, stored from `to`.
HWY_INLINE void StoreBytes(IntV v, std::uint8_t* to) {
  const hn::Rebind<std::uint8_t, FloatTag> du8;
  hn::StoreU(hn::TruncateTo(du8, hn::BitCast(hn::RebindToUnsigned<IntTag>(), v)), du8, to);
}

// Calls encode(from, to, j) for each vector of the `floats` floats from `in`, whose bytes go
// from `out` on (j: the vector's first float): the last, partial one from a copy padded with
// zeros into a buffer of which only its own bytes are kept, so every float goes through the
// same lanes.
template <class Encode>
HWY_INLINE void ForEachVector(const float* in, int floats, std::uint8_t* out,
                              const Encode& encode) {
  const int lanes = static_cast<int>(hn::Lanes(FloatTag()));
  int j = 0;
  for (; j + lanes <= floats; j += lanes) encode(in + j, out + j, j);
  if (j == floats) return;
  alignas(64) float padded_in[kMaxFloatLanes] = {};
  alignas(64) std::uint8_t padded_out[kMaxFloatLanes];
  std::copy_n(in + j, floats - j, padded_in);
  encode(padded_in, padded_out, j);
  std::copy_n(padded_out, floats - j, out + j);
}

// The encode of one vector of floats from `from` (float j of the row on) into `to`.
HWY_INLINE void EncodeVector(const std::uint32_t* lines, const float* factor, const float* from,
                             std::uint8_t* to, int j) {
  const FloatTag df;
  const IntTag di;
  // Alpha's factor is 1: its lanes keep their value.
  const FloatV c = Clamped(hn::Mul(hn::LoadU(df, from), hn::LoadU(df, factor + (j & 3))));
  // Alpha's lanes (j % 4 == 3, counted from j & 3 on, for vectors of one or two lanes).
  const IntV three = hn::Set(di, 3);
  const auto alpha = hn::Eq(hn::And(hn::Iota(di, j & 3), three), three);
  StoreBytes(hn::IfThenElse(alpha, Rounded(c), SrgbCodes(lines, c)), to);
}

void EncodeSrgbRow(const glm::vec4* colors, int count, float scale, std::uint8_t* rgba) {
  const std::uint32_t* lines = srgb_tables().encode_lines.data();
  alignas(64) float factor[kMaxFloatLanes + 4];
  FillFactors(scale, kMaxFloatLanes + 4, factor);
  ForEachVector(&colors[0].x, 4 * count, rgba, [&](const float* from, std::uint8_t* to, int j) {
    EncodeVector(lines, factor, from, to, j);
  });
}

// A vector whose floats all have known's bits takes known's codes; the others are encoded. A
// channel's code depends on its value and whether it is alpha alone, so the bytes are the
// encode's either way. Targets of fewer than four lanes encode every vector.
void EncodeSrgbRowKnowing(const glm::vec4* colors, int count, float scale, const KnownCodes& known,
                          std::uint8_t* rgba) {
  const FloatTag df;
  const IntTag di;
  const std::uint32_t* lines = srgb_tables().encode_lines.data();
  alignas(64) float factor[kMaxFloatLanes + 4];
  FillFactors(scale, kMaxFloatLanes + 4, factor);
  const int lanes = static_cast<int>(hn::Lanes(df));
  if (lanes < 4) {
    ForEachVector(&colors[0].x, 4 * count, rgba, [&](const float* from, std::uint8_t* to, int j) {
      EncodeVector(lines, factor, from, to, j);
    });
    return;
  }
  // Vectors start at a color (j % 4 == 0): known's channels, once per color in the vector.
  const IntV known_bits = hn::BitCast(di, hn::LoadDup128(df, &known.color.x));
  ForEachVector(&colors[0].x, 4 * count, rgba, [&](const float* from, std::uint8_t* to, int j) {
    if (hn::AllTrue(di, hn::Eq(hn::BitCast(di, hn::LoadU(df, from)), known_bits))) {
      for (int k = 0; k < lanes; k += 4) std::memcpy(to + k, &known.codes, 4);
    } else {
      EncodeVector(lines, factor, from, to, j);
    }
  });
}

// Every channel as EncodeSrgbRow rounds alpha, lane by lane.
void RoundUnorm8Row(const glm::vec4* colors, int count, std::uint8_t* rgba) {
  const FloatTag df;
  ForEachVector(&colors[0].x, 4 * count, rgba, [&](const float* from, std::uint8_t* to, int) {
    StoreBytes(Rounded(Clamped(hn::LoadU(df, from))), to);  // 0 .. 255: the low bytes
  });
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(EncodeSrgbRow);
HWY_EXPORT(EncodeSrgbRowKnowing);
HWY_EXPORT(RoundUnorm8Row);

EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(EncodeSrgbRow)[target];
}

EncodeSrgbRowKnowingKernel encode_srgb_row_knowing_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(EncodeSrgbRowKnowing)[target];
}

RoundUnorm8RowKernel round_unorm8_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(RoundUnorm8Row)[target];
}

}  // namespace facet::shading

namespace facet {

void encode_srgb8(std::span<const glm::vec4> linear, std::span<std::uint8_t> rgba, float scale) {
  if (rgba.size() / 4 < linear.size()) {
    throw Error("encode_srgb8: " + std::to_string(rgba.size()) + " bytes for " +
                std::to_string(linear.size()) + " colors");
  }
  shading::encode_srgb_row_kernel(chosen_simd_target())(
      linear.data(), static_cast<int>(linear.size()), scale, rgba.data());
}

}  // namespace facet
#endif  // HWY_ONCE
