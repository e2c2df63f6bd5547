// Color-space helpers: sRGB <-> linear conversion (IEC 61966-2-1), used by resolve and tests.
#pragma once

#include <cmath>
#include <cstdint>

namespace facet::shading {

inline float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline float linear_to_srgb(float c) {
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Encodes linear [0, 1] (clamped; NaN -> 0) to an 8-bit sRGB value through a table exact to
// the nearest 8-bit step: the table holds, per output code, the linear threshold where the
// code begins, and a binary search finds the code. Used once per pixel at resolve.
std::uint8_t encode_srgb8(float linear);

// Decodes an 8-bit sRGB code to linear (table lookup).
float decode_srgb8(std::uint8_t code);

}  // namespace facet::shading
