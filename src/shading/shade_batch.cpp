// The built-in shading models, a batch of pixels at a time (see shade_batch.hpp). Highway compiles
// this file once per SIMD target (foreach_target.h re-includes it); the frame fetches the chosen
// target's kernel (pipeline/kernels.hpp). Every target computes the same IEEE operations in the
// same order (no fused multiply-add; std::max and std::min as compare-and-select; pow and exp as
// portable_math.hpp's polynomials), so each gives the same bits; shade_batch_test checks it. The
// environment's reflections and light see the procedural sky with SIMD and an image through the
// texture lookups for all lanes at once (environment_batch-inl.h); the image-based light's
// harmonics and split sum go a lane at a time through environment_light.cpp.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/shade_batch.cpp"
#include "shading/shade_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

#include "core/portable_math.hpp"
#include "shading/batch_math-inl.h"
#include "shading/environment_batch-inl.h"
#include "shading/environment_light.hpp"
#include "shading/fog_batch-inl.h"
#include "shading/light_batch-inl.h"
#include "shading/pbr_batch-inl.h"
#include "shading/pbr_surface.hpp"
#include "shading/planar_reflection-inl.h"
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

// The material's emission at pixels j..: the emissive factor (`factor`, the material's, set
// once per batch), times the emissive map's texel where it is read (the raster loop samples it
// only for a non-zero factor).
HWY_INLINE Vec3V Emission(const Vec3V& factor, const ShadeInput& in, int j) {
  if (in.map_texel[kEmissiveMap] == nullptr) return factor;
  FloatV t[4];
  LoadTexel(in.map_texel[kEmissiveMap], j, t);
  return {hn::Mul(factor.x, t[0]), hn::Mul(factor.y, t[1]), hn::Mul(factor.z, t[2])};
}

// Normal mapping of unit normal n: the map's tangent-space normal (scaled in x and y by the
// material's normal scale) through the tangent frame, the interpolated tangent made orthogonal to
// n (Gram-Schmidt) and n x tangent signed by the handedness; where the pixel has a tangent and
// the mapped normal is not zero.
HWY_INLINE Vec3V MappedNormal(const Material& m, const ShadeInput& in, int j, const Vec3V& n) {
  const FloatTag d;
  const Vec3V tangent = Load3(in.v, kTangentSlot, j);
  const FloatV handedness = hn::Load(d, in.v[kTangentSlot + 3] + j);
  const auto has_tangent = hn::Gt(Dot(tangent, tangent), hn::Zero(d));
  const FloatV along = Dot(n, tangent);
  const Vec3V t = SafeNormalize({hn::Sub(tangent.x, hn::Mul(n.x, along)),
                                 hn::Sub(tangent.y, hn::Mul(n.y, along)),
                                 hn::Sub(tangent.z, hn::Mul(n.z, along))});
  const FloatV one = hn::Set(d, 1.0f), two = hn::Set(d, 2.0f);
  const Vec3V b =
      Scale(Cross(n, t), hn::IfThenElse(hn::Lt(handedness, hn::Zero(d)), hn::Neg(one), one));
  FloatV texel[4];
  LoadTexel(in.map_texel[kNormalMap], j, texel);
  const FloatV scale = hn::Set(d, m.normal_scale);
  const FloatV tx = hn::Mul(hn::Sub(hn::Mul(texel[0], two), one), scale);
  const FloatV ty = hn::Mul(hn::Sub(hn::Mul(texel[1], two), one), scale);
  const FloatV tz = hn::Sub(hn::Mul(texel[2], two), one);
  const Vec3V mapped =
      SafeNormalize({hn::Add(hn::Add(hn::Mul(t.x, tx), hn::Mul(b.x, ty)), hn::Mul(n.x, tz)),
                     hn::Add(hn::Add(hn::Mul(t.y, tx), hn::Mul(b.y, ty)), hn::Mul(n.y, tz)),
                     hn::Add(hn::Add(hn::Mul(t.z, tx), hn::Mul(b.z, ty)), hn::Mul(n.z, tz))});
  const auto nonzero = hn::Or(hn::Or(hn::Ne(mapped.x, hn::Zero(d)), hn::Ne(mapped.y, hn::Zero(d))),
                              hn::Ne(mapped.z, hn::Zero(d)));
  const auto use = hn::And(has_tangent, nonzero);
  return {hn::IfThenElse(use, mapped.x, n.x), hn::IfThenElse(use, mapped.y, n.y),
          hn::IfThenElse(use, mapped.z, n.z)};
}

