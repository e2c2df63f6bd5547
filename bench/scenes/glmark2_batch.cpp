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

// shadow's ground (ShadowGroundShading), the whole batch: s = ShadowCoord / ShadowCoord.w per
// pixel, the light's depth at every s.xy in one lookup of the frame's sampler (NEAREST and
// clamped, as the map's sampler says), then grey 0.15 where that depth is nearer than
// s.z + bias, else 0.3.
HWY_INLINE void ShadowGround(const DrawUniforms& u, const ShadeInput& in, DisplayCodes codes) {
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  alignas(64) float s[3][shading::kShadeBatch], lod[shading::kShadeBatch] = {};
  alignas(64) float texel[shading::kShadeBatch][4];
  for (int j = 0; j < in.count; j += lanes) {
    const BatchV inverse_w = hn::Div(hn::Set(d, 1.0f), hn::Load(d, in.v[3] + j));
    for (int c = 0; c < 3; ++c) {
      hn::Store(hn::Mul(hn::Load(d, in.v[c] + j), inverse_w), d, s[c] + j);
    }
  }
  const TextureMap& map = u.material->base_color_map;
  u.frame->kernels->sample_at(*map.texture, map.sampler, s[0], s[1], lod, in.count, texel);
  const int padded = (in.count + lanes - 1) / lanes * lanes;
  std::fill(&texel[0][0] + 4 * in.count, &texel[0][0] + 4 * padded, 0.0f);  // scratch lanes
  for (int j = 0; j < in.count; j += lanes) {
    BatchV t[4];
    hn::LoadInterleaved4(d, &texel[j][0], t[0], t[1], t[2], t[3]);
    const BatchV s_z = hn::Add(hn::Load(d, s[2] + j), hn::Set(d, ShadowGroundShading::kDepthBias));
    const auto shadowed = hn::And(hn::Gt(hn::Load(d, in.v[3] + j), hn::Zero(d)), hn::Lt(t[0], s_z));
    const BatchV gray = hn::IfThenElse(shadowed, hn::Set(d, 0.15f), hn::Set(d, 0.3f));
    StoreDisplayCodes({gray, gray, gray}, j, codes);
  }
}

