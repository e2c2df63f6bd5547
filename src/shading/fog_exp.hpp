// e^x for exponential fog, built from IEEE basic operations only (floor, +, -, *, bit
// manipulation; no fused multiply-add), so that the scalar fog and the SIMD batch shader
// (shade_batch.cpp, which repeats these steps lane by lane) compute the same bits on every CPU.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace facet::shading {

namespace fog_exp_constants {
inline constexpr float kLog2E = 1.44269504f;
// ln(2)^k / k!: 2^f = e^(f ln 2) as its Taylor series, for f in [-0.5, 0.5].
inline constexpr float kC1 = 0.693147182f;
inline constexpr float kC2 = 0.240226507f;
inline constexpr float kC3 = 0.0555041087f;
inline constexpr float kC4 = 0.00961812911f;
inline constexpr float kC5 = 0.00133335581f;
inline constexpr float kC6 = 0.000154035304f;
inline constexpr float kC7 = 1.52527338e-05f;
inline constexpr float kLowest = -126.5f;  // below: 0 (subnormal results are not needed)
inline constexpr float kHighest = 127.5f;  // from here: +inf
}  // namespace fog_exp_constants

// e^x to within (2e-7 + 1e-7 |x|) relative for results in the normal range (x log2 e is
// rounded to float first); 0 below it, +inf above, NaN for NaN. Reduction: x log2(e) = n + f with n
// whole and |f| <= 0.5; 2^n is built in the exponent bits.
inline float fog_exp(float x) {
  using namespace fog_exp_constants;
  const float t = x * kLog2E;
  if (!(t >= kLowest)) return t < kLowest ? 0.0f : t;  // NaN stays NaN
  if (t >= kHighest) return std::numeric_limits<float>::infinity();
  const float n = std::floor(t + 0.5f);
  const float f = t - n;
  const float p =
      1.0f + f * (kC1 + f * (kC2 + f * (kC3 + f * (kC4 + f * (kC5 + f * (kC6 + f * kC7))))));
  const float scale =
      std::bit_cast<float>(static_cast<std::uint32_t>(static_cast<int>(n) + 127) << 23);
  return p * scale;
}

}  // namespace facet::shading
