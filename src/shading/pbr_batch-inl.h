// The physically based model's light for a vector of pixels at once, for the batch kernel
// (shade_batch.cpp): Cook-Torrance under each light, the metallic-roughness and occlusion maps,
// and the ambient or the environment's light. Included inside shade_batch.cpp's HWY_NAMESPACE
// after batch_math-inl.h and light_batch-inl.h, the Highway "-inl.h" way.
#if defined(FACET_SHADING_PBR_BATCH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_PBR_BATCH_INL_H_
#undef FACET_SHADING_PBR_BATCH_INL_H_
#else
#define FACET_SHADING_PBR_BATCH_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>

#include "shading/batch_math-inl.h"
#include "shading/environment_batch-inl.h"
#include "shading/environment_light.hpp"
#include "shading/light_batch-inl.h"
#include "shading/pbr_surface.hpp"
#include "shading/planar_reflection-inl.h"
#include "shading/shade_batch.hpp"
#include "shading/uniforms.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Schlick's Fresnel approximation, the reflectance f0 at normal incidence rising to 1 at grazing:
// f0 + (1 - f0) k^5 with k = 1 - clamp(cos, 0, 1). SchlickK5 gives k^5, Schlick the channel's.
HWY_INLINE BatchV SchlickK5(BatchV cos) {
  const BatchTag d;
  const BatchV one = hn::Set(d, 1.0f);
  const BatchV k = hn::Sub(one, StdClamp(cos, hn::Zero(d), one));
  return hn::Mul(hn::Mul(hn::Mul(k, k), hn::Mul(k, k)), k);
}
HWY_INLINE BatchV Schlick(BatchV f0, BatchV k5) {
  return hn::Add(f0, hn::Mul(hn::Sub(hn::Set(BatchTag(), 1.0f), f0), k5));
}

// The Cook-Torrance BRDF f(l, v) for unit n, v and l ("Real Shading in Unreal Engine 4", Karis
// 2013: GGX distribution, Smith-Schlick geometry, Schlick Fresnel), zero where n.l or n.v is not
// positive. Roughness is clamped to [0.04, 1] so highlights stay finite. Light enters the surface
// once through Fresnel on the way in (at n.l) and once on the way out (at n.v); only what passes
// both is diffused, so specular plus diffuse never exceeds what arrives even at grazing angles
// (the white furnace test checks this); metals have no diffuse part.
HWY_INLINE Vec3V CookTorrance(const Vec3V& albedo, BatchV metallic, BatchV roughness,
                              const Vec3V& f0, const Vec3V& n, const Vec3V& v, const Vec3V& l) {
  const BatchTag d;
  const BatchV zero = hn::Zero(d), one = hn::Set(d, 1.0f);
  const BatchV n_dot_l = Dot(n, l), n_dot_v = Dot(n, v);
  const auto above = hn::Not(hn::Or(hn::Le(n_dot_l, zero), hn::Le(n_dot_v, zero)));
  const Vec3V h = Normalize({hn::Add(v.x, l.x), hn::Add(v.y, l.y), hn::Add(v.z, l.z)});
  const BatchV n_dot_h = StdMax(Dot(n, h), zero);
  const BatchV r = StdClamp(roughness, hn::Set(d, 0.04f), one);
  const auto fresnel = [&](const BatchV k5, int c) {
    return Schlick(c == 0 ? f0.x : c == 1 ? f0.y : f0.z, k5);
  };
  // The GGX distribution: a2 / (pi d d), d = n.h^2 (a2 - 1) + 1, a = r^2.
  const BatchV a = hn::Mul(r, r);
  const BatchV a2 = hn::Mul(a, a);
  const BatchV dd = hn::Add(hn::Mul(hn::Mul(n_dot_h, n_dot_h), hn::Sub(a2, one)), one);
  const BatchV distribution = hn::Div(a2, hn::Mul(hn::Mul(hn::Set(d, kPi), dd), dd));
  // Smith-Schlick geometry: g1(n.v) g1(n.l), g1(x) = x / (x (1 - k) + k), k = (r + 1)^2 / 8.
  const BatchV r1 = hn::Add(r, one);
  const BatchV k = hn::Div(hn::Mul(r1, r1), hn::Set(d, 8.0f));
  const BatchV one_minus_k = hn::Sub(one, k);
  const auto g1 = [&](BatchV x) { return hn::Div(x, hn::Add(hn::Mul(x, one_minus_k), k)); };
  const BatchV geometry = hn::Mul(g1(n_dot_v), g1(n_dot_l));
  const BatchV specular_scale = hn::Div(hn::Mul(distribution, geometry),
                                        hn::Mul(hn::Mul(hn::Set(d, 4.0f), n_dot_v), n_dot_l));
  const BatchV k5_h = SchlickK5(Dot(v, h)), k5_l = SchlickK5(n_dot_l), k5_v = SchlickK5(n_dot_v);
  const BatchV diffuse_share = hn::Sub(one, metallic);
  const BatchV albedo_c[3] = {albedo.x, albedo.y, albedo.z};
  BatchV out[3];
  for (int c = 0; c < 3; ++c) {
    const BatchV specular = hn::Mul(fresnel(k5_h, c), specular_scale);
    const BatchV enter = hn::Sub(one, fresnel(k5_l, c));
    const BatchV leave = hn::Sub(one, fresnel(k5_v, c));
    const BatchV diffuse = hn::Div(
        hn::Mul(hn::Mul(hn::Mul(enter, leave), diffuse_share), albedo_c[c]), hn::Set(d, kPi));
    out[c] = hn::IfThenElseZero(above, hn::Add(diffuse, specular));
  }
  return {out[0], out[1], out[2]};
}

