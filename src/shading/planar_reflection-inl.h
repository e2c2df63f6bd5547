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
#include "shading/fog_batch-inl.h"
#include "shading/kernels.hpp"
#include "shading/planar_reflection.hpp"
#include "shading/shade_batch.hpp"
#include "shading/uniforms.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The level of detail of surfaces of roughness alpha (PlanarReflection::blur_texels).
HWY_INLINE BatchV ReflectionLod(const PlanarReflection& r, BatchV alpha) {
  const BatchTag d;
  return LodLog2(hn::Add(hn::Set(d, 1.0f), hn::Mul(alpha, hn::Set(d, r.blur_texels))));
}

// The reflection's radiance seen at world points `position` (pixels j.. of `in`, of the draw
// whose reflection u.reflection is), read at level of detail `lod`, for the batch's lanes; the
// others' results are not meant to be used. Under fog (in.fog), as the pixel must hold it for
// the fog the kernel then applies to the whole pixel to leave it as the pass fogged it: the pass
// fogged what it shows over the whole path from the eye through the mirror (the mirrored eye's
// view depth is that path's length), so the fog of the path to the mirror must not count twice.
// Fog mixes v into (v - f) keep + f; the value it turns into r is (r - f (1 - keep)) / keep (or
// r where keep is 0, and the pixel is the fog color whatever it holds).
HWY_INLINE Vec3V PlanarReflectionRadiance(const DrawUniforms& u, const ShadeInput& in, int j,
                                          const Vec3V& position, BatchV lod) {
  const BatchTag d;
  const PlanarReflection& r = *u.reflection;
  int count = in.count - j;
  const glm::mat4& m = r.world_to_image;
  // Row c of m times (p, 1): glm's mat4 x vec4, (m0 x + m1 y) + (m2 z + m3 w).
  const auto row = [&](int c) {
    return hn::Add(
        hn::Add(hn::Mul(hn::Set(d, m[0][c]), position.x), hn::Mul(hn::Set(d, m[1][c]), position.y)),
        hn::Add(hn::Mul(hn::Set(d, m[2][c]), position.z), hn::Set(d, m[3][c])));
  };
  const BatchV inv_w = hn::Div(hn::Set(d, 1.0f), row(3));
  alignas(64) float tex_u[8], tex_v[8], lanes_lod[8], rgba[8][4];
  hn::Store(hn::Mul(row(0), inv_w), d, tex_u);
  hn::Store(hn::Mul(row(1), inv_w), d, tex_v);
  hn::Store(lod, d, lanes_lod);
  count = std::min(count, static_cast<int>(hn::Lanes(d)));
  u.frame->kernels->sample_at(*r.image, r.sampler, tex_u, tex_v, lanes_lod, count, rgba);
  alignas(64) float red[8] = {}, green[8] = {}, blue[8] = {};
  for (int lane = 0; lane < count; ++lane) {
    red[lane] = rgba[lane][0], green[lane] = rgba[lane][1], blue[lane] = rgba[lane][2];
  }
  const Vec3V radiance{hn::Load(d, red), hn::Load(d, green), hn::Load(d, blue)};
  if (in.fog == nullptr || in.fog->mode == FogMode::none) return radiance;
  const BatchV keep = FogKeep(*in.fog, u.frame->view_depth, in, j);
  const BatchV lose = hn::Sub(hn::Set(d, 1.0f), keep);
  const auto clear = hn::Gt(keep, hn::Zero(d));
  const glm::vec3& fog = in.fog->color;
  const auto unfogged = [&](BatchV v, float f) {
    return hn::IfThenElse(clear, hn::Div(hn::Sub(v, hn::Mul(hn::Set(d, f), lose)), keep), v);
  };
  return {unfogged(radiance.x, fog.x), unfogged(radiance.y, fog.y), unfogged(radiance.z, fog.z)};
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_PLANAR_REFLECTION_INL_H_
