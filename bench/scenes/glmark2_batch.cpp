// glmark2's shaders a batch at a time (see glmark2_batch.hpp), each the formula its model's comment
// gives (glmark2_shading.hpp). Highway compiles this file once per SIMD target; the frame fetches
// the chosen target's kernel (pipeline/kernels.hpp). The operations and their order are fixed, the
// same on every target: dot is (x*x' + y*y') + z*z', normalize is v * (1 / sqrt(dot)), length is
// sqrt(dot), reflect(I, N) is I - (N * dot(N, I)) * 2, mat3 x v is (m0 x + m1 y) + m2 z, and
// max(a, b) keeps a unless a < b.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "scenes/glmark2_batch.cpp"
#include "scenes/glmark2_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>

#include "core/color.hpp"
#include "scenes/glmark2_shading.hpp"
#include "shading/batch_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::bench::glmark2::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using namespace shading::HWY_NAMESPACE;  // batch_math-inl.h
using shading::DrawUniforms;
using shading::ShadeInput;

// x^100 for x in [0, 1] by repeated squaring: x^64 x^32 x^4, as ((x32 x32) x32) x4.
HWY_INLINE BatchV Pow100(BatchV x) {
  const BatchV x2 = hn::Mul(x, x), x4 = hn::Mul(x2, x2), x8 = hn::Mul(x4, x4);
  const BatchV x16 = hn::Mul(x8, x8), x32 = hn::Mul(x16, x16);
  return hn::Mul(hn::Mul(hn::Mul(x32, x32), x32), x4);
}

// x^10: x^8 x^2 with x^8 = ((x2 x2) x2) x2.
HWY_INLINE BatchV Pow10(BatchV x) {
  const BatchV x2 = hn::Mul(x, x);
  return hn::Mul(hn::Mul(hn::Mul(hn::Mul(x2, x2), x2), x2), x2);
}

// bump's light: white Blinn-Phong with the light and half vector of the default light,
// 0.1 + 0.8 max(N.L, 0) + 0.16 max(N.H, 0)^100.
HWY_INLINE Vec3V BumpLight(const Vec3V& n) {
  const BatchTag d;
  const BatchV diffuse =
      hn::Mul(hn::Set(d, 0.8f), StdMax(Dot(n, Set3(kLightDirection)), hn::Zero(d)));
  const BatchV specular =
      hn::Mul(hn::Set(d, 0.16f), Pow100(StdMax(Dot(n, Set3(kHalfVector)), hn::Zero(d))));
  const BatchV gray = hn::Add(hn::Add(hn::Set(d, 0.1f), diffuse), specular);
  return {gray, gray, gray};
}

// Samples `map` with the frame's lookup kernel at (s[i], t[i]), level of detail lod[i], for the
// batch's pixels, and zeroes the texels of the vectors' scratch lanes past in.count.
HWY_INLINE void SampleMap(const DrawUniforms& u, const TextureMap& map, const ShadeInput& in,
                          const float* s, const float* t, const float* lod, float (*texel)[4]) {
  const int lanes = static_cast<int>(hn::Lanes(BatchTag()));
  u.frame->kernels->sample_at(*map.texture, map.sampler, s, t, lod, in.count, texel);
  const int padded = (in.count + lanes - 1) / lanes * lanes;
  std::fill(&texel[0][0] + 4 * in.count, &texel[0][0] + 4 * padded, 0.0f);
}

