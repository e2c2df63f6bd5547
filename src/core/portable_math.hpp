// log2, exp2, exp and pow built from IEEE basic operations only (bit manipulation, floor, +, -,
// *, / and no fused multiply-add), so that the scalar shading code and every SIMD target of the
// batch code (texel_batch.cpp, shade_batch.cpp repeat these steps lane by lane) compute the
// same bits on every CPU. glibc's log2f, expf and powf pick their implementation per CPU (FMA
// or not), and a libm call per pixel is dear in the shading loops.
//   lod_log2       texture level of detail      portable_exp  exponential fog
//   portable_pow   specular highlights (x^s for x >= 0: by repeated squaring for a whole s,
//                  else through portable_log2)
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace facet::shading {

namespace portable_math {
// log2: 2 / ln 2 times 1, 1/3, 1/5, 1/7: log2(m) = 2/ln2 * atanh(s), s = (m - 1) / (m + 1).
inline constexpr float kSqrt2 = 1.41421356f;
inline constexpr float kLog2C1 = 2.88539008f;
inline constexpr float kLog2C3 = 0.961796693f;
inline constexpr float kLog2C5 = 0.577078016f;
inline constexpr float kLog2C7 = 0.412198583f;
inline constexpr float kSmallestNormal = 1.17549435e-38f;
inline constexpr float kTwoTo23 = 8388608.0f;
// exp2: ln(2)^k / k!, 2^f = e^(f ln 2) as its Taylor series, for f in [-0.5, 0.5].
inline constexpr float kExp2C1 = 0.693147182f;
inline constexpr float kExp2C2 = 0.240226507f;
inline constexpr float kExp2C3 = 0.0555041087f;
inline constexpr float kExp2C4 = 0.00961812911f;
inline constexpr float kExp2C5 = 0.00133335581f;
inline constexpr float kExp2C6 = 0.000154035304f;
inline constexpr float kExp2C7 = 1.52527338e-05f;
inline constexpr float kExp2Lowest = -126.5f;  // below: 0 (subnormal results are not needed)
inline constexpr float kExp2Highest = 127.5f;  // from here: +inf
inline constexpr float kLog2E = 1.44269504f;
// lod_log2: log2(1 + f) for f in [0, 1) as f (c1 + f (c2 + f c3)), fitted for the smallest
// largest error with c1 + c2 + c3 = 1 (so octaves join); increasing on [0, 1].
inline constexpr float kLodLog2C1 = 1.42286066f;
inline constexpr float kLodLog2C2 = -0.582073628f;
inline constexpr float kLodLog2C3 = 0.15921297f;
}  // namespace portable_math

// log2 where x is not positive and finite: -inf for 0, +inf for +inf, NaN for NaN and negative x.
inline float log2_special(float x) {
  if (x == std::numeric_limits<float>::infinity()) return x;
  return x == 0.0f ? -std::numeric_limits<float>::infinity()
                   : std::numeric_limits<float>::quiet_NaN();
}

// log2(x) to within 1e-6 for every positive normal or subnormal x; -inf for 0, +inf for +inf,
// NaN for NaN and negative x. Reduction: x = m * 2^e with m in [sqrt(1/2), sqrt(2)), then
// |s| <= 0.1716, where the atanh series to s^7 leaves an error below 5e-8.
inline float portable_log2(float x) {
  using namespace portable_math;
  if (!(x > 0.0f) || x == std::numeric_limits<float>::infinity()) return log2_special(x);
  float bias = 127.0f;
  if (x < kSmallestNormal) {  // subnormal: scale into the normal range first (exact)
    x *= kTwoTo23;
    bias = 150.0f;
  }
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  float e = static_cast<float>(static_cast<std::int32_t>(bits >> 23)) - bias;
  float m = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);  // [1, 2)
  if (m > kSqrt2) {
    m *= 0.5f;  // exact
    e += 1.0f;
  }
  const float s = (m - 1.0f) / (m + 1.0f);
  const float s2 = s * s;
  return e + s * (kLog2C1 + s2 * (kLog2C3 + s2 * (kLog2C5 + s2 * kLog2C7)));
}

// log2(x) to within 0.001 for positive normal x, for the texture level of detail: a thousandth
// of a mip level is far below what shows, and without portable_log2's division and range
// reduction the batch sampler's level of detail is much cheaper. Subnormal x give about
// -127 (far below level 0 all the same); -inf for 0, +inf for +inf, NaN for NaN and negative x.
inline float lod_log2(float x) {
  using namespace portable_math;
  if (!(x > 0.0f) || x == std::numeric_limits<float>::infinity()) return log2_special(x);
  const std::int32_t bits = std::bit_cast<std::int32_t>(x);
  const float e = static_cast<float>((bits >> 23) - 127);
  const float f = std::bit_cast<float>((bits & 0x007fffff) | 0x3f800000) - 1.0f;  // [0, 1)
  return e + f * (kLodLog2C1 + f * (kLodLog2C2 + f * kLodLog2C3));
}

// 2^t to within 2e-7 relative for results in the normal range; 0 below it, +inf above, NaN
// for NaN. Reduction: t = n + f with n whole and |f| <= 0.5; 2^n is built in the exponent bits.
inline float portable_exp2(float t) {
  using namespace portable_math;
  if (!(t >= kExp2Lowest)) return t < kExp2Lowest ? 0.0f : t;  // NaN stays NaN
  if (t >= kExp2Highest) return std::numeric_limits<float>::infinity();
  const float n = std::floor(t + 0.5f);
  const float f = t - n;
  const float p =
      1.0f +
      f * (kExp2C1 +
           f * (kExp2C2 +
                f * (kExp2C3 + f * (kExp2C4 + f * (kExp2C5 + f * (kExp2C6 + f * kExp2C7))))));
  return p * std::bit_cast<float>(static_cast<std::uint32_t>(static_cast<int>(n) + 127) << 23);
}

// e^x = 2^(x log2 e): within (2e-7 + 1e-7 |x|) relative (x log2 e is rounded to float first).
inline float portable_exp(float x) { return portable_exp2(x * portable_math::kLog2E); }

namespace portable_math {
// The exponents portable_pow takes by repeated squaring: whole numbers from 1 to 2^16.
inline bool is_whole_power(float s) { return s >= 1.0f && s <= 65536.0f && s == std::floor(s); }
}  // namespace portable_math

// x^s for x >= 0 (NaN stays NaN) and s >= 0; x^0 = 1. A whole s (is_whole_power: the common
// shininesses) by repeated squaring, lowest bit of s first: within about 1.2e-7 s relative (each
// squaring doubles the error before it); otherwise as 2^(s log2 x), within about 1e-6 s. Either
// is invisible in an 8-bit highlight.
inline float portable_pow(float x, float s) {
  if (s == 0.0f) return 1.0f;
  if (portable_math::is_whole_power(s)) {
    auto n = static_cast<std::uint32_t>(s);
    float power = x;  // x^(2^k), k the bit of n looked at
    while ((n & 1u) == 0) n >>= 1, power *= power;
    float result = power;
    for (n >>= 1; n != 0; n >>= 1) {
      power *= power;
      if (n & 1u) result *= power;
    }
    return result;
  }
  return portable_exp2(s * portable_log2(x));
}

}  // namespace facet::shading
