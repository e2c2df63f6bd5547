// log2 for the texture level of detail, built from IEEE basic operations only (bit
// manipulation, +, -, *, / and no fused multiply-add), so that the scalar sampler and every
// SIMD target of the batch sampler (texel_batch.cpp, which repeats these steps lane by lane)
// compute the same bits on every CPU. glibc's log2f picks its implementation per CPU, and a
// libm call per pixel was a fifth of a trilinear-textured frame.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace facet::shading {

// The constants, shared with the SIMD version.
namespace lod_log2_constants {
inline constexpr float kSqrt2 = 1.41421356f;
// 2 / ln 2 times 1, 1/3, 1/5, 1/7: log2(m) = 2/ln2 * atanh(s), s = (m - 1) / (m + 1).
inline constexpr float kC1 = 2.88539008f;
inline constexpr float kC3 = 0.961796693f;
inline constexpr float kC5 = 0.577078016f;
inline constexpr float kC7 = 0.412198583f;
inline constexpr float kSmallestNormal = 1.17549435e-38f;
inline constexpr float kTwoTo23 = 8388608.0f;
}  // namespace lod_log2_constants

// log2(x) to within 1e-6 for every positive normal or subnormal x; -inf for 0, +inf for +inf,
// NaN for NaN and negative x. Reduction: x = m * 2^e with m in [sqrt(1/2), sqrt(2)), then
// |s| <= 0.1716, where the atanh series to s^7 leaves an error below 5e-8.
inline float lod_log2(float x) {
  using namespace lod_log2_constants;
  if (!(x > 0.0f)) {
    return x == 0.0f ? -std::numeric_limits<float>::infinity()
                     : std::numeric_limits<float>::quiet_NaN();
  }
  if (x == std::numeric_limits<float>::infinity()) return x;
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
  return e + s * (kC1 + s2 * (kC3 + s2 * (kC5 + s2 * kC7)));
}

}  // namespace facet::shading
