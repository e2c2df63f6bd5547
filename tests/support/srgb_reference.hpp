// The 8-bit encodes written out one value at a time, for tests: the sRGB encode by its lines
// (core/color.hpp), the exact encode it approximates, and the plain rounding of alpha and display
// values. srgb_row_test compares the row kernels (core/srgb_row.cpp) with them on every target
// and holds the lines to the exact encode; the library encodes through the row kernels alone.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

#include "core/color.hpp"

namespace facet::test {

// The encode's line (color.hpp) at linear [0, 1] (clamped to [2^-13, the float below 1]; NaN
// -> 2^-13): the code plus 0.5, in 1/65536 codes.
inline std::uint32_t srgb_line_value(const shading::SrgbTables& tables, float linear) {
  using Tables = shading::SrgbTables;
  const float base = std::bit_cast<float>(Tables::kEncodeBase);
  const float top = std::bit_cast<float>(Tables::kEncodeTop);
  const float clamped = linear > base ? std::min(linear, top) : base;  // NaN fails
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(clamped);
  const std::uint32_t line = tables.encode_lines[Tables::line_entry(bits)];
  const std::uint32_t t = (bits >> Tables::kEncodePointShift) & 0xFF;
  return (line >> 16) * 512 + (line & 0xFFFF) * t;
}

// Encodes linear [0, 1] (NaN -> 0) to an 8-bit sRGB code by the encode's line for the value.
inline std::uint8_t encode_srgb8(const shading::SrgbTables& tables, float linear) {
  return static_cast<std::uint8_t>(srgb_line_value(tables, linear) >> 16);
}
inline std::uint8_t encode_srgb8(float linear) {
  return encode_srgb8(shading::srgb_tables(), linear);
}

// The exact encode: the largest code whose threshold is at most the value, which is
// round(linear_to_srgb(v) * 255) (v clamped to [0, 1]; NaN -> 0).
inline std::uint8_t exact_srgb8(float linear) {
  const shading::SrgbTables& tables = shading::srgb_tables();
  if (!(linear > 0.0f)) return 0;
  const float* after =
      std::upper_bound(tables.thresholds.begin() + 1, tables.thresholds.begin() + 256, linear);
  return static_cast<std::uint8_t>(after - tables.thresholds.begin() - 1);
}

// A value clamped to [0, 1] (NaN -> 0) and rounded to an 8-bit code: v * 255 + 0.5, truncated,
// a multiplication then an addition (not fused).
inline std::uint8_t encode_unorm8(float v) {
  const float unit = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
  return static_cast<std::uint8_t>(unit * 255.0f + 0.5f);
}

}  // namespace facet::test
