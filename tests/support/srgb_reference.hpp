// The 8-bit encodes written out one value at a time, for tests: the sRGB encode from its tables
// (core/color.hpp) and the plain rounding of alpha and display values. srgb_row_test compares
// the row kernels (core/srgb_row.cpp) with them on every target, and texture_test holds the
// sRGB one to the definition, round(linear_to_srgb(v) * 255). The library encodes through the
// row kernels alone.
#pragma once

#include <bit>
#include <cstdint>

#include "core/color.hpp"

namespace facet::test {

// Encodes linear [0, 1] (clamped; NaN -> 0) to an 8-bit sRGB code: the largest code whose
// threshold is at most the value, by one lookup of its run and one comparison (color.hpp).
inline std::uint8_t encode_srgb8(const shading::SrgbTables& t, float linear) {
  using Tables = shading::SrgbTables;
  if (!(linear > 0.0f)) return 0;  // also catches NaN
  if (linear >= 1.0f) return 255;
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(linear);
  const std::uint32_t above = bits > Tables::kRunBase ? bits - Tables::kRunBase : 0;
  const std::uint32_t entry = t.run_code[above >> Tables::kRunBits];
  const bool next = (above & Tables::kRunMask) >= (entry & Tables::kRunOffsetMask);
  return static_cast<std::uint8_t>((entry >> Tables::kRunCodeShift) + next);
}
inline std::uint8_t encode_srgb8(float linear) {
  return encode_srgb8(shading::srgb_tables(), linear);
}

// A value clamped to [0, 1] (NaN -> 0) and rounded to an 8-bit code: v * 255 + 0.5, truncated,
// a multiplication then an addition (not fused).
inline std::uint8_t encode_unorm8(float v) {
  const float unit = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
  return static_cast<std::uint8_t>(unit * 255.0f + 0.5f);
}

}  // namespace facet::test
