// The environment seen along a vector of directions, for the shading kernels' reflections and
// image-based light (shade_batch.cpp, pbr_batch-inl.h): the procedural sky with SIMD
// (sky_gradient-inl.h), an image through the texture lookups for all lanes at once (each lane's
// texture coordinates by direction computed one at a time: environment.cpp).
// Included inside each file's HWY_NAMESPACE after batch_math-inl.h, the Highway "-inl.h" way.
#if defined(FACET_SHADING_ENVIRONMENT_BATCH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_ENVIRONMENT_BATCH_INL_H_
#undef FACET_SHADING_ENVIRONMENT_BATCH_INL_H_
#else
#define FACET_SHADING_ENVIRONMENT_BATCH_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>

#include "facet/light.hpp"
#include "shading/batch_math-inl.h"
#include "shading/environment.hpp"
#include "shading/kernels.hpp"
#include "shading/sky_gradient-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The environment's radiance along unit directions `direction`, an image's blurred to mip level
// `lod` (the sky is smooth already) and read with `sample_at`. An image is read for the first
// `count` lanes only; the others' results are not meant to be used.
HWY_INLINE Vec3V EnvironmentRadiance(SampleAtKernel sample_at, const Environment& environment,
                                     const Vec3V& direction, BatchV lod, int count) {
  const BatchTag d;
  if (!environment.image) {
    BatchV rgb[3];
    SkyRadiance(d, environment, direction.y, rgb);
    return {rgb[0], rgb[1], rgb[2]};
  }
  Lanes3 lanes(direction);
  alignas(64) float lanes_lod[8];
  hn::Store(lod, d, lanes_lod);
  count = std::min(count, static_cast<int>(hn::Lanes(d)));
  glm::vec3 directions[8] = {}, radiance[8];
  for (int lane = 0; lane < count; ++lane) directions[lane] = lanes[lane];
  image_radiance(sample_at, environment, directions, lanes_lod, count, radiance);
  for (int lane = 0; lane < count; ++lane) lanes.set(lane, radiance[lane]);
  return lanes.load();
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_ENVIRONMENT_BATCH_INL_H_
