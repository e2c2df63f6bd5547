// The 8-bit sRGB encode written out one value at a time from its tables (core/color.hpp), for
// tests: srgb_row_test compares the row kernel (core/srgb_row.cpp) with it on every target, and
// texture_test holds it to the definition, round(linear_to_srgb(v) * 255). The library encodes
// through the row kernel alone.
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

}  // namespace facet::test
