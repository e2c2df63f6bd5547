// The planar reflection's lookup (planar_reflection.hpp) for a vector of surface points, for the
// Phong and PBR batch kernels (shade_batch.cpp, pbr_batch-inl.h). Included inside each file's
// HWY_NAMESPACE after batch_math-inl.h, the Highway "-inl.h" way. Every target computes the same
// IEEE operations in the same order, and the texture lookups are the sampler kernel's, the same
// bits on every target.
#if defined(FACET_SHADING_PLANAR_REFLECTION_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_PLANAR_REFLECTION_INL_H_
#undef FACET_SHADING_PLANAR_REFLECTION_INL_H_
#else
#define FACET_SHADING_PLANAR_REFLECTION_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>

#include "core/texture_sampler.hpp"
#include "shading/batch_math-inl.h"
#include "shading/planar_reflection.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The level of detail of surfaces of roughness alpha (PlanarReflection::blur_texels).
HWY_INLINE BatchV ReflectionLod(const PlanarReflection& r, BatchV alpha) {
  const BatchTag d;
  return LodLog2(hn::Add(hn::Set(d, 1.0f), hn::Mul(alpha, hn::Set(d, r.blur_texels))));
}

// The reflection's radiance seen at world points `position`, read at level of detail `lod`, for
// the first `count` lanes; the others' results are not meant to be used.
HWY_INLINE Vec3V PlanarReflectionRadiance(SampleAtKernel sample_at, const PlanarReflection& r,
                                          const Vec3V& position, BatchV lod, int count) {
  const BatchTag d;
  const glm::mat4& m = r.world_to_image;
  // Row c of m times (p, 1): glm's mat4 x vec4, (m0 x + m1 y) + (m2 z + m3 w).
  const auto row = [&](int c) {
    return hn::Add(
        hn::Add(hn::Mul(hn::Set(d, m[0][c]), position.x), hn::Mul(hn::Set(d, m[1][c]), position.y)),
        hn::Add(hn::Mul(hn::Set(d, m[2][c]), position.z), hn::Set(d, m[3][c])));
  };
  const BatchV inv_w = hn::Div(hn::Set(d, 1.0f), row(3));
  alignas(64) float u[8], v[8], lanes_lod[8], rgba[8][4];
  hn::Store(hn::Mul(row(0), inv_w), d, u);
  hn::Store(hn::Mul(row(1), inv_w), d, v);
  hn::Store(lod, d, lanes_lod);
  count = std::min(count, static_cast<int>(hn::Lanes(d)));
  sample_at(*r.image, r.sampler, u, v, lanes_lod, count, rgba);
  alignas(64) float red[8] = {}, green[8] = {}, blue[8] = {};
  for (int lane = 0; lane < count; ++lane) {
    red[lane] = rgba[lane][0], green[lane] = rgba[lane][1], blue[lane] = rgba[lane][2];
  }
  return {hn::Load(d, red), hn::Load(d, green), hn::Load(d, blue)};
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_PLANAR_REFLECTION_INL_H_
