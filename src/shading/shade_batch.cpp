// Batch shading of the unlit, Lambert, Phong and Blinn-Phong models and the normals view (see
// shade_batch.hpp). Highway compiles this file once per SIMD target (foreach_target.h re-includes
// it); the frame fetches the chosen target's kernel (pipeline/kernels.hpp). Every step repeats
// models.hpp, lit_models.hpp, brdf.hpp and surface.cpp with the same IEEE operations in the same
// order (glm's dot is (x*x' + y*y') + z*z'; std::max(0, d) keeps 0 for NaN; no fused multiply-add),
// so each target gives fragment()'s bits; shade_batch_test checks it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/shade_batch.cpp"
#include "shading/shade_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "core/portable_math.hpp"
#include "shading/batch_math-inl.h"
#include "shading/lighting.hpp"
#include "shading/light_batch-inl.h"
#include "shading/shadow_batch-inl.h"
#include "shading/surface.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using FloatTag = BatchTag;
using FloatV = BatchV;

// The base color: material x vertex color (the color slots), times the map's texel if any.
struct Albedo {
  FloatV c[4];
};
// The surface color of pixels j...: the interpolated color, or `constant` (the material's,
// for the constant-color forms) when not null; times the base color map's texel, if any.
HWY_INLINE Albedo LoadAlbedo(const ShadeInput& in, int j, const Albedo* constant) {
  const FloatTag d;
  Albedo a;
  for (int c = 0; c < 4; ++c) {
    a.c[c] = constant ? constant->c[c] : hn::Load(d, in.v[kColorSlot + c] + j);
  }
  if (in.base_texel != nullptr) {
    FloatV t[4];
    hn::LoadInterleaved4(d, &in.base_texel[j][0], t[0], t[1], t[2], t[3]);
    for (int c = 0; c < 4; ++c) a.c[c] = hn::Mul(a.c[c], t[c]);
  }
  return a;
}

// diffuse_light() of models.hpp: ambient + sum of radiance x max(0, N.L), the radiance after the
// light's shadow at `position` where N.L > 0 (active: the batch's lanes).
HWY_INLINE Vec3V DiffuseLight(const DrawUniforms& u, const Vec3V& normal, const Vec3V& position,
                              BatchMask active) {
  const FloatTag d;
  Vec3V light = Set3(u.frame->ambient);
  for (int i = 0; i < u.frame->light_count; ++i) {
    const LightData& l = u.frame->lights[i];
    IncidentV in = Incident(l, position);
    const FloatV n_dot_l = Dot(normal, in.direction);
    const auto facing_mask = hn::Lt(hn::Zero(d), n_dot_l);
    const FloatV facing = hn::IfThenElse(facing_mask, n_dot_l, hn::Zero(d));
    in.radiance = ReceivedRadiance(l, in, position, normal, hn::And(facing_mask, active));
    light.x = hn::Add(light.x, hn::Mul(in.radiance.x, facing));
    light.y = hn::Add(light.y, hn::Mul(in.radiance.y, facing));
    light.z = hn::Add(light.z, hn::Mul(in.radiance.z, facing));
  }
  return light;
}

// apply_fog() of fog.hpp at the ViewDepth (uniforms.hpp) of pixels j.. of `in`: the fraction
// kept (fog_keep), clamped, then mixed with the fog color.
HWY_INLINE void Fogged(const Fog& fog, const ViewDepth& depth, const ShadeInput& in, int j,
                       FloatV color[3]) {
  const FloatTag d;
  const FloatV w = hn::Add(hn::Add(hn::Mul(hn::Set(d, depth.from_w), hn::Load(d, in.w + j)),
                                   hn::Mul(hn::Set(d, depth.from_z), hn::Load(d, in.z + j))),
                           hn::Set(d, depth.offset));
  FloatV keep;
  if (fog.mode == FogMode::linear) {
    keep =
        hn::Div(hn::Sub(hn::Set(d, fog.end), w), hn::Set(d, std::max(fog.end - fog.start, 1e-6f)));
  } else {
    keep = PortableExp(hn::Mul(hn::Set(d, -fog.density), w));
  }
  const FloatV one = hn::Set(d, 1.0f);
  keep = hn::IfThenElse(hn::Lt(keep, hn::Zero(d)), hn::Zero(d),
                        hn::IfThenElse(hn::Lt(one, keep), one, keep));  // std::clamp
  const FloatV lose = hn::Sub(one, keep);
  for (int c = 0; c < 3; ++c) {
    color[c] = hn::Add(hn::Mul(hn::Set(d, fog.color[c]), lose), hn::Mul(color[c], keep));
  }
}

