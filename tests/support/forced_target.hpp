// Forces one Highway SIMD target for a scope, for tests that compare every target the machine
// supports (simd_targets_test, texel_batch_test, shade_batch_test, vertex_batch_test).
#pragma once

#include <hwy/targets.h>

#include <cstdint>
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

}  // namespace facet::test
