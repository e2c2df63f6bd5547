// facet's own log2, exp and pow (shading/portable_math.hpp), which the scalar and SIMD shading
// share so that both give the same bits on every CPU: they must be the functions they stand for.
#include "core/portable_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace facet::test {
namespace {

using shading::lod_log2;
using shading::portable_exp;
using shading::portable_log2;
using shading::portable_pow;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(PortableMath, Log2IsWithinAMillionth) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> exponent(-140.0f, 127.0f);
  for (int i = 0; i < 200000; ++i) {
    const float x = std::exp2(exponent(rng));
    if (x == 0.0f) continue;
    const double exact = std::log2(static_cast<double>(x));
    ASSERT_NEAR(portable_log2(x), exact, 1e-6 * std::max(1.0, std::abs(exact))) << "x = " << x;
  }
  for (float x : {1.0f, 2.0f, 0.5f, 1024.0f}) EXPECT_EQ(portable_log2(x), std::log2(x));
}

TEST(PortableMath, Log2OfSpecialValues) {
  EXPECT_EQ(portable_log2(0.0f), -kInf);
  EXPECT_EQ(portable_log2(kInf), kInf);
  EXPECT_TRUE(std::isnan(portable_log2(-1.0f)));
  EXPECT_TRUE(std::isnan(portable_log2(kNaN)));
  EXPECT_NEAR(portable_log2(std::numeric_limits<float>::denorm_min()), -149.0, 1e-4);
}

TEST(PortableMath, LodLog2IsWithinAThousandthOfALevel) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> exponent(-125.0f, 127.0f);
  for (int i = 0; i < 200000; ++i) {
    const float x = std::exp2(exponent(rng));
    ASSERT_NEAR(lod_log2(x), std::log2(static_cast<double>(x)), 1e-3) << "x = " << x;
  }
  // Increasing, also across the octaves where the polynomial restarts.
  for (int e = -20; e <= 20; ++e) {
    const float power = std::ldexp(1.0f, e);
    float previous = lod_log2(std::nextafter(power, 0.0f) * 0.999f);
    for (float x = std::nextafter(power, 0.0f) * 0.999f; x < power * 1.001f;
         x = std::nextafter(x, power * 2.0f)) {
      ASSERT_GE(lod_log2(x), previous) << "x = " << x;
      previous = lod_log2(x);
    }
    EXPECT_EQ(lod_log2(power), static_cast<float>(e));
  }
}

// The batch sampler takes a footprint of at most one texel (rho^2 <= 1) as magnified without
// the logarithm (texel_batch.cpp): lod_log2 must not be above 0 there. Below 1/2 it is about
// -2 + log2(m) <= -1; in [1/2, 1] every float is checked.
TEST(PortableMath, LodLog2IsNotPositiveUpToOne) {
  for (float x = 0.5f; x <= 1.0f; x = std::nextafter(x, 2.0f)) {
    ASSERT_LE(lod_log2(x), 0.0f) << "x = " << x;
  }
  for (float x = 1e-30f; x < 0.5f; x *= 1.001f) ASSERT_LT(lod_log2(x), -0.99f) << "x = " << x;
}

TEST(PortableMath, LodLog2OfSpecialValues) {
  EXPECT_EQ(lod_log2(0.0f), -kInf);
  EXPECT_EQ(lod_log2(kInf), kInf);
  EXPECT_TRUE(std::isnan(lod_log2(-1.0f)));
  EXPECT_TRUE(std::isnan(lod_log2(kNaN)));
  // Subnormals: far below level 0, which is all the level of detail needs.
  EXPECT_LT(lod_log2(std::numeric_limits<float>::denorm_min()), -126.0f);
}

TEST(PortableMath, ExpIsExpToFloatPrecision) {
  for (float x = -87.0f; x <= 88.0f; x += 0.0137f) {
    // x log2(e) rounds to float first: the error grows with |x| (2^-24 |x log2 e| ln 2).
    const double exact = std::exp(static_cast<double>(x));
    ASSERT_NEAR(portable_exp(x), exact, (2e-7 + 1e-7 * std::abs(x)) * exact) << "x = " << x;
  }
  EXPECT_EQ(portable_exp(0.0f), 1.0f);
  EXPECT_EQ(portable_exp(-1000.0f), 0.0f);
  EXPECT_EQ(portable_exp(1000.0f), kInf);
  EXPECT_TRUE(std::isnan(portable_exp(kNaN)));
}

TEST(PortableMath, PowIsPowForHighlights) {
  // Whole exponents by repeated squaring: each product's rounding (2^-24 relative) doubles with
  // each squaring after it, so within about s 2^-24 relative. Others through log2 and exp2.
  for (float s : {1.0f, 2.0f, 7.0f, 8.0f, 32.0f, 48.0f, 100.0f, 256.0f, 1000.0f, 65536.0f}) {
    for (float x = 0.0f; x <= 1.0f; x += 0.001f) {
      const double exact = std::pow(static_cast<double>(x), static_cast<double>(s));
      // Relative 2 s 2^-24, or absolutely tiny where the result underflows the normal range.
      ASSERT_NEAR(portable_pow(x, s), exact, 1.2e-7 * s * exact + 1e-37) << x << "^" << s;
    }
  }
  for (float s : {0.5f, 1.5f, 12.8f, 33.3f, 100.5f, 65537.0f}) {
    for (float x = 0.0f; x <= 1.0f; x += 0.001f) {
      const double exact = std::pow(static_cast<double>(x), static_cast<double>(s));
      ASSERT_NEAR(portable_pow(x, s), exact, 2e-6 * s * exact + 1e-37) << x << "^" << s;
    }
  }
  EXPECT_EQ(portable_pow(0.0f, 32.0f), 0.0f);
  EXPECT_EQ(portable_pow(1.0f, 32.0f), 1.0f);
  EXPECT_EQ(portable_pow(0.0f, 0.0f), 1.0f);
  EXPECT_EQ(portable_pow(0.3f, 0.0f), 1.0f);
  EXPECT_TRUE(std::isnan(portable_pow(kNaN, 4.0f)));
}

}  // namespace
}  // namespace facet::test