// PhongShadingT::fragment()'s light loop: albedo x ambient, plus for each light facing the
// surface radiance x (albedo N.L + specular x highlight), the radiance after the light's shadow
// at `position` (active: the batch's lanes).
HWY_INLINE Vec3V SpecularLight(const DrawUniforms& u, bool blinn, const Vec3V& n, const Vec3V& view,
                               const Vec3V& position, const Albedo& albedo, const Vec3V& specular,
                               BatchMask active) {
  const FloatTag d;
  const Material& m = *u.material;
  Vec3V color{hn::Mul(albedo.c[0], hn::Set(d, u.frame->ambient.x)),
              hn::Mul(albedo.c[1], hn::Set(d, u.frame->ambient.y)),
              hn::Mul(albedo.c[2], hn::Set(d, u.frame->ambient.z))};
  for (int i = 0; i < u.frame->light_count; ++i) {
    const LightData& l = u.frame->lights[i];
    IncidentV in = Incident(l, position);
    const Vec3V& to_light = in.direction;
    const FloatV n_dot_l = Dot(n, to_light);
    FloatV along;  // blinn_phong_specular / phong_specular, before the power
    if (blinn) {
      along = Dot(n, Normalize({hn::Add(to_light.x, view.x), hn::Add(to_light.y, view.y),
                                hn::Add(to_light.z, view.z)}));
    } else {
      along = Dot(Reflect(Negate(to_light), n), view);
    }
    const FloatV highlight = m.shininess == 0.0f
                                 ? hn::Set(d, 1.0f)
                                 : PortablePow(StdMax(along, hn::Zero(d)), m.shininess);
    const auto lit = hn::Not(hn::Le(n_dot_l, hn::Zero(d)));  // the scalar loop's continue
    in.radiance = ReceivedRadiance(l, in, position, n, hn::And(lit, active));
    const FloatV* a = albedo.c;
    const FloatV r[3] = {in.radiance.x, in.radiance.y, in.radiance.z};
    const FloatV s[3] = {specular.x, specular.y, specular.z};
    FloatV* out[3] = {&color.x, &color.y, &color.z};
    for (int c = 0; c < 3; ++c) {
      const FloatV term = hn::Add(hn::Mul(a[c], n_dot_l), hn::Mul(s[c], highlight));
      *out[c] = hn::IfThenElse(lit, hn::Add(*out[c], hn::Mul(r[c], term)), *out[c]);
    }
  }
  return color;
}

