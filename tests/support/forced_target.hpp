// Forces one Highway SIMD target for a scope, for tests that compare every target the machine
// supports (simd_targets_test, texel_batch_test, shade_batch_test, vertex_batch_test).
#pragma once

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace facet::test {

// Forces one target for the scope's lifetime, then gives the choice back to the CPU (also
// when a failed assertion leaves the scope early).
class ForcedTarget {
 public:
  explicit ForcedTarget(std::int64_t target) { hwy::SetSupportedTargetsForTest(target); }
  ~ForcedTarget() { hwy::SetSupportedTargetsForTest(0); }
  ForcedTarget(const ForcedTarget&) = delete;
  ForcedTarget& operator=(const ForcedTarget&) = delete;
};

// Every target this machine can run that the build compiled, best first.
inline std::vector<std::int64_t> simd_targets() { return hwy::SupportedAndGeneratedTargets(); }

// The portable target among them (HWY_EMU128 or HWY_SCALAR: plain C++, a lane at a time), which
// tests of kernels with no scalar twin compare the others with; 0 if the build has none.
inline std::int64_t portable_simd_target() {
  for (std::int64_t target : simd_targets()) {
    if (target == HWY_EMU128 || target == HWY_SCALAR) return target;
  }
  return 0;
}

// Calls fill(out) with the portable target forced, then with each other target, and expects
// entries 0 to count - 1 of out's first `rows` rows (out[row][entry]) bit for bit the portable
// target's. fill fetches the forced target's kernels itself (chosen_simd_target()). Returns how
// many entries it compared; `context` names the case in a failure.
template <int kEntries, class Fill>
int expect_rows_alike_on_every_target(int rows, int count, Fill&& fill,
                                      const std::string& context) {
  const std::int64_t portable = portable_simd_target();
  alignas(64) float expected[32][kEntries];
  alignas(64) float out[32][kEntries];
  if (rows > 32 || portable == 0) {
    ADD_FAILURE() << "no portable target, or more than 32 rows";
    return 0;
  }
  {
    ForcedTarget forced(portable);
    fill(expected);
  }
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    if (target == portable) continue;
    ForcedTarget forced(target);
    std::fill_n(&out[0][0], 32 * kEntries, std::numeric_limits<float>::quiet_NaN());
    fill(out);
    for (int n = 0; n < count; ++n) {
      for (int k = 0; k < rows; ++k) {
        if (std::memcmp(&expected[k][n], &out[k][n], sizeof(float)) != 0) {
          ADD_FAILURE() << hwy::TargetName(target) << ", " << context << ", entry " << n << ", row "
                        << k << ": " << out[k][n] << ", " << hwy::TargetName(portable) << " gives "
                        << expected[k][n];
          return compared;
        }
      }
      ++compared;
    }
  }
  return compared;
}

}  // namespace facet::test
