// Color-space helpers: sRGB <-> linear conversion (IEC 61966-2-1), the 8-bit decode and the
// tables of the 8-bit encode (core/srgb_row.hpp encodes with them, a row at a time).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace facet::shading {

inline float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline float linear_to_srgb(float c) {
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// thresholds[i] = linear value at which code i begins (the midpoint between codes i-1 and i in
// sRGB space, decoded): the exact encode is "the largest i with thresholds[i] <= linear", which
// equals round(linear_to_srgb(linear) * 255).
//
// The library's encode (core/srgb_row.cpp) approximates it by lines, one per eighth of an octave
// of [2^-13, 1): the value is clamped to [2^-13, the float below 1] (NaN to 2^-13, whose code is
// 0), its bits shifted right by 20 pick the line (its entry: those bits modulo 128), and the
// next 8 bits of its mantissa, t, the point on it: code = ((line >> 16) * 512 + (line & 0xFFFF)
// * t) >> 16, one multiply-add of the line's 16-bit halves with (512, t) in SIMD. Each
// line is its eighth's chord of the exact curve, moved to split the curve's largest distances
// above and below it evenly, plus 0.5 so that the shift rounds. The lines stay within 0.07 of a
// code of the curve, so a code is at most one from the exact one, and mostly equal to it
// (srgb_row_test's SrgbLines tests hold them to both). Integers only, so the same bytes on every
// target, and a table of 104 entries that AVX-512 reads from registers.
struct SrgbTables {
  std::array<float, 257> thresholds;  // [256] is a sentinel above every input
  std::array<float, 256> decode;

  static constexpr std::uint32_t kEncodeBase = 0x39000000;  // the bits of 2^-13
  static constexpr std::uint32_t kEncodeTop = 0x3F7FFFFF;   // the float below 1
  static constexpr int kEncodeLineShift = 20;   // the line: bits above an eighth of an octave
  static constexpr int kEncodePointShift = 12;  // t: the 8 bits below the line's
  static constexpr int kEncodeLines = ((kEncodeTop - kEncodeBase) >> kEncodeLineShift) + 1;
  // The entry of a value's line: (bits >> kEncodeLineShift) % kEncodeEntries, the exponent and
  // top mantissa bits wrapped, which AVX-512's permutes read without a subtraction. The first
  // line's (2^-13) is kEncodeFirstEntry.
  static constexpr int kEncodeEntries = 128;
  static constexpr int kEncodeFirstEntry = (kEncodeBase >> kEncodeLineShift) % kEncodeEntries;
  static_assert(kEncodeFirstEntry + kEncodeLines <= kEncodeEntries);
  static constexpr int line_entry(std::uint32_t bits) {
    return static_cast<int>((bits >> kEncodeLineShift) % kEncodeEntries);
  }
  // Each line: (its value at t = 0, plus 0.5, in 1/128 codes) << 16 | (its slope per t, in
  // 1/65536 codes); both below 2^15, so positive as signed 16-bit halves. Zero outside the
  // lines' entries: the vectors that hold them are read whole.
  alignas(64) std::array<std::uint32_t, kEncodeEntries> encode_lines;

  SrgbTables();
};

// Built during static initialisation, before main(); nothing reads it earlier (textures and
// the missing-texture checker are built lazily).
extern const SrgbTables kSrgbTables;
inline const SrgbTables& srgb_tables() { return kSrgbTables; }

// 1 / 255: an 8-bit code c as the value c * kInverse255 in [0, 1], which the 8-bit rounding
// (core/srgb_row.hpp's round_unorm8_row_kernel) turns back into c.
inline constexpr float kInverse255 = 1.0f / 255.0f;

// Decodes an 8-bit sRGB code to linear.
inline float decode_srgb8(std::uint8_t code) { return kSrgbTables.decode[code]; }

}  // namespace facet::shading
