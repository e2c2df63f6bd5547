// 8-bit encoding a row at a time (see srgb_row.hpp). Highway compiles this file once per SIMD
// target; callers fetch the chosen target's kernel (encode_srgb_row_kernel below).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/srgb_row.cpp"
#include "core/srgb_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

#include "core/color.hpp"
#include "core/truncate_in_range-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace simd = facet::simd::HWY_NAMESPACE;

using FloatTag = hn::ScalableTag<float>;
using IntTag = hn::RebindToSigned<FloatTag>;

// Colors per step: the SIMD passes fill and read arrays for this many, the lookups between.
constexpr int kChunk = 64;
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

// The bits of c (clamped) above those of the first run of the encoding table (color.hpp; 0
// below it): the run is these >> kRunBits, the offset in it the bits below.
HWY_INLINE IntV BitsAbove(FloatV c) {
  const IntTag di;
  return hn::Max(
      hn::Sub(hn::BitCast(di, c), hn::Set(di, static_cast<std::int32_t>(Tables::kRunBase))),
      hn::Zero(di));
}

// The bytes of the vector of floats from j: a color channel's code from its run's `entry` (the
// run's first code, or the next from its offset in the run on), alpha's (j % 4 == 3, counted
// from j & 3 on, for vectors of one or two lanes) `alpha_code`.
HWY_INLINE IntV Codes(IntV entry, IntV above, IntV alpha_code, int j) {
  const IntTag di;
  const auto offset = hn::And(above, hn::Set(di, static_cast<std::int32_t>(Tables::kRunMask)));
  const auto next = hn::Not(hn::Lt(
      offset, hn::And(entry, hn::Set(di, static_cast<std::int32_t>(Tables::kRunOffsetMask)))));
  // The mask as a vector is -1 where the next code has begun.
  const auto code =
      hn::Sub(hn::ShiftRight<Tables::kRunCodeShift>(entry), hn::VecFromMask(di, next));
  const auto three = hn::Set(di, 3);
  const auto alpha = hn::Eq(hn::And(hn::Iota(di, j & 3), three), three);
  return hn::IfThenElse(alpha, alpha_code, code);
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

void EncodeSrgbRow(const glm::vec4* colors, int count, float scale, std::uint8_t* rgba) {
  const FloatTag df;
  const IntTag di;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const Tables& tables = srgb_tables();
  alignas(64) float factor[kChunk + 4];
  FillFactors(scale, kChunk + 4, factor);
  // Per channel: BitsAbove and its run. Per color channel, the run's entry; per alpha channel,
  // its 8-bit rounding.
  alignas(64) std::int32_t above[4 * kChunk + kMaxFloatLanes];
  alignas(64) std::int32_t run[4 * kChunk + kMaxFloatLanes];
  alignas(64) std::int32_t entry[4 * kChunk + kMaxFloatLanes];
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
      const auto c = Clamped(hn::Mul(hn::LoadU(df, in + j), hn::LoadU(df, factor + (j & 3))));
      const auto bits_above = BitsAbove(c);
      hn::Store(bits_above, di, above + j);
      hn::Store(hn::ShiftRight<Tables::kRunBits>(bits_above), di, run + j);
      hn::Store(Rounded(c), di, entry + j);
    }
    // 2. The color channels' runs looked up, one at a time (scalar loads: faster than gathers
    // where the microcode mitigates Gather Data Sampling; EncodeSrgbRowGathering elsewhere).
    for (int k = 0; k < whole; k += 4) {
      entry[k] = static_cast<std::int32_t>(tables.run_code[run[k]]);
      entry[k + 1] = static_cast<std::int32_t>(tables.run_code[run[k + 1]]);
      entry[k + 2] = static_cast<std::int32_t>(tables.run_code[run[k + 2]]);
    }
    // 3. The codes (alpha's entry is its rounding).
    for (int j = 0; j < whole; j += lanes) {
      const auto e = hn::Load(di, entry + j);
      StoreBytes(Codes(e, hn::Load(di, above + j), e, j), out + j);
    }
    if (out != destination) std::copy_n(out, floats, destination);
  }
}

// EncodeSrgbRow with each run's entry gathered, in one pass over the row: the same bytes, faster
// where gathers are fast (gathers_are_fast()).
void EncodeSrgbRowGathering(const glm::vec4* colors, int count, float scale, std::uint8_t* rgba) {
#if !HWY_ARCH_X86 || HWY_TARGET > HWY_AVX3  // gathers measured faster with AVX-512 only
  EncodeSrgbRow(colors, count, scale, rgba);
#else
  const FloatTag df;
  const IntTag di;
  const auto* run_code = reinterpret_cast<const std::int32_t*>(srgb_tables().run_code.data());
  alignas(64) float factor[kMaxFloatLanes + 4];
  FillFactors(scale, kMaxFloatLanes + 4, factor);
  ForEachVector(&colors[0].x, 4 * count, rgba, [&](const float* from, std::uint8_t* to, int j) {
    const auto c = Clamped(hn::Mul(hn::LoadU(df, from), hn::LoadU(df, factor + (j & 3))));
    const auto above = BitsAbove(c);
    // Alpha's lanes gather too: their runs are as valid, their entries unused.
    const auto entry = hn::GatherIndex(di, run_code, hn::ShiftRight<Tables::kRunBits>(above));
    StoreBytes(Codes(entry, above, Rounded(c), j), to);
  });
#endif
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
HWY_EXPORT(EncodeSrgbRowGathering);
HWY_EXPORT(RoundUnorm8Row);

namespace {

// Whether the CPU is AMD's ("AuthenticAMD"), by the vendor string of CPUID leaf 0.
bool cpu_is_amd() {
#if defined(__x86_64__) || defined(__i386__)
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (__get_cpuid(0, &eax, &ebx, &ecx, &edx) == 0) return false;
  char vendor[12];
  std::memcpy(vendor, &ebx, 4), std::memcpy(vendor + 4, &edx, 4), std::memcpy(vendor + 8, &ecx, 4);
  return std::memcmp(vendor, "AuthenticAMD", 12) == 0;
#else
  return false;
#endif
}

}  // namespace

bool gathers_are_fast() {
  // Intel's AVX-512 gathers beat a load per lane unless the microcode mitigates Gather Data
  // Sampling (Skylake to Tiger Lake), which makes them several times slower; the kernel says.
  // AMD's (Zen 4) are microcoded: a load per lane measured faster there.
  static const bool fast = [] {
    if ((hwy::SupportedTargets() & HWY_AVX3) == 0 || cpu_is_amd()) return false;
    std::ifstream status("/sys/devices/system/cpu/vulnerabilities/gather_data_sampling");
    std::string text;
    return std::getline(status, text) && text.rfind("Not affected", 0) == 0;
  }();
  return fast;
}

EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target, bool gathering) {
  return gathering ? HWY_DISPATCH_TABLE(EncodeSrgbRowGathering)[target]
                   : HWY_DISPATCH_TABLE(EncodeSrgbRow)[target];
}

EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target) {
  return encode_srgb_row_kernel(target, gathers_are_fast());
}

RoundUnorm8RowKernel round_unorm8_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(RoundUnorm8Row)[target];
}

}  // namespace facet::shading
#endif  // HWY_ONCE