// shadow's ground (ShadowGroundShading), the whole batch: s = ShadowCoord / ShadowCoord.w per
// pixel, the light's depth at every s.xy in one lookup of the frame's sampler (NEAREST and
// clamped, as the map's sampler says), then grey 0.15 where that depth is nearer than
// s.z + bias, else 0.3.
HWY_INLINE void ShadowGround(const DrawUniforms& u, const ShadeInput& in, DisplayOut& out) {
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  alignas(64) float s[3][shading::kShadeBatch], no_lod[shading::kShadeBatch] = {};
  alignas(64) float texel[shading::kShadeBatch][4];
  for (int j = 0; j < in.count; j += lanes) {
    const BatchV inverse_w = hn::Div(hn::Set(d, 1.0f), hn::Load(d, in.v[3] + j));
    for (int c = 0; c < 3; ++c) {
      hn::Store(hn::Mul(hn::Load(d, in.v[c] + j), inverse_w), d, s[c] + j);
    }
  }
  SampleMap(u, u.material->base_color_map, in, s[0], s[1], no_lod, texel);
  for (int j = 0; j < in.count; j += lanes) {
    BatchV t[4];
    hn::LoadInterleaved4(d, &texel[j][0], t[0], t[1], t[2], t[3]);
    const BatchV s_z = hn::Add(hn::Load(d, s[2] + j), hn::Set(d, ShadowGroundShading::kDepthBias));
    const auto shadowed = hn::And(hn::Gt(hn::Load(d, in.v[3] + j), hn::Zero(d)), hn::Lt(t[0], s_z));
    const BatchV gray = hn::IfThenElse(shadowed, hn::Set(d, 0.15f), hn::Set(d, 0.3f));
    StoreDisplay({gray, gray, gray}, j, out);
  }
}

// GLSL's refract(I, N, e): with k = 1 - (e e) (1 - (N.I) (N.I)), zero where k < 0, else
// e I - (e (N.I) + sqrt k) N.
HWY_INLINE Vec3V Refract(const Vec3V& i, const Vec3V& n, BatchV e) {
  const BatchTag d;
  const BatchV n_dot_i = Dot(n, i);
  const BatchV k =
      hn::Sub(hn::Set(d, 1.0f),
              hn::Mul(hn::Mul(e, e), hn::Sub(hn::Set(d, 1.0f), hn::Mul(n_dot_i, n_dot_i))));
  const auto inside = hn::Not(hn::Lt(k, hn::Zero(d)));
  const BatchV along_n = hn::Add(hn::Mul(e, n_dot_i), hn::Sqrt(StdMax(k, hn::Zero(d))));
  return {hn::IfThenElseZero(inside, hn::Sub(hn::Mul(e, i.x), hn::Mul(along_n, n.x))),
          hn::IfThenElseZero(inside, hn::Sub(hn::Mul(e, i.y), hn::Mul(along_n, n.y))),
          hn::IfThenElseZero(inside, hn::Sub(hn::Mul(e, i.z), hn::Mul(along_n, n.z)))};
}