// The PBR model's light for pixels j..: each light through Cook-Torrance (times pi, the glTF
// "punctual light" convention, so a white surface under a unit light is as bright as in Lambert),
// then the ambient light (plus the environment's reflections, if it has them) or the environment's
// light (environment_light.hpp), through the occlusion map; emission is the caller's. The
// metallic-roughness map holds roughness in green, metallic in blue (glTF's packing).
HWY_INLINE Vec3V PbrLight(const DrawUniforms& u, const ShadeInput& in, int j, const Vec3V& n,
                          const Vec3V& view, const Vec3V& position, const Vec3V& albedo,
                          BatchMask active) {
  const BatchTag d;
  const Material& m = *u.material;
  const BatchV one = hn::Set(d, 1.0f);
  BatchV metallic = hn::Set(d, m.metallic), roughness = hn::Set(d, m.roughness);
  if (in.map_texel[kMetallicRoughnessMap] != nullptr) {
    BatchV t[4];
    LoadTexel(in.map_texel[kMetallicRoughnessMap], j, t);
    roughness = hn::Mul(roughness, t[1]);
    metallic = hn::Mul(metallic, t[2]);
  }
  BatchV occlusion = one;
  if (in.map_texel[kOcclusionMap] != nullptr) {
    BatchV t[4];
    LoadTexel(in.map_texel[kOcclusionMap], j, t);
    occlusion = hn::Add(one, hn::Mul(hn::Set(d, m.occlusion_strength), hn::Sub(t[0], one)));
  }
  // f0 = mix(0.04, albedo, metallic).
  const BatchV dielectric = hn::Mul(hn::Set(d, 0.04f), hn::Sub(one, metallic));
  const Vec3V f0{hn::Add(dielectric, hn::Mul(albedo.x, metallic)),
                 hn::Add(dielectric, hn::Mul(albedo.y, metallic)),
                 hn::Add(dielectric, hn::Mul(albedo.z, metallic))};
  Vec3V color{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
  const BatchV pi = hn::Set(d, kPi);
  for (int i = 0; i < u.frame->light_count; ++i) {
    const LightData& l = u.frame->lights[i];
    IncidentV incoming = Incident(l, position);
    const BatchV n_dot_l = Dot(n, incoming.direction);
    const auto lit = hn::Not(hn::Le(n_dot_l, hn::Zero(d)));  // facing the light (not NaN)
    incoming.radiance = ReceivedRadiance(l, incoming, position, n, hn::And(lit, active));
    const Vec3V brdf = CookTorrance(albedo, metallic, roughness, f0, n, view, incoming.direction);
    const BatchV scale = hn::Mul(n_dot_l, pi);
    color.x = hn::IfThenElse(
        lit, hn::Add(color.x, hn::Mul(hn::Mul(brdf.x, incoming.radiance.x), scale)), color.x);
    color.y = hn::IfThenElse(
        lit, hn::Add(color.y, hn::Mul(hn::Mul(brdf.y, incoming.radiance.y), scale)), color.y);
    color.z = hn::IfThenElse(
        lit, hn::Add(color.z, hn::Mul(hn::Mul(brdf.z, incoming.radiance.z), scale)), color.z);
  }
  // ambient x (diffuse albedo + f0 / 2), or the environment's light.
  const BatchV diffuse_share = hn::Sub(one, metallic);
  const BatchV half = hn::Set(d, 0.5f);
  Vec3V ambient{hn::Mul(hn::Set(d, u.frame->ambient.x),
                        hn::Add(hn::Mul(albedo.x, diffuse_share), hn::Mul(f0.x, half))),
                hn::Mul(hn::Set(d, u.frame->ambient.y),
                        hn::Add(hn::Mul(albedo.y, diffuse_share), hn::Mul(f0.y, half))),
                hn::Mul(hn::Set(d, u.frame->ambient.z),
                        hn::Add(hn::Mul(albedo.z, diffuse_share), hn::Mul(f0.z, half)))};
  const Environment& environment = u.frame->lighting->environment;
  if (u.frame->environment_light != nullptr || environment.reflections || u.reflection != nullptr) {
    // What is seen in the mirror direction glm::reflect(-view, n), blurred by roughness: the
    // planar reflection at the surface point where the draw has one (blurred by alpha =
    // roughness^2), else the environment.
    const Vec3V mirror = Reflect(Negate(view), n);
    const int count = std::min(static_cast<int>(hn::Lanes(d)), in.count - j);
    const Vec3V seen =
        u.reflection != nullptr
            ? PlanarReflectionRadiance(u, in, j, position,
                                       ReflectionLod(*u.reflection, hn::Mul(roughness, roughness)))
            : EnvironmentRadiance(u.frame->kernels->sample_at, environment, mirror,
                                  hn::Mul(roughness, hn::Set(d, 8.0f)), count);
    if (u.frame->environment_light != nullptr) {
      // The image-based light replaces the ambient, a lane at a time (environment_light.hpp).
      Lanes3 lanes_ambient(ambient);
      const Lanes3 lanes_albedo(albedo), lanes_f0(f0), lanes_n(n), lanes_view(view),
          lanes_mirror(mirror), lanes_seen(seen);
      alignas(64) float lanes_metallic[8], lanes_roughness[8];
      hn::Store(metallic, d, lanes_metallic), hn::Store(roughness, d, lanes_roughness);
      for (int lane = 0; lane < count; ++lane) {
        const PbrSurface surface{lanes_albedo[lane], lanes_metallic[lane], lanes_roughness[lane]};
        lanes_ambient.set(lane, environment_light(*u.frame->environment_light, surface,
                                                  lanes_f0[lane], lanes_n[lane], lanes_view[lane],
                                                  lanes_mirror[lane], lanes_seen[lane]));
      }
      ambient = lanes_ambient.load();
    } else {
      // Reflections add the mirror direction's radiance through the Fresnel reflectance at n . v,
      // dimmed as the surface roughens: radiance x fresnel x (1 - 0.7 roughness).
      const BatchV k5 = SchlickK5(Dot(n, view));
      const BatchV dim = hn::Sub(one, hn::Mul(roughness, hn::Set(d, 0.7f)));
      ambient = {hn::Add(ambient.x, hn::Mul(hn::Mul(seen.x, Schlick(f0.x, k5)), dim)),
                 hn::Add(ambient.y, hn::Mul(hn::Mul(seen.y, Schlick(f0.y, k5)), dim)),
                 hn::Add(ambient.z, hn::Mul(hn::Mul(seen.z, Schlick(f0.z, k5)), dim))};
    }
  }
  return {hn::Add(color.x, hn::Mul(ambient.x, occlusion)),
          hn::Add(color.y, hn::Mul(ambient.y, occlusion)),
          hn::Add(color.z, hn::Mul(ambient.z, occlusion))};
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_PBR_BATCH_INL_H_