// NormalsShading::fragment(): display_value(safe_normalize(n) * 0.5 + 0.5), then fog, if any,
// on the decoded colors in SIMD again.
void ShadeNormals(const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const FloatV half = hn::Set(d, 0.5f);
  if (u.frame->display_exact) {  // a float target: the values themselves, clamped to [0, 1]
    for (int j = 0; j < in.count; j += lanes) {
      const Vec3V n = SafeNormalize(Load3(in.v, 0, j));
      FloatV color[4] = {hn::Add(hn::Mul(n.x, half), half), hn::Add(hn::Mul(n.y, half), half),
                         hn::Add(hn::Mul(n.z, half), half), hn::Set(d, 1.0f)};
      for (int c = 0; c < 3; ++c) {
        color[c] =
            StdMin(hn::IfThenElseZero(hn::Gt(color[c], hn::Zero(d)), color[c]), hn::Set(d, 1.0f));
      }
      StoreColors(color, ColorAt(rgba, in.rgba_row_stride, j));
    }
  } else {
    alignas(64) std::int32_t codes[3][kShadeBatch];
    for (int j = 0; j < in.count; j += lanes) {
      const Vec3V n = SafeNormalize(Load3(in.v, 0, j));
      StoreDisplayCodes({hn::Add(hn::Mul(n.x, half), half), hn::Add(hn::Mul(n.y, half), half),
                         hn::Add(hn::Mul(n.z, half), half)},
                        j, codes);
    }
    DecodeDisplayCodes(codes, in.count, u.frame->display_referred, in.rgba_row_stride, rgba);
  }
  if (in.fog == nullptr || in.fog->mode == FogMode::none) return;
  for (int j = 0; j < in.count; j += lanes) {
    alignas(64) float padded[8][4] = {};  // rgba past the batch's count may be unset
    const int active = std::min(lanes, in.count - j);
    std::memcpy(padded, ColorAt(rgba, in.rgba_row_stride, j), sizeof(float) * 4 * active);
    FloatV color[4];
    hn::LoadInterleaved4(d, &padded[0][0], color[0], color[1], color[2], color[3]);
    Fogged(*in.fog, u.frame->view_depth, in, j, color);
    StoreColors(color, ColorAt(rgba, in.rgba_row_stride, j));
  }
}

// The constant-color unlit model with a base color map and no fog: each pixel's color is the
// material's times its texel, plus the emission, channel by channel. Done on the colors as they
// lie, RGBA, four pixels to a 16-lane vector, rather than turned into a vector per channel and
// back, which would cost more than the arithmetic itself. Returns false where vectors do not
// hold whole pixels.
bool ShadeConstantUnlitAsRgba(const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
  const hn::ScalableTag<float> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  if (lanes % 4 != 0 || lanes > 32) return false;
  const int pixels = lanes / 4;  // per vector: 1, 2, 4 or 8, within one row of 8 (ColorAt)
  const glm::vec4& c = u.material->base_color;
  const glm::vec3& e = u.material->emissive;
  alignas(16) const float factor[4] = {c.r, c.g, c.b, c.a};
  alignas(16) const float added[4] = {e.x, e.y, e.z, 0.0f};
  const auto base = hn::LoadDup128(d, factor), emission = hn::LoadDup128(d, added);
  const int padded = (in.count + 7) / 8 * 8;  // as the per-channel loop writes them
  for (int n = 0; n < padded; n += pixels) {
    const auto texel = hn::LoadU(d, in.base_texel[n]);
    hn::StoreU(hn::Add(hn::Mul(base, texel), emission), d, *ColorAt(rgba, in.rgba_row_stride, n));
  }
  return true;
}

