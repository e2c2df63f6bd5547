// The SIMD target Highway has chosen, as an index into every kernel's HWY_DISPATCH_TABLE. One
// convention for every kernel: the frame reads the target once (pipeline/kernels.hpp) and
// fetches each kernel's pointer for it, so no call asks libhwy which target to run, and a
// target a test forces between frames is followed from the next frame on.
#pragma once

#include <hwy/targets.h>

#include <cstddef>

namespace facet {

using SimdTarget = std::size_t;

// What HWY_DYNAMIC_DISPATCH would call now. Until a target is chosen (at the first dispatch,
// and again after a test forces one), the tables lead to a function that chooses one on every
// call: choose it here, as that function does.
inline SimdTarget chosen_simd_target() {
  hwy::ChosenTarget& chosen = hwy::GetChosenTarget();
  if (!chosen.IsInitialized()) chosen.Update(hwy::SupportedTargets());
  return chosen.GetIndex();
}

}  // namespace facet
