// The procedural sky for an array of directions (see sky_batch.hpp). Highway compiles this file
// once per SIMD target; the caller fetches the chosen target's kernel (core/simd_target.hpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/sky_batch.cpp"
#include "shading/sky_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>

#include "shading/sky_gradient-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void SkyBatch(const Environment& environment, const float* up, int count, glm::vec3* radiance) {
  const hn::CappedTag<float, 8> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  for (int i = 0; i < count; i += lanes) {
    // Lanes past count (in the last vector) take an up of zero and are not stored.
    alignas(32) float padded_up[8] = {};
    const int active = std::min(lanes, count - i);
    std::copy_n(up + i, active, padded_up);
    hn::Vec<decltype(d)> rgb[3];
    SkyRadiance(d, environment, hn::Load(d, padded_up), rgb);
    alignas(32) float out[3][8];
    for (int c = 0; c < 3; ++c) hn::Store(rgb[c], d, out[c]);
    for (int k = 0; k < active; ++k) radiance[i + k] = {out[0][k], out[1][k], out[2][k]};
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(SkyBatch);

SkyBatchKernel sky_batch_kernel(SimdTarget target) { return HWY_DISPATCH_TABLE(SkyBatch)[target]; }

}  // namespace facet::shading
#endif  // HWY_ONCE