void ShadeBatch(BatchModel model, const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
  if (model == BatchModel::normals) return ShadeNormals(u, in, rgba);
  const bool fogged = in.fog != nullptr && in.fog->mode != FogMode::none;
  if (model == BatchModel::constant_unlit && in.base_texel != nullptr && !fogged &&
      ShadeConstantUnlitAsRgba(u, in, rgba)) {
    return;
  }
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const Material& m = *u.material;
  // emission(): the emissive factor (batch_shades() leaves out emissive maps).
  const FloatV emissive[3] = {hn::Set(d, m.emissive.x), hn::Set(d, m.emissive.y),
                              hn::Set(d, m.emissive.z)};
  // Lambert needs no view, nor its square root and division; nor its position, unless a
  // light's direction or shadow depends on it.
  const bool needs_view = model != BatchModel::lambert;
  const bool needs_position =
      needs_view || any_shadowed_light(u) || !only_directional_lights(u);
  const Vec3V specular = Set3(m.specular_color);
  const Vec3V eye{hn::Set(d, u.frame->eye.x), hn::Set(d, u.frame->eye.y),
                  hn::Set(d, u.frame->eye.z)};
  const Albedo base{{hn::Set(d, u.material->base_color.r), hn::Set(d, u.material->base_color.g),
                     hn::Set(d, u.material->base_color.b), hn::Set(d, u.material->base_color.a)}};
  const bool constant_color =
      model == BatchModel::constant_unlit || model == BatchModel::constant_gouraud;
  for (int j = 0; j < in.count; j += lanes) {
    const Albedo albedo = LoadAlbedo(in, j, constant_color ? &base : nullptr);
    FloatV color[4];
    if (model == BatchModel::unlit || model == BatchModel::constant_unlit) {
      for (int c = 0; c < 3; ++c) color[c] = hn::Add(albedo.c[c], emissive[c]);
      color[3] = hn::Add(albedo.c[3], hn::Zero(d));
    } else if (model == BatchModel::gouraud || model == BatchModel::constant_gouraud) {
      // GouraudLight::lit(): albedo x diffuse light + specular light, then emission.
      const int diffuse =
          model == BatchModel::gouraud ? kGouraudDiffuseSlot : kConstantGouraudDiffuseSlot;
      for (int c = 0; c < 3; ++c) {
        const FloatV lit = hn::Add(hn::Mul(albedo.c[c], hn::Load(d, in.v[diffuse + c] + j)),
                                   hn::Load(d, in.v[diffuse + 3 + c] + j));
        color[c] = hn::Add(lit, emissive[c]);
      }
      color[3] = albedo.c[3];
    } else {
      // surface_point(): view and normal (setup reversed the normal of a two-sided back face).
      Vec3V view{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
      Vec3V position = view;
      if (needs_position) position = Load3(in.v, kPositionSlot, j);
      if (needs_view) {
        view = SafeNormalize(
            {hn::Sub(eye.x, position.x), hn::Sub(eye.y, position.y), hn::Sub(eye.z, position.z)});
      }
      const Vec3V n = SafeNormalize(Load3(in.v, kNormalSlot, j));
      const auto active = hn::FirstN(d, static_cast<std::size_t>(in.count - j));
      const Vec3V light = model == BatchModel::lambert
                              ? DiffuseLight(u, n, position, active)
                              : SpecularLight(u, model == BatchModel::blinn_phong, n, view,
                                              position, albedo, specular, active);
      if (model == BatchModel::lambert) {
        color[0] = hn::Mul(albedo.c[0], light.x);  // diffuse_light(): albedo x light
        color[1] = hn::Mul(albedo.c[1], light.y);
        color[2] = hn::Mul(albedo.c[2], light.z);
      } else {
        color[0] = light.x, color[1] = light.y, color[2] = light.z;  // albedo already in
      }
      for (int c = 0; c < 3; ++c) color[c] = hn::Add(color[c], emissive[c]);
      color[3] = albedo.c[3];
    }
    if (fogged) Fogged(*in.fog, u.frame->view_depth, in, j, color);
    StoreColors(color, ColorAt(rgba, in.rgba_row_stride, j));
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(ShadeBatch);

bool batch_shades(BatchModel model, const DrawUniforms& u) {
  if (model == BatchModel::normals) return true;  // no light, no material
  const Material& m = *u.material;
  if (m.emissive != glm::vec3(0.0f) && m.emissive_map) return false;
  if (model == BatchModel::phong || model == BatchModel::blinn_phong) {
    if (m.normal_map || m.specular_map) return false;
    if (m.reflectivity > 0.0f && u.frame->lighting->environment.reflections) return false;
  }
  return true;
}

ShadeBatchKernel shade_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(ShadeBatch)[target];
}

}  // namespace facet::shading
#endif  // HWY_ONCE