// refract's bunny (RefractShading), the whole batch: each of its three dependent lookups is one
// call of the lookup kernel for every pixel, between the steps of the formula that need it.
HWY_INLINE void RefractBatch(const DrawUniforms& u, const ShadeInput& in, DisplayOut& out) {
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  constexpr int kBatch = shading::kShadeBatch;
  alignas(64) float front[3][kBatch], back[3][kBatch];  // T1, then Pb
  alignas(64) float normal[3][kBatch], eye[3][kBatch];  // normalize(N), E = normalize(-P)
  alignas(64) float s[kBatch], t[kBatch], lod[kBatch], no_lod[kBatch] = {};
  alignas(64) float texel[kBatch][4];
  const Material& material = *u.material;
  const BatchV half = hn::Set(d, 0.5f);
  constexpr int kPosition = RefractShading::kPosition, kMapCoord = RefractShading::kMapCoord;
  // T1 = refract(E, N, 1.2), and the distance map's coordinate m.xy 0.5 + 0.5.
  for (int j = 0; j < in.count; j += lanes) {
    const Vec3V e = Normalize(Negate(Load3(in.v, kPosition, j)));
    const Vec3V n = Normalize(Load3(in.v, 0, j));
    Store3(e, eye, 0, j);
    Store3(n, normal, 0, j);
    const Vec3V t1 = Refract(e, n, hn::Set(d, kRefractiveIndex));
    Store3(t1, front, 0, j);
    const BatchV inverse_w = hn::Div(hn::Set(d, 1.0f), hn::Load(d, in.v[kMapCoord + 3] + j));
    const BatchV m_x = hn::Add(hn::Mul(hn::Load(d, in.v[kMapCoord] + j), inverse_w), t1.x);
    const BatchV m_y = hn::Add(hn::Mul(hn::Load(d, in.v[kMapCoord + 1] + j), inverse_w), t1.y);
    hn::Store(hn::Add(hn::Mul(m_x, half), half), d, s + j);
    hn::Store(hn::Add(hn::Mul(m_y, half), half), d, t + j);
  }
  SampleMap(u, material.occlusion_map, in, s, t, no_lod, texel);
  // Pb = P + T1 dist, the normal map's coordinate Pb.xy 0.5 + 0.5, and its level of detail:
  // log2 of the larger of the coordinate's changes, in texels, for a step of one pixel along x
  // and along y on the plane through P normal to N (RefractShading). A step along x moves P by
  // (2 |P.z| / (W P[0][0])) (e_x - P N.x / N.P), and so the coordinate by texels_x |P.z| times
  // that bracket, with texels_x = size / (W P[0][0]) (and with y, H and P[1][1] along y).
  const float texels_x = static_cast<float>(material.normal_map.texture->width()) /
                         (static_cast<float>(u.frame->width) * u.frame->projection[0][0]);
  const float texels_y = static_cast<float>(material.normal_map.texture->height()) /
                         (static_cast<float>(u.frame->height) * u.frame->projection[1][1]);
  for (int j = 0; j < in.count; j += lanes) {
    BatchV dist[4];
    hn::LoadInterleaved4(d, &texel[j][0], dist[0], dist[1], dist[2], dist[3]);
    const Vec3V p = Load3(in.v, kPosition, j);
    const Vec3V pb = {hn::Add(p.x, hn::Mul(hn::Load(d, front[0] + j), dist[0])),
                      hn::Add(p.y, hn::Mul(hn::Load(d, front[1] + j), dist[0])),
                      hn::Add(p.z, hn::Mul(hn::Load(d, front[2] + j), dist[0]))};
    Store3(pb, back, 0, j);
    hn::Store(hn::Add(hn::Mul(pb.x, half), half), d, s + j);
    hn::Store(hn::Add(hn::Mul(pb.y, half), half), d, t + j);
    const Vec3V n = Load3(normal, 0, j);
    const BatchV depth = hn::Neg(p.z);
    const BatchV q = hn::Div(hn::Set(d, 1.0f), Dot(n, p));
    const BatchV a = hn::Mul(depth, hn::Set(d, texels_x)), b = hn::Mul(depth, hn::Set(d, texels_y));
    const BatchV nx_q = hn::Mul(n.x, q), ny_q = hn::Mul(n.y, q);
    const BatchV du_dx = hn::Mul(a, hn::Sub(hn::Set(d, 1.0f), hn::Mul(p.x, nx_q)));
    const BatchV dv_dx = hn::Mul(a, hn::Neg(hn::Mul(p.y, nx_q)));
    const BatchV du_dy = hn::Mul(b, hn::Neg(hn::Mul(p.x, ny_q)));
    const BatchV dv_dy = hn::Mul(b, hn::Sub(hn::Set(d, 1.0f), hn::Mul(p.y, ny_q)));
    const BatchV rho2 = StdMax(hn::Add(hn::Mul(du_dx, du_dx), hn::Mul(dv_dx, dv_dx)),
                               hn::Add(hn::Mul(du_dy, du_dy), hn::Mul(dv_dy, dv_dy)));
    hn::Store(hn::Mul(half, LodLog2(rho2)), d, lod + j);
  }
  SampleMap(u, material.normal_map, in, s, t, lod, texel);
  // T2 = refract(Pb, Nb, 1 / 1.2), and the image's coordinate T2.xy 0.5 + 0.5.
  for (int j = 0; j < in.count; j += lanes) {
    BatchV nb[4];
    hn::LoadInterleaved4(d, &texel[j][0], nb[0], nb[1], nb[2], nb[3]);
    const Vec3V t2 =
        Refract(Load3(back, 0, j), {nb[0], nb[1], nb[2]}, hn::Set(d, 1.0f / kRefractiveIndex));
    hn::Store(hn::Add(hn::Mul(t2.x, half), half), d, s + j);
    hn::Store(hn::Add(hn::Mul(t2.y, half), half), d, t + j);
  }
  SampleMap(u, material.base_color_map, in, s, t, no_lod, texel);
  // The image plus the white highlight 0.8 max(reflect(Ld, N).E, 0)^100.
  for (int j = 0; j < in.count; j += lanes) {
    const Vec3V p = Load3(in.v, kPosition, j);
    const Vec3V e = Load3(eye, 0, j), n = Load3(normal, 0, j);
    const Vec3V light_direction = Normalize({hn::Sub(p.x, hn::Set(d, kRefractLightPosition.x)),
                                             hn::Sub(p.y, hn::Set(d, kRefractLightPosition.y)),
                                             hn::Sub(p.z, hn::Set(d, kRefractLightPosition.z))});
    const BatchV specular =
        hn::Mul(hn::Set(d, 0.8f), Pow100(StdMax(Dot(Reflect(light_direction, n), e), hn::Zero(d))));
    BatchV image[4];
    hn::LoadInterleaved4(d, &texel[j][0], image[0], image[1], image[2], image[3]);
    StoreDisplay(
        {hn::Add(image[0], specular), hn::Add(image[1], specular), hn::Add(image[2], specular)}, j,
        out);
  }
}

