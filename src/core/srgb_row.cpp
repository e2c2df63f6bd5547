// 8-bit encoding a row at a time (see srgb_row.hpp). Highway compiles this file once per SIMD
// target; callers fetch the chosen target's kernel (encode_srgb_row_kernel below).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/srgb_row.cpp"
#include "core/srgb_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>

#include "core/color.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using FloatTag = hn::ScalableTag<float>;
using IntTag = hn::RebindToSigned<FloatTag>;

// Colors per step: the SIMD passes fill and read arrays for this many, the lookups between.
constexpr int kChunk = 64;
// Floats in the widest vector of any target.
constexpr int kMaxFloatLanes = HWY_MAX_BYTES / sizeof(float);

void EncodeSrgbRow(const glm::vec4* colors, int count, float scale, std::uint8_t* rgba) {
  const FloatTag df;
  const IntTag di;
  const hn::RebindToUnsigned<IntTag> du;
  const hn::Rebind<std::uint8_t, FloatTag> du8;
  const int lanes = static_cast<int>(hn::Lanes(df));
  using Tables = SrgbTables;
  const Tables& tables = srgb_tables();
  // Each channel's factor, (scale, scale, scale, 1) over and over: the exposure scales red,
  // green and blue, not alpha. A vector starting at float j reads it from j % 4 on, which
  // covers targets with fewer than four lanes.
  alignas(64) float factor[kChunk + 4];
  for (int j = 0; j < kChunk + 4; ++j) factor[j] = j % 4 == 3 ? 1.0f : scale;
  // Per channel: the bits of its value clamped to [0, 1] (NaN to 0) above those of the first
  // run (color.hpp; 0 below it), and its run. Per color channel, the run's entry; per alpha
  // channel, its 8-bit rounding (v * 255 + 0.5, truncated).
  alignas(64) std::int32_t above[4 * kChunk + kMaxFloatLanes];
  alignas(64) std::int32_t run[4 * kChunk + kMaxFloatLanes];
  alignas(64) std::int32_t entry[4 * kChunk + kMaxFloatLanes];
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto run_base = hn::Set(di, static_cast<std::int32_t>(Tables::kRunBase));
  const auto codes = hn::Set(df, 255.0f), half = hn::Set(df, 0.5f);
  const auto three = hn::Set(di, 3);
  const auto run_mask = hn::Set(di, static_cast<std::int32_t>(Tables::kRunMask));
  const auto offset_mask = hn::Set(di, static_cast<std::int32_t>(Tables::kRunOffsetMask));
  // A chunk whose floats end inside a vector is encoded from a copy padded with zeros, into a
  // buffer of which only its own bytes are kept: every float goes through the same lanes.
  alignas(64) float padded_in[4 * kChunk + kMaxFloatLanes];
  alignas(64) std::uint8_t padded_out[4 * kChunk + kMaxFloatLanes];
  for (int first = 0; first < count; first += kChunk) {
    const int floats = 4 * std::min(kChunk, count - first);
    // Whole vectors, a whole number of colors (lanes are 1, 2 or a multiple of 4).
    const int whole = (floats + lanes - 1) / lanes * lanes;
    const float* in = &colors[first].x;
    std::uint8_t* const destination = rgba + 4 * static_cast<std::ptrdiff_t>(first);
    std::uint8_t* out = destination;
    if (whole != floats) {
      std::copy_n(in, floats, padded_in);
      std::fill(padded_in + floats, padded_in + whole, 0.0f);
      in = padded_in, out = padded_out;
    }
    // 1. Clamp; the run; alpha's code.
    for (int j = 0; j < whole; j += lanes) {
      const auto x = hn::Mul(hn::LoadU(df, in + j), hn::LoadU(df, factor + (j & 3)));
      const auto c = hn::Min(hn::IfThenElseZero(hn::Gt(x, zero), x), one);
      const auto bits_above = hn::Max(hn::Sub(hn::BitCast(di, c), run_base), hn::Zero(di));
      hn::Store(bits_above, di, above + j);
      hn::Store(hn::ShiftRight<Tables::kRunBits>(bits_above), di, run + j);
      // A multiplication then an addition, not fused.
      hn::Store(hn::ConvertTo(di, hn::Add(hn::Mul(c, codes), half)), di, entry + j);
    }
    // 2. The color channels' runs looked up, one at a time (scalar loads: faster than gathers
    // on the CPUs this runs on).
    for (int k = 0; k < whole; k += 4) {
      entry[k] = static_cast<std::int32_t>(tables.run_code[run[k]]);
      entry[k + 1] = static_cast<std::int32_t>(tables.run_code[run[k + 1]]);
      entry[k + 2] = static_cast<std::int32_t>(tables.run_code[run[k + 2]]);
    }
    // 3. A color's code: the run's first, or the next from its offset in the run on.
    for (int j = 0; j < whole; j += lanes) {
      const auto e = hn::Load(di, entry + j);
      const auto offset = hn::And(hn::Load(di, above + j), run_mask);
      const auto next = hn::Not(hn::Lt(offset, hn::And(e, offset_mask)));
      // The mask as a vector is -1 where the next code has begun.
      const auto code =
          hn::Sub(hn::ShiftRight<Tables::kRunCodeShift>(e), hn::VecFromMask(di, next));
      // Alpha's lanes: j % 4 == 3, counted from j & 3 on (vectors of one or two lanes).
      const auto alpha = hn::Eq(hn::And(hn::Iota(di, j & 3), three), three);
      const auto byte = hn::IfThenElse(alpha, e, code);
      hn::StoreU(hn::TruncateTo(du8, hn::BitCast(du, byte)), du8, out + j);
    }
    if (out != destination) std::copy_n(out, floats, destination);
  }
}

// Every channel as EncodeSrgbRow rounds alpha, lane by lane.
void RoundUnorm8Row(const glm::vec4* colors, int count, std::uint8_t* rgba) {
  const FloatTag df;
  const IntTag di;
  const hn::Rebind<std::uint8_t, FloatTag> du8;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto codes = hn::Set(df, 255.0f), half = hn::Set(df, 0.5f);
  const auto round = [&](const float* from, std::uint8_t* to) {
    const auto x = hn::LoadU(df, from);
    const auto c = hn::Min(hn::IfThenElseZero(hn::Gt(x, zero), x), one);
    // A multiplication then an addition, not fused, as alpha's.
    const auto code = hn::ConvertTo(di, hn::Add(hn::Mul(c, codes), half));
    hn::StoreU(hn::DemoteTo(du8, code), du8, to);
  };
  const float* in = &colors[0].x;
  const int floats = 4 * count;
  int j = 0;
  for (; j + lanes <= floats; j += lanes) round(in + j, rgba + j);
  if (j == floats) return;
  // The floats left, padded with zeros to a vector; only their own bytes are kept.
  alignas(64) float padded_in[kMaxFloatLanes] = {};
  alignas(64) std::uint8_t padded_out[kMaxFloatLanes];
  std::copy_n(in + j, floats - j, padded_in);
  round(padded_in, padded_out);
  std::copy_n(padded_out, floats - j, rgba + j);
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(EncodeSrgbRow);
HWY_EXPORT(RoundUnorm8Row);

EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(EncodeSrgbRow)[target];
}

RoundUnorm8RowKernel round_unorm8_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(RoundUnorm8Row)[target];
}

}  // namespace facet::shading
#endif  // HWY_ONCE
