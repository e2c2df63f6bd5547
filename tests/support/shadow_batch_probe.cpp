// The SIMD shadow lookup for every target (see shadow_batch_probe.hpp). Highway compiles this
// file once per target (foreach_target.h re-includes it), as the library's batch kernels.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "support/shadow_batch_probe.cpp"
#include "support/shadow_batch_probe.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

#include "shading/batch_math-inl.h"
#include "shading/shadow_batch-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void ShadowVisibilityProbe(const ShadowMaps& maps, const glm::vec3* points,
                           const glm::vec3* normals, int count, float* visibility) {
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  for (int j = 0; j < count; j += lanes) {
    const int live = std::min(lanes, count - j);
    // The lanes past the points: zeros, looked up by no one.
    alignas(64) float p[3][8] = {}, n[3][8] = {}, out[8];
    for (int lane = 0; lane < live; ++lane) {
      for (int c = 0; c < 3; ++c)
        p[c][lane] = points[j + lane][c], n[c][lane] = normals[j + lane][c];
    }
    const Vec3V pv{hn::Load(d, p[0]), hn::Load(d, p[1]), hn::Load(d, p[2])};
    const Vec3V nv{hn::Load(d, n[0]), hn::Load(d, n[1]), hn::Load(d, n[2])};
    hn::Store(ShadowVisibility(maps, pv, nv, hn::FirstN(d, static_cast<std::size_t>(live))), d,
              out);
    std::memcpy(visibility + j, out, sizeof(float) * live);
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {
HWY_EXPORT(ShadowVisibilityProbe);
}  // namespace facet::shading

namespace facet::test {

void shadow_visibility_batch(SimdTarget target, const shading::ShadowMaps& maps,
                             const glm::vec3* points, const glm::vec3* normals, int count,
                             float* visibility) {
  using namespace shading;  // where the table is
  HWY_DISPATCH_TABLE(ShadowVisibilityProbe)[target](maps, points, normals, count, visibility);
}

}  // namespace facet::test
#endif  // HWY_ONCE