// glmark2's phong shader, in passes: the unit vectors, the diffuse and specular terms, then the
// colors. In passes of their own the CPU overlaps each vector's long chains of dependent
// operations (square roots, divisions, the power) with the next vector's; in one loop it would
// not.
HWY_INLINE void PhongBatch(const DrawUniforms& u, const ShadeInput& in, DisplayOut& out) {
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  alignas(64) float unit[9][shading::kShadeBatch];  // eye, light, normal
  for (int j = 0; j < in.count; j += lanes) {
    const Vec3V p = Load3(in.v, PhongShading::kPosition, j);
    const Vec3V eye = Normalize(Negate(p));
    const Vec3V light = Normalize(
        {hn::Sub(hn::Zero(d), p.x), hn::Sub(hn::Set(d, 1.0f), p.y), hn::Sub(hn::Zero(d), p.z)});
    Store3(eye, unit, 0, j), Store3(light, unit, 3, j);
    Store3(Normalize(Load3(in.v, 0, j)), unit, 6, j);
  }
  alignas(64) float terms[2][shading::kShadeBatch];  // specular, diffuse
  for (int j = 0; j < in.count; j += lanes) {
    const Vec3V eye = Load3(unit, 0, j), light = Load3(unit, 3, j), n = Load3(unit, 6, j);
    const Vec3V reflection = Reflect(Negate(light), n);
    hn::Store(hn::Mul(hn::Set(d, 0.8f), Pow100(StdMax(hn::Zero(d), Dot(reflection, eye)))), d,
              terms[0] + j);
    hn::Store(StdMax(hn::Zero(d), Dot(n, light)), d, terms[1] + j);
  }
  for (int j = 0; j < in.count; j += lanes) {
    const BatchV lit = hn::Mul(hn::Set(d, 0.8f), hn::Load(d, terms[1] + j));
    const BatchV base = hn::Add(hn::Load(d, terms[0] + j), hn::Set(d, 0.02f));
    StoreDisplay({hn::Add(base, hn::Mul(lit, hn::Set(d, u.material->base_color.r))),
                  hn::Add(base, hn::Mul(lit, hn::Set(d, u.material->base_color.g))),
                  hn::Add(base, hn::Mul(lit, hn::Set(d, u.material->base_color.b)))},
                 j, out);
  }
}

