// The light arriving at a vector of surface points at once, for the batch kernels of the models
// lit per pixel (shade_batch.cpp) and per vertex (vertex_batch.cpp): directional, point and spot
// lights, after their shadows. Included inside each file's HWY_NAMESPACE after batch_math-inl.h
// and shadow_batch-inl.h, the Highway "-inl.h" way. Every target computes the same IEEE
// operations in the same order; the kernels' tests check the light on cases worked out by hand.
#if defined(FACET_SHADING_LIGHT_BATCH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_LIGHT_BATCH_INL_H_
#undef FACET_SHADING_LIGHT_BATCH_INL_H_
#else
#define FACET_SHADING_LIGHT_BATCH_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>

#include "shading/batch_math-inl.h"
#include "shading/shadow_batch-inl.h"
#include "shading/uniforms.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// std::clamp(v, lo, hi): lo where v < lo, else hi where hi < v, else v (NaN stays).
HWY_INLINE BatchV StdClamp(BatchV v, BatchV lo, BatchV hi) {
  return hn::IfThenElse(hn::Lt(v, lo), lo, hn::IfThenElse(hn::Lt(hi, v), hi, v));
}

// IncidentLight: the unit direction toward the light and the radiance arriving, per lane.
struct IncidentV {
  Vec3V direction;
  Vec3V radiance;
};

// A point or spot light's direction and radiance at p: inverse-square falloff windowed to reach
// zero at the light's range (glTF KHR_lights_punctual), and a spot light's cone.
HWY_INLINE IncidentV PositionalIncident(const LightData& light, const Vec3V& p) {
  const BatchTag d;
  const BatchV one = hn::Set(d, 1.0f);
  const Vec3V to_light{hn::Sub(hn::Set(d, light.position.x), p.x),
                       hn::Sub(hn::Set(d, light.position.y), p.y),
                       hn::Sub(hn::Set(d, light.position.z), p.z)};
  const BatchV distance_squared = StdMax(Dot(to_light, to_light), hn::Set(d, 1e-8f));
  const Vec3V direction = Scale(to_light, hn::Div(one, hn::Sqrt(distance_squared)));
  BatchV attenuation = hn::Div(one, distance_squared);
  if (light.inv_range_squared > 0.0f) {
    const BatchV ratio = hn::Mul(distance_squared, hn::Set(d, light.inv_range_squared));
    const BatchV window = StdClamp(hn::Sub(one, hn::Mul(ratio, ratio)), hn::Zero(d), one);
    attenuation = hn::Mul(attenuation, hn::Mul(window, window));
  }
  if (light.type == LightType::spot) {
    const BatchV cos_angle = Dot(Negate(direction), Set3(light.spot_direction));
    const float cone = std::max(light.cos_inner - light.cos_outer, 1e-4f);
    const BatchV t =
        StdClamp(hn::Div(hn::Sub(cos_angle, hn::Set(d, light.cos_outer)), hn::Set(d, cone)),
                 hn::Zero(d), one);
    attenuation = hn::Mul(attenuation, hn::Mul(t, t));
  }
  return {direction, Scale(Set3(light.radiance), attenuation)};
}

// The light's unit direction and radiance at points p: a directional light's are the same
// everywhere.
HWY_INLINE IncidentV Incident(const LightData& light, const Vec3V& p) {
  if (light.type == LightType::directional) return {Set3(light.to_light), Set3(light.radiance)};
  return PositionalIncident(light, p);
}

// The radiance of `in` at points p of unit normals n in the lanes of `wanted` (facing the light;
// the others' results are not used): the radiance after the light's shadow, if it casts one.
HWY_INLINE Vec3V ReceivedRadiance(const LightData& light, const IncidentV& in, const Vec3V& p,
                                  const Vec3V& n, BatchMask wanted) {
  if (!light.shadow) return in.radiance;
  return Scale(in.radiance, ShadowVisibility(*light.shadow, p, n, wanted));
}

// The highlight of a light in direction to_light before its radiance, at points of unit normals
// n seen along unit views: max(0, N.H)^shininess with H the half vector (Blinn-Phong), or
// max(0, R.V)^shininess with R the light's mirror direction (Phong); 1 for shininess 0.
HWY_INLINE BatchV Highlight(const Material& m, bool blinn, const Vec3V& n, const Vec3V& view,
                            const Vec3V& to_light) {
  const BatchTag d;
  if (m.shininess == 0.0f) return hn::Set(d, 1.0f);
  const BatchV along =
      blinn ? Dot(n, Normalize({hn::Add(to_light.x, view.x), hn::Add(to_light.y, view.y),
                                hn::Add(to_light.z, view.z)}))
            : Dot(Reflect(Negate(to_light), n), view);
  return PortablePow(StdMax(along, hn::Zero(d)), m.shininess);
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_LIGHT_BATCH_INL_H_
