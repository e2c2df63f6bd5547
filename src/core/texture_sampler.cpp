// Texture lookups at given levels of detail (see texture_sampler.hpp). Highway compiles this file
// once per SIMD target (foreach_target.h re-includes it).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/texture_sampler.cpp"
#include "core/texture_sampler.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <utility>

#include "core/texture_sample-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::sampling::HWY_NAMESPACE {

void SampleAt(const Texture& texture, const Sampler& sampler, const float* u, const float* v,
              const float* lod, int count, float (*rgba)[4]) {
  const FloatTag df;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const Source src = SourceOf(texture, sampler);
  const FloatV top = hn::Set(df, static_cast<float>(texture.level_count() - 1));
  // Up to kMaxPixels lookups at a time, copied to arrays of whole vectors (zeros after them).
  alignas(32) float us[kMaxPixels], vs[kMaxPixels], lods[kMaxPixels];
  alignas(32) std::int32_t level[kMaxPixels];
  alignas(32) float fraction[kMaxPixels];
  for (int first = 0; first < count; first += kMaxPixels) {
    const int n = std::min(kMaxPixels, count - first);
    const int whole = (n + lanes - 1) / lanes * lanes;
    std::fill(std::copy_n(u + first, n, us), us + whole, 0.0f);
    std::fill(std::copy_n(v + first, n, vs), vs + whole, 0.0f);
    if (sampler.filter == Filter::trilinear) {
      std::fill(std::copy_n(lod + first, n, lods), lods + whole, 0.0f);
      for (int j = 0; j < n; j += lanes)
        StoreLevel(hn::Load(df, lods + j), top, level, fraction, j);
    }
    auto coords = [&](int j) HWY_ATTR {
      return std::pair{hn::Load(df, us + j), hn::Load(df, vs + j)};
    };
    SamplePixels(src, sampler.filter, coords, level, fraction, n, rgba + first);
  }
}

}  // namespace facet::sampling::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet {
namespace sampling {
HWY_EXPORT(SampleAt);
}  // namespace sampling

SampleAtKernel sample_at_kernel(SimdTarget target) {
  return sampling::HWY_DISPATCH_TABLE(SampleAt)[target];
}

}  // namespace facet
#endif  // HWY_ONCE