void ShadeGlmark2Batch(BatchShader shader, const DrawUniforms& u, const ShadeInput& in,
                       float (*rgba)[4]) {
  using Shader = BatchShader;
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  // Every shader's colour is shown as glmark2's RGBA8 buffer stores it, an 8-bit code per
  // channel: the codes are stored per vector, then decoded once for the batch (or, into a tile of
  // codes, stored as they are: StoreDisplay).
  DisplayOut display(*u.frame, in, rgba);
  // The shaders shaded in passes of their own: those that look textures up at coordinates they
  // compute (all lookups of a kind at once), and phong (for its chains of dependent operations).
  const bool in_passes =
      shader == Shader::shadow_ground || shader == Shader::refract || shader == Shader::phong;
  if (shader == Shader::shadow_ground) ShadowGround(u, in, display);
  if (shader == Shader::refract) RefractBatch(u, in, display);
  if (shader == Shader::phong) PhongBatch(u, in, display);
  // The unit normals of the shaders that start from them, in a loop of their own (as PhongBatch's
  // passes, for the square roots' and divisions' chains).
  alignas(64) float unit_normal[3][shading::kShadeBatch];
  const bool unit_normals =
      shader == Shader::blinn_phong_inf || shader == Shader::cel || shader == Shader::bump_poly;
  for (int j = 0; unit_normals && j < in.count; j += lanes) {
    Store3(Normalize(Load3(in.v, 0, j)), unit_normal, 0, j);
  }
  // bump's normal map: normalize(normal_matrix * (texel * 2 - 1)), so too.
  for (int j = 0; shader == Shader::bump_normals && j < in.count; j += lanes) {
    BatchV t[4];
    hn::LoadInterleaved4(d, &in.base_texel[j][0], t[0], t[1], t[2], t[3]);
    BatchV raw[3];
    for (int c = 0; c < 3; ++c) raw[c] = hn::Sub(hn::Mul(t[c], hn::Set(d, 2.0f)), hn::Set(d, 1.0f));
    const glm::mat3& m = u.normal_matrix;
    BatchV turned[3];
    for (int r = 0; r < 3; ++r) {
      turned[r] = hn::Add(
          hn::Add(hn::Mul(hn::Set(d, m[0][r]), raw[0]), hn::Mul(hn::Set(d, m[1][r]), raw[1])),
          hn::Mul(hn::Set(d, m[2][r]), raw[2]));
    }
    Store3(Normalize({turned[0], turned[1], turned[2]}), unit_normal, 0, j);
  }
  // Cel's light and view directions and the light's attenuation, so too.
  alignas(64) float cel[7][shading::kShadeBatch];
  for (int j = 0; shader == Shader::cel && j < in.count; j += lanes) {
    const Vec3V p = Load3(in.v, CelShading::kPosition, j);
    const Vec3V to_light{hn::Sub(hn::Set(d, 4.0f), p.x), hn::Sub(hn::Set(d, 3.0f), p.y),
                         hn::Sub(hn::Set(d, 1.0f), p.z)};
    Store3(Normalize(to_light), cel, 0, j);
    Store3(Normalize(Negate(p)), cel, 3, j);
    hn::Store(hn::Div(hn::Set(d, CelShading::kLightLength), hn::Sqrt(Dot(to_light, to_light))), d,
              cel[6] + j);
  }
  for (int j = 0; !in_passes && j < in.count; j += lanes) {
    switch (shader) {
      case Shader::basic_light: {
        const Vec3V light = Load3(in.v, 0, j);
        StoreDisplay(light, j, display);
        break;
      }
      case Shader::basic_light_texture: {
        BatchV t[4];
        hn::LoadInterleaved4(d, &in.base_texel[j][0], t[0], t[1], t[2], t[3]);
        const Vec3V light = Load3(in.v, 0, j);
        StoreDisplay({hn::Mul(t[0], light.x), hn::Mul(t[1], light.y), hn::Mul(t[2], light.z)}, j,
                     display);
        break;
      }
      case Shader::blinn_phong_inf: {
        const Vec3V n = Load3(unit_normal, 0, j);
        const BatchV diffuse =
            hn::Mul(hn::Set(d, 0.8f), StdMax(Dot(n, Set3(kLightDirection)), hn::Zero(d)));
        const BatchV specular =
            hn::Mul(hn::Set(d, 0.8f), Pow100(StdMax(Dot(n, Set3(kHalfVector)), hn::Zero(d))));
        const BatchV gray = hn::Add(hn::Set(d, 0.1f), specular);
        StoreDisplay({gray, gray, hn::Add(gray, diffuse)}, j, display);
        break;
      }
      case Shader::cel: {
        const Vec3V n = Load3(unit_normal, 0, j);
        const Vec3V l = Load3(cel, 0, j);
        const BatchV n_dot_l = Dot(n, l);
        const BatchV max_n_dot_l = StdMax(n_dot_l, hn::Zero(d));
        const BatchV attenuation = hn::Load(d, cel[6] + j);
        // Two-tone green, black where the surface turns away (mix(0.1, 0.4, max N.L)).
        BatchV green = hn::IfThenElse(hn::Ge(hn::Mul(attenuation, max_n_dot_l), hn::Set(d, 0.1f)),
                                      hn::Set(d, 0.6f), hn::Set(d, 0.3f));
        const Vec3V v = Load3(cel, 3, j);
        const BatchV edge =
            hn::Add(hn::Mul(hn::Set(d, 0.1f), hn::Sub(hn::Set(d, 1.0f), max_n_dot_l)),
                    hn::Mul(hn::Set(d, 0.4f), max_n_dot_l));
        const auto outline = hn::Lt(Dot(v, n), edge);
        green = hn::IfThenElseZero(hn::Not(outline), green);
        // The highlight: pow10(max(0, reflect(-l, n) . v)), thresholded.
        const Vec3V reflection = Reflect(Negate(l), n);
        const BatchV specular = Pow10(StdMax(hn::Zero(d), Dot(reflection, v)));
        const auto highlight = hn::And(hn::Gt(n_dot_l, hn::Zero(d)),
                                       hn::Gt(hn::Mul(attenuation, specular), hn::Set(d, 0.5f)));
        auto brighten = [&](BatchV c) HWY_ATTR {
          return hn::IfThenElse(highlight, hn::Add(hn::Set(d, 0.7f), hn::Mul(hn::Set(d, 0.3f), c)),
                                c);
        };
        StoreDisplay({brighten(hn::Zero(d)), brighten(green), brighten(hn::Zero(d))}, j, display);
        break;
      }
      case Shader::bump_poly:
      case Shader::bump_normals:  // (the normal map's normals found above)
        StoreDisplay(BumpLight(Load3(unit_normal, 0, j)), j, display);
        break;
      case Shader::refract_back_normal:
        StoreDisplay(Load3(in.v, 0, j), j, display);
        break;
      case Shader::shadow_ground:  // shaded above, in passes
      case Shader::refract:
      case Shader::phong:
        break;
    }
  }
  FinishDisplay(display, in.count);
}

}  // namespace facet::bench::glmark2::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::bench::glmark2 {

HWY_EXPORT(ShadeGlmark2Batch);

Glmark2BatchKernel glmark2_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(ShadeGlmark2Batch)[target];
}

}  // namespace facet::bench::glmark2
#endif  // HWY_ONCE