// Lambert's light: ambient + sum of radiance x max(0, N.L), the radiance after the light's shadow
// at `position` where N.L > 0 (active: the batch's lanes).
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

// The color mixed with the fog color, keeping `keep` of it.
HWY_INLINE void FoggedBy(const Fog& fog, FloatV keep, FloatV color[3]) {
  const FloatTag d;
  const FloatV lose = hn::Sub(hn::Set(d, 1.0f), keep);
  for (int c = 0; c < 3; ++c) {
    color[c] = hn::Add(hn::Mul(hn::Set(d, fog.color[c]), lose), hn::Mul(color[c], keep));
  }
}

// Distance fog at pixels j.. of `in`: the color mixed with the fog color, keeping FogKeep's
// share (fog_batch-inl.h).
HWY_INLINE void Fogged(const Fog& fog, const ViewDepth& depth, const ShadeInput& in, int j,
                       FloatV color[3]) {
  FoggedBy(fog, FogKeep(fog, depth, in, j), color);
}

// Highlights found before the shading loop (ShadeModel), in a loop of their own: there the CPU
// overlaps a power's chain of multiplications across vectors, in the shading loop it would not.
// For each of the first kHighlightsAhead lights, a row of the batch's highlights, or null where
// the shading loop finds them (lights other than directional ones, whose direction it finds).
inline constexpr int kHighlightsAhead = 4;
struct HighlightsAhead {
  const float* of[kHighlightsAhead] = {};
};

// Fills rows with the highlights of the first directional lights at the batch's `count` pixels,
// whose unit normals and views `unit` holds (slots 0..2 and 3..5).
HWY_INLINE HighlightsAhead FindHighlightsAhead(const DrawUniforms& u, bool blinn, int count,
                                               const float (*unit)[kShadeBatch],
                                               float (*rows)[kShadeBatch]) {
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  HighlightsAhead ahead;
  for (int i = 0; i < std::min(u.frame->light_count, kHighlightsAhead); ++i) {
    const LightData& light = u.frame->lights[i];
    if (light.type != LightType::directional) continue;
    const Vec3V to_light = Set3(light.to_light);
    for (int j = 0; j < count; j += lanes) {
      hn::Store(Highlight(*u.material, blinn, Load3(unit, 0, j), Load3(unit, 3, j), to_light), d,
                rows[i] + j);
    }
    ahead.of[i] = rows[i];
  }
  return ahead;
}