void ShadeGlmark2Batch(BatchShader shader, const DrawUniforms& u, const ShadeInput& in,
                       float (*rgba)[4]) {
  using Shader = BatchShader;
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  // Every shader's colour is shown as glmark2's RGBA8 buffer stores it, an 8-bit code per
  // channel: the codes are stored per vector, then decoded once for the batch.
  alignas(64) std::int32_t codes[3][shading::kShadeBatch];
  if (shader == Shader::shadow_ground) ShadowGround(u, in, codes);  // its lookups all at once
  for (int j = 0; shader != Shader::shadow_ground && j < in.count; j += lanes) {
    switch (shader) {
      case Shader::basic_light: {
        const Vec3V light = Load3(in.v, 0, j);
        StoreDisplayCodes(light, j, codes);
        break;
      }
      case Shader::basic_light_texture: {
        BatchV t[4];
        hn::LoadInterleaved4(d, &in.base_texel[j][0], t[0], t[1], t[2], t[3]);
        const Vec3V light = Load3(in.v, 0, j);
        StoreDisplayCodes({hn::Mul(t[0], light.x), hn::Mul(t[1], light.y), hn::Mul(t[2], light.z)},
                          j, codes);
        break;
      }
      case Shader::blinn_phong_inf: {
        const Vec3V n = Normalize(Load3(in.v, 0, j));
        const BatchV diffuse =
            hn::Mul(hn::Set(d, 0.8f), StdMax(Dot(n, Set3(kLightDirection)), hn::Zero(d)));
        const BatchV specular =
            hn::Mul(hn::Set(d, 0.8f), Pow100(StdMax(Dot(n, Set3(kHalfVector)), hn::Zero(d))));
        const BatchV gray = hn::Add(hn::Set(d, 0.1f), specular);
        StoreDisplayCodes({gray, gray, hn::Add(gray, diffuse)}, j, codes);
        break;
      }
      case Shader::phong: {
        const Vec3V p = Load3(in.v, PhongShading::kPosition, j);
        const Vec3V eye = Normalize(Negate(p));
        const Vec3V light = Normalize(
            {hn::Sub(hn::Zero(d), p.x), hn::Sub(hn::Set(d, 1.0f), p.y), hn::Sub(hn::Zero(d), p.z)});
        const Vec3V n = Normalize(Load3(in.v, 0, j));
        const Vec3V reflection = Reflect(Negate(light), n);
        const BatchV specular =
            hn::Mul(hn::Set(d, 0.8f), Pow100(StdMax(hn::Zero(d), Dot(reflection, eye))));
        const BatchV diffuse = StdMax(hn::Zero(d), Dot(n, light));
        const BatchV lit = hn::Mul(hn::Set(d, 0.8f), diffuse);
        const BatchV base = hn::Add(specular, hn::Set(d, 0.02f));
        StoreDisplayCodes({hn::Add(base, hn::Mul(lit, hn::Set(d, u.material->base_color.r))),
                           hn::Add(base, hn::Mul(lit, hn::Set(d, u.material->base_color.g))),
                           hn::Add(base, hn::Mul(lit, hn::Set(d, u.material->base_color.b)))},
                          j, codes);
        break;
      }
      case Shader::cel: {
        const Vec3V p = Load3(in.v, CelShading::kPosition, j);
        const Vec3V to_light{hn::Sub(hn::Set(d, 4.0f), p.x), hn::Sub(hn::Set(d, 3.0f), p.y),
                             hn::Sub(hn::Set(d, 1.0f), p.z)};
        const Vec3V n = Normalize(Load3(in.v, 0, j));
        const Vec3V l = Normalize(to_light);
        const BatchV n_dot_l = Dot(n, l);
        const BatchV max_n_dot_l = StdMax(n_dot_l, hn::Zero(d));
        const BatchV attenuation =
            hn::Div(hn::Set(d, CelShading::kLightLength), hn::Sqrt(Dot(to_light, to_light)));
        // Two-tone green, black where the surface turns away (mix(0.1, 0.4, max N.L)).
        BatchV green = hn::IfThenElse(hn::Ge(hn::Mul(attenuation, max_n_dot_l), hn::Set(d, 0.1f)),
                                      hn::Set(d, 0.6f), hn::Set(d, 0.3f));
        const Vec3V v = Normalize(Negate(p));
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
        StoreDisplayCodes({brighten(hn::Zero(d)), brighten(green), brighten(hn::Zero(d))}, j,
                          codes);
        break;
      }
      case Shader::bump_poly:
        StoreDisplayCodes(BumpLight(Normalize(Load3(in.v, 0, j))), j, codes);
        break;
      case Shader::bump_normals: {
        // normalize(normal_matrix * (texel * 2 - 1))
        BatchV t[4];
        hn::LoadInterleaved4(d, &in.base_texel[j][0], t[0], t[1], t[2], t[3]);
        BatchV raw[3];
        for (int c = 0; c < 3; ++c) {
          raw[c] = hn::Sub(hn::Mul(t[c], hn::Set(d, 2.0f)), hn::Set(d, 1.0f));
        }
        const glm::mat3& m = u.normal_matrix;
        BatchV turned[3];
        for (int r = 0; r < 3; ++r) {
          turned[r] = hn::Add(
              hn::Add(hn::Mul(hn::Set(d, m[0][r]), raw[0]), hn::Mul(hn::Set(d, m[1][r]), raw[1])),
              hn::Mul(hn::Set(d, m[2][r]), raw[2]));
        }
        StoreDisplayCodes(BumpLight(Normalize({turned[0], turned[1], turned[2]})), j, codes);
        break;
      }
      case Shader::shadow_ground:  // shaded above
        break;
    }
  }
  DecodeDisplayCodes(codes, in.count, u.frame->display_referred, in.rgba_row_stride, rgba);
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
