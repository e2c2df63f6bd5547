// The SIMD target Highway has chosen, for kernels fetched as plain function pointers
// (raster_kernels, setup_batch_kernel, cull_kernel): a caller fetches its kernel once and calls
// it for many triangles, where HWY_DYNAMIC_DISPATCH would ask libhwy on every call.
#pragma once

#include <hwy/targets.h>

#include <cstddef>

namespace facet::pipeline {

// The chosen target's index into an HWY_DISPATCH_TABLE: what HWY_DYNAMIC_DISPATCH would call.
// Until a target is chosen (at the first dispatch, and again after a test forces one), the
// tables lead to a function that chooses one on every call: choose it here, as that function
// does.
inline std::size_t chosen_target_index() {
  hwy::ChosenTarget& chosen = hwy::GetChosenTarget();
  if (!chosen.IsInitialized()) chosen.Update(hwy::SupportedTargets());
  return chosen.GetIndex();
}

}  // namespace facet::pipeline
