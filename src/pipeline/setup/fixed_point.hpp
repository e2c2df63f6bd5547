// Fixed-point screen coordinates shared by setup (writes them), the rasterizers (read them)
// and the reference rasterizer. All integer widths are argued here, in one place.
#pragma once

#include <cmath>
#include <cstdint>

namespace facet::pipeline {

// 8 sub-pixel bits: vertices snap to 1/256 pixel, as the issue and most GPUs do.
inline constexpr int kSubpixelBits = 8;
inline constexpr std::int32_t kSubpixelScale = 1 << kSubpixelBits;
inline constexpr std::int32_t kHalfPixel = kSubpixelScale / 2;

// Guard band: vertices may lie this many pixels outside the framebuffer before the
// geometry stage clips against the side planes. With a framebuffer of at most 8192 pixels,
// snapped coordinates stay within +-(8192 + 8192) * 256 = +-2^22, so edge coefficients
// (differences) fit in 24 bits and an edge function value a*x + b*y + c fits comfortably in
// 64 bits (2^24 * 2^23 * 3 < 2^50). Evaluation is therefore exact: no rounding anywhere in
// coverage, which is what makes the fast path and the reference path agree bit for bit.
inline constexpr float kGuardBandPixels = 8192.0f;

// Snaps a screen coordinate in pixels to fixed point: round to nearest, ties to even (lrint in
// the default rounding mode: one instruction, where lround is a library call).
inline std::int32_t snap(float pixels) {
  return static_cast<std::int32_t>(std::lrint(pixels * static_cast<float>(kSubpixelScale)));
}

// Fixed-point coordinate of the centre of pixel column/row p: pixel centres are at p + 0.5.
inline std::int64_t pixel_centre(int p) {
  return static_cast<std::int64_t>(p) * kSubpixelScale + kHalfPixel;
}

// floor(a / b) for b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

}  // namespace facet::pipeline