// Phong's and Blinn-Phong's light at pixels j..: albedo x ambient, plus for each light facing
// the surface radiance x (albedo N.L + specular x highlight), the radiance after the light's
// shadow at `position` (active: the batch's lanes); the highlights found ahead taken as found.
HWY_INLINE Vec3V SpecularLight(const DrawUniforms& u, bool blinn, const Vec3V& n, const Vec3V& view,
                               const Vec3V& position, const Albedo& albedo, const Vec3V& specular,
                               BatchMask active, const HighlightsAhead& ahead, int j) {
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
    const FloatV highlight = i < kHighlightsAhead && ahead.of[i] != nullptr
                                 ? hn::Load(d, ahead.of[i] + j)
                                 : Highlight(m, blinn, n, view, to_light);
    const auto lit = hn::Not(hn::Le(n_dot_l, hn::Zero(d)));  // facing the light (not NaN)
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

// Phong's mirror reflection: the color mixed with the radiance from the mirror direction of the
// view about n by the material's reflectivity (glm::mix(color, radiance, reflectivity)), for the
// first `count` lanes. The radiance is the planar reflection's at the surface point, blurred as
// the highlight's exponent says (phong_roughness), where the draw has one; else the
// environment's along glm::reflect(-view, n). Out of line: it would take the inlined loop's
// registers.
static HWY_NOINLINE Vec3V Reflected(const DrawUniforms& u, const ShadeInput& in, int j,
                                    const Vec3V& color, const Vec3V& view, const Vec3V& n,
                                    const Vec3V& position) {
  const FloatTag d;
  const int count = in.count - j;
  const Vec3V radiance =
      u.reflection != nullptr
          ? PlanarReflectionRadiance(
                u, in, j, position,
                ReflectionLod(*u.reflection, hn::Set(d, phong_roughness(u.material->shininess))))
          : EnvironmentRadiance(u.frame->kernels->sample_at, u.frame->lighting->environment,
                                Reflect(Negate(view), n), hn::Zero(d), count);
  const float reflectivity = u.material->reflectivity;
  const FloatV kept = hn::Set(d, 1.0f - reflectivity), taken = hn::Set(d, reflectivity);
  return {hn::Add(hn::Mul(color.x, kept), hn::Mul(radiance.x, taken)),
          hn::Add(hn::Mul(color.y, kept), hn::Mul(radiance.y, taken)),
          hn::Add(hn::Mul(color.z, kept), hn::Mul(radiance.z, taken))};
}

// Fogs the colors already in rgba (ColorAt) in place, if in.fog.
void FogBatch(const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
  if (in.fog == nullptr || in.fog->mode == FogMode::none) return;
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
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

// The debug views' display values (not light: an 8-bit code per channel, models.hpp's
// DisplayReferred) of pixels j..: the normal, renormalized, as n * 0.5 + 0.5; the view depth over
// the frame's range (FrameUniforms::depth_view_near, depth_view_far), near white, far black; the
// texture coordinates' fractional parts as red and green.
template <BatchModel kView>
HWY_INLINE Vec3V DisplayShown(const DrawUniforms& u, const ShadeInput& in, int j) {
  const FloatTag d;
  const FloatV half = hn::Set(d, 0.5f);
  if constexpr (kView == BatchModel::normals) {
    const Vec3V n = SafeNormalize(Load3(in.v, 0, j));
    return {hn::Add(hn::Mul(n.x, half), half), hn::Add(hn::Mul(n.y, half), half),
            hn::Add(hn::Mul(n.z, half), half)};
  } else if constexpr (kView == BatchModel::depth_view) {
    const ViewDepth& depth = u.frame->view_depth;
    const FloatV view = hn::Add(hn::Add(hn::Mul(hn::Set(d, depth.from_w), hn::Load(d, in.w + j)),
                                        hn::Mul(hn::Set(d, depth.from_z), hn::Load(d, in.z + j))),
                                hn::Set(d, depth.offset));
    const float near = u.frame->depth_view_near, far = u.frame->depth_view_far;
    const FloatV t =
        hn::Div(hn::Sub(view, hn::Set(d, near)), hn::Set(d, std::max(far - near, 1e-30f)));
    const FloatV shown = hn::Sub(hn::Set(d, 1.0f), t);  // clamped to [0, 1] as it is shown
    return {shown, shown, shown};
  } else {
    const FloatV u_value = hn::Load(d, in.v[0] + j), v_value = hn::Load(d, in.v[1] + j);
    return {hn::Sub(u_value, hn::Floor(u_value)), hn::Sub(v_value, hn::Floor(v_value)),
            hn::Zero(d)};
  }
}

// A debug view (DisplayShown): its display values as the tile stores them (models.hpp's
// DisplayReferred: the code decoded, or code / 255 in display-referred frames, or the value
// clamped to [0, 1] in float targets), then fog, if any, on the stored colors in SIMD again.
template <BatchModel kView>
void ShadeDisplay(const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  if (u.frame->display_exact) {  // a float target: the values themselves, clamped to [0, 1]
    for (int j = 0; j < in.count; j += lanes) {
      const Vec3V shown = DisplayShown<kView>(u, in, j);
      FloatV color[4] = {shown.x, shown.y, shown.z, hn::Set(d, 1.0f)};
      for (int c = 0; c < 3; ++c) {
        color[c] =
            StdMin(hn::IfThenElseZero(hn::Gt(color[c], hn::Zero(d)), color[c]), hn::Set(d, 1.0f));
      }
      StoreColors(color, ColorAt(rgba, in.rgba_row_stride, j));
    }
  } else {
    DisplayOut out(*u.frame, in, rgba);
    for (int j = 0; j < in.count; j += lanes) StoreDisplay(DisplayShown<kView>(u, in, j), j, out);
    FinishDisplay(out, in.count);
  }
  FogBatch(u, in, rgba);
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
  const hn::RebindToSigned<decltype(d)> di;
  const auto alpha =  // lanes 3, 7, 11, ...
      hn::RebindMask(d, hn::Eq(hn::And(hn::Iota(di, 0), hn::Set(di, 3)), hn::Set(di, 3)));
  const int padded = (in.count + 7) / 8 * 8;  // as the per-channel loop writes them
  for (int n = 0; n < padded; n += pixels) {
    const auto texel = hn::LoadU(d, in.base_texel[n]);
    auto color = hn::Add(hn::Mul(base, texel), emission);
    if (in.opaque) color = hn::IfThenElse(alpha, hn::Set(d, 1.0f), color);
    hn::StoreU(color, d, *ColorAt(rgba, in.rgba_row_stride, n));
  }
  return true;
}

// The loop of one model (not the normals view), compiled per model: each holds only its own
// steps, and the maps it reads (maps_read) are the only ones it tests for.
template <BatchModel kModel>
void ShadeModel(const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
  constexpr bool kUnlit = kModel == BatchModel::unlit || kModel == BatchModel::constant_unlit;
  constexpr bool kGray = kModel == BatchModel::gray_gouraud;
  constexpr bool kGouraud =
      kModel == BatchModel::gouraud || kModel == BatchModel::constant_gouraud || kGray;
  constexpr bool kConstantColor =
      kModel == BatchModel::constant_unlit || kModel == BatchModel::constant_gouraud || kGray;
  constexpr bool kPhong = kModel == BatchModel::phong || kModel == BatchModel::blinn_phong;
  constexpr unsigned kMapsRead = maps_read(kModel);
  const bool fogged = in.fog != nullptr && in.fog->mode != FogMode::none;
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const Material& m = *u.material;
  // Lambert needs no view, nor its square root and division; nor its position, unless a
  // light's direction or shadow depends on it.
  constexpr bool kNeedsView = kModel != BatchModel::lambert;
  const bool needs_position = kNeedsView || any_shadowed_light(u) || !only_directional_lights(u);
  const bool reflects = kPhong && m.reflectivity > 0.0f &&
                        (u.reflection != nullptr || u.frame->lighting->environment.reflections);
  const Vec3V eye = Set3(u.frame->eye);
  const Albedo base{{hn::Set(d, m.base_color.r), hn::Set(d, m.base_color.g),
                     hn::Set(d, m.base_color.b), hn::Set(d, m.base_color.a)}};
  const Vec3V emissive_factor = Set3(m.emissive);
  // Fog's shares first, in a loop of their own: its polynomial is a long chain of dependent
  // operations, which a loop this short overlaps across vectors and the shading loop would not.
  alignas(64) float fog_keep[kShadeBatch];
  if (fogged) {
    for (int j = 0; j < in.count; j += lanes) {
      hn::Store(FogKeep(*in.fog, u.frame->view_depth, in, j), d, fog_keep + j);
    }
  }
  // So too the surface point's unit normal and view (a square root and a division each).
  constexpr bool kSurface = !kUnlit && !kGouraud;
  alignas(64) float unit[6][kShadeBatch];  // normal, view
  for (int j = 0; kSurface && j < in.count; j += lanes) {
    Store3(SafeNormalize(Load3(in.v, kNormalSlot, j)), unit, 0, j);
    if constexpr (kNeedsView) {  // (and so needs_position)
      const Vec3V p = Load3(in.v, kPositionSlot, j);
      Store3(SafeNormalize({hn::Sub(eye.x, p.x), hn::Sub(eye.y, p.y), hn::Sub(eye.z, p.z)}), unit,
             3, j);
    }
  }
  // And the highlights of the first directional lights, where no normal map bends the normals.
  alignas(64) float highlights[kHighlightsAhead][kShadeBatch];
  HighlightsAhead ahead;
  if constexpr (kPhong) {
    if ((kMapsRead & map_bit(kNormalMap)) == 0 || in.map_texel[kNormalMap] == nullptr) {
      ahead = FindHighlightsAhead(u, kModel == BatchModel::blinn_phong, in.count, unit, highlights);
    }
  }
  for (int j = 0; j < in.count; j += lanes) {
    const Albedo albedo = LoadAlbedo(in, j, kConstantColor ? &base : nullptr);
    Vec3V emission = emissive_factor;
    if constexpr ((kMapsRead & map_bit(kEmissiveMap)) != 0) emission = Emission(emission, in, j);
    FloatV color[4];
    if constexpr (kUnlit) {
      color[0] = hn::Add(albedo.c[0], emission.x);
      color[1] = hn::Add(albedo.c[1], emission.y);
      color[2] = hn::Add(albedo.c[2], emission.z);
      color[3] = hn::Add(albedo.c[3], hn::Zero(d));
    } else if constexpr (kGouraud) {
      // Albedo x the interpolated diffuse light + the specular light, then emission. Gray light
      // keeps one slot for each, and its diffuse light without the ambient (GouraudLayout).
      constexpr int kDiffuse =
          kModel == BatchModel::gouraud ? kGouraudDiffuseSlot : kConstantGouraudDiffuseSlot;
      const FloatV e[3] = {emission.x, emission.y, emission.z};
      for (int c = 0; c < 3; ++c) {
        const int diffuse = kGray ? kDiffuse : kDiffuse + c;
        const int specular = kGray ? kDiffuse + 1 : kDiffuse + 3 + c;
        FloatV light = hn::Load(d, in.v[diffuse] + j);
        if constexpr (kGray) light = hn::Add(hn::Set(d, u.frame->ambient[c]), light);
        const FloatV lit = hn::Add(hn::Mul(albedo.c[c], light), hn::Load(d, in.v[specular] + j));
        color[c] = hn::Add(lit, e[c]);
      }
      color[3] = albedo.c[3];
    } else {
      // The surface point: view and normal (setup reversed the normal of a two-sided back face).
      Vec3V view{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
      Vec3V position = view;
      if (needs_position) position = Load3(in.v, kPositionSlot, j);
      if constexpr (kNeedsView) {
        view = Load3(unit, 3, j);
      }
      Vec3V n = Load3(unit, 0, j);
      if constexpr ((kMapsRead & map_bit(kNormalMap)) != 0) {
        if (in.map_texel[kNormalMap] != nullptr) n = MappedNormal(m, in, j, n);
      }
      const auto active = hn::FirstN(d, static_cast<std::size_t>(in.count - j));
      Vec3V light;
      if constexpr (kModel == BatchModel::lambert) {
        light = DiffuseLight(u, n, position, active);
        light = {hn::Mul(albedo.c[0], light.x), hn::Mul(albedo.c[1], light.y),
                 hn::Mul(albedo.c[2], light.z)};  // albedo x light
      } else if constexpr (kModel == BatchModel::pbr) {
        light =
            PbrLight(u, in, j, n, view, position, {albedo.c[0], albedo.c[1], albedo.c[2]}, active);
      } else {
        // The specular color: the factor times the specular map's texel, if any.
        Vec3V specular = Set3(m.specular_color);
        if (in.map_texel[kSpecularMap] != nullptr) {
          FloatV t[4];
          LoadTexel(in.map_texel[kSpecularMap], j, t);
          specular = {hn::Mul(specular.x, t[0]), hn::Mul(specular.y, t[1]),
                      hn::Mul(specular.z, t[2])};
        }
        light = SpecularLight(u, kModel == BatchModel::blinn_phong, n, view, position, albedo,
                              specular, active, ahead, j);  // albedo already in
        if (reflects) light = Reflected(u, in, j, light, view, n, position);
      }
      color[0] = hn::Add(light.x, emission.x);
      color[1] = hn::Add(light.y, emission.y);
      color[2] = hn::Add(light.z, emission.z);
      color[3] = albedo.c[3];
    }
    if (in.opaque) color[3] = hn::Set(d, 1.0f);
    if (fogged) FoggedBy(*in.fog, hn::Load(d, fog_keep + j), color);
    StoreColors(color, ColorAt(rgba, in.rgba_row_stride, j));
  }
}

void ShadeBatch(BatchModel model, const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
  switch (model) {
    case BatchModel::normals:
      return ShadeDisplay<BatchModel::normals>(u, in, rgba);
    case BatchModel::depth_view:
      return ShadeDisplay<BatchModel::depth_view>(u, in, rgba);
    case BatchModel::texcoords_view:
      return ShadeDisplay<BatchModel::texcoords_view>(u, in, rgba);
    case BatchModel::unlit:
      return ShadeModel<BatchModel::unlit>(u, in, rgba);
    case BatchModel::constant_unlit:
      if (in.base_texel != nullptr && (in.fog == nullptr || in.fog->mode == FogMode::none) &&
          in.map_texel[kEmissiveMap] == nullptr && ShadeConstantUnlitAsRgba(u, in, rgba)) {
        return;
      }
      return ShadeModel<BatchModel::constant_unlit>(u, in, rgba);
    case BatchModel::lambert:
      return ShadeModel<BatchModel::lambert>(u, in, rgba);
    case BatchModel::phong:
      return ShadeModel<BatchModel::phong>(u, in, rgba);
    case BatchModel::blinn_phong:
      return ShadeModel<BatchModel::blinn_phong>(u, in, rgba);
    case BatchModel::gouraud:
      return ShadeModel<BatchModel::gouraud>(u, in, rgba);
    case BatchModel::constant_gouraud:
      return ShadeModel<BatchModel::constant_gouraud>(u, in, rgba);
    case BatchModel::gray_gouraud:
      return ShadeModel<BatchModel::gray_gouraud>(u, in, rgba);
    case BatchModel::pbr:
      return ShadeModel<BatchModel::pbr>(u, in, rgba);
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(ShadeBatch);
HWY_EXPORT(FogBatch);

ShadeBatchKernel shade_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(ShadeBatch)[target];
}

FogBatchKernel fog_batch_kernel(SimdTarget target) { return HWY_DISPATCH_TABLE(FogBatch)[target]; }

}  // namespace facet::shading
#endif  // HWY_ONCE
