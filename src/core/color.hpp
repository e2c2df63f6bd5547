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
// sRGB space, decoded). Encoding is "the largest i with thresholds[i] <= linear", which equals
// round(linear_to_srgb(linear) * 255) without a pow per pixel.
//
// A search per pixel is slow, so a second table slices [2^-14, 1] by the float's bits: each
// run of 2^16 consecutive floats (a 128th of an octave) holds at most one threshold
// (srgb_row_test's SrgbTables test checks it), so a run's entry holds both the code at its
// start and where in the run the next code begins: one lookup and one comparison, still exact.
// Below 2^-14 (run 0, which holds no threshold) every value is code 0. The row encoder
// (core/srgb_row.cpp) is the one that reads these tables.
struct SrgbTables {
  std::array<float, 257> thresholds;  // [256] is a sentinel above every input
  std::array<float, 256> decode;

  static constexpr std::uint32_t kRunBase = 0x38800000;  // the bits of 2^-14
  static constexpr int kRunBits = 16;
  static constexpr std::uint32_t kRunMask = (1u << kRunBits) - 1;
  static constexpr int kRuns = ((0x3F800000 - kRunBase) >> kRunBits) + 1;  // 1.0 starts the last
  static constexpr int kRunCodeShift = kRunBits + 1;
  static constexpr std::uint32_t kRunOffsetMask = (1u << kRunCodeShift) - 1;
  // Run r holds the floats whose bits minus kRunBase are r * 2^16 + (0 ... 2^16 - 1): its
  // entry is (the code at its start) << kRunCodeShift | (the offset in the run of the first
  // float of the next code, or 2^16 when the run holds no threshold).
  std::array<std::uint32_t, kRuns> run_code;

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
