// glmark2's shaders (2023.01, /usr/share/glmark2/shaders) as facet shading models, formula for
// formula (GLMARK2_SCENES.md §2), for the glmark2-equivalent benchmark scenes. See
// shading/models.hpp for what a shading model provides.
//
// Spaces: the scenes put facet's camera at the origin looking down -Z, so facet's world space
// is glmark2's eye space: u.model is glmark2's ModelView, u.normal_matrix the rotation part of
// it (= glmark2's NormalMatrix applied to (n, 1), §1.3), and VertexInput::normal is already
// normalize(NormalMatrix * n). Lights given in eye space are used as they are.
#pragma once

#include <algorithm>
#include <glm/glm.hpp>

#include "scenes/glmark2_batch.hpp"
#include "shading/fragment.hpp"
#include "shading/models.hpp"
#include "shading/surface.hpp"
#include "shading/uniforms.hpp"

namespace facet::bench::glmark2 {

using shading::DrawUniforms;
using shading::Fragment;
using shading::VertexInput;

// The default light "position" (20, 20, 10), used as a direction: normalize(20, 20, 10).
inline const glm::vec3 kLightDirection{2.0f / 3.0f, 2.0f / 3.0f, 1.0f / 3.0f};
// Blinn half vector with the viewer at infinity: normalize(L + (0, 0, 1)) = (1, 1, 2) / sqrt 6.
inline const glm::vec3 kHalfVector{0.40824829f, 0.40824829f, 0.81649658f};

// glmark2 writes its colour to an RGBA8 UNORM buffer: clamp, then round to the nearest of 256
// codes. The fragment returns that code as a display value (models.hpp's display_value, as
// facet's debug views do): the linear value whose sRGB code is exactly that UNORM code, or in
// frames of display values alone the code / 255. Either way the stored bytes are glmark2's.
inline glm::vec4 unorm8_output(glm::vec3 rgb, const DrawUniforms& u) {
  return shading::display_value(rgb, u);
}

// pow(x, 100) and pow(x, 10) for x in [0, 1] by repeated squaring: x^100 = x^64 x^32 x^4.
inline float pow100(float x) {
  const float x2 = x * x, x4 = x2 * x2, x8 = x4 * x4, x16 = x8 * x8, x32 = x16 * x16;
  return x32 * x32 * x32 * x4;
}
inline float pow10(float x) {
  const float x2 = x * x, x8 = x2 * x2 * x2 * x2;
  return x8 * x2;
}

// light-basic.vert/.frag (build, gouraud): Lambert per vertex, no ambient, no specular.
// Color = max(N.L, 0) x MaterialDiffuse (the material's base colour); the pixel shows it.
// With its batch form, whole blocks go straight into the tile and small triangles' pixels wait
// to be shaded together, instead of one pixel at a time with fragment().
struct BasicLightShading : BatchForm<BatchShader::basic_light>, shading::DisplayReferred {
  static constexpr int kVaryings = 3;
  static constexpr int kNormalSlot = -1;  // the scenes' meshes carry normals
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    const float diffuse = std::max(glm::dot(in.normal, kLightDirection), 0.0f);
    shading::store(out, diffuse * glm::vec3(u.material->base_color));
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    return unorm8_output(shading::load3(f.v), u);
  }
};

// light-basic.vert + light-basic-tex.frag (texture): the per-vertex light above times the
// texel of the material's base colour map (its sampler: bilinear or trilinear, clamped).
// Layout: colour (3), texture coordinate (2).
struct BasicLightTextureShading : BatchForm<BatchShader::basic_light_texture>,
                                  shading::DisplayReferred {
  static constexpr int kVaryings = 5;
  static constexpr int kNormalSlot = -1;
  static constexpr int kTexcoord = 3;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    BasicLightShading::vertex(in, u, out);
    shading::store(out + kTexcoord, in.texcoord);
  }
  static constexpr int kBaseColorTexcoord = kTexcoord;
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const glm::vec4 texel = shading::base_color_texel(f, u, kTexcoord);
    return unorm8_output(glm::vec3(texel) * shading::load3(f.v), u);
  }
};

// The vertex stage of the shaders that light per pixel with the object-space normal: it is the
// only varying. Shared by blinn-phong-inf and bump-poly.
struct InterpolatedNormal {
  static constexpr int kVaryings = 3;
  static constexpr int kNormalSlot = 0;
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    shading::store(out, in.normal);
  }
};

// light-advanced.vert/.frag (blinn-phong-inf): per pixel, directional light and viewer at
// infinity; ambient 0.1, diffuse 0.8 x blue, specular 0.8 x white, shininess 100 — constants
// of the shader, not uniforms.
struct BlinnPhongInfShading : InterpolatedNormal,
                              BatchForm<BatchShader::blinn_phong_inf>,
                              shading::DisplayReferred {
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const glm::vec3 n = glm::normalize(shading::load3(f.v));
    const float diffuse = 0.8f * std::max(glm::dot(n, kLightDirection), 0.0f);
    const float specular = 0.8f * pow100(std::max(glm::dot(n, kHalfVector), 0.0f));
    return unorm8_output(glm::vec3(0.1f + specular, 0.1f + specular, 0.1f + specular + diffuse), u);
  }
};

// light-phong.vert: the eye-space normal and position (ModelView x p; w is 1, MV is affine).
// Layout: normal (3), eye position (3). Shared by phong and cel.
struct EyeNormalPosition {
  static constexpr int kVaryings = 6;
  static constexpr int kNormalSlot = 0;
  static constexpr int kPosition = 3;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    shading::store(out, in.normal);
    shading::store(out + kPosition, glm::vec3(u.model * glm::vec4(in.position, 1.0f)));
  }
};

// light-phong.frag with num-lights=1: a point light at eye (0, 1, 0) with diffuse colour 0.8,
// MaterialDiffuse the material's base colour; ambient 0.1 x 0.2, specular 0.8, shininess 100.
struct PhongShading : EyeNormalPosition, BatchForm<BatchShader::phong>, shading::DisplayReferred {
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const glm::vec3 p = shading::load3(f.v + kPosition);
    const glm::vec3 eye_direction = glm::normalize(-p);
    const glm::vec3 light_direction = glm::normalize(glm::vec3(0.0f, 1.0f, 0.0f) - p);
    const glm::vec3 n = glm::normalize(shading::load3(f.v));
    const glm::vec3 reflection = glm::reflect(-light_direction, n);
    const float specular = 0.8f * pow100(std::max(0.0f, glm::dot(reflection, eye_direction)));
    const float diffuse = std::max(0.0f, glm::dot(n, light_direction));
    return unorm8_output(
        glm::vec3(specular + 0.02f) + 0.8f * diffuse * glm::vec3(u.material->base_color), u);
  }
};

// light-cel.frag: its own light at eye (4, 3, 1), two-tone green, a black outline where the
// surface turns away from the viewer, and a thresholded white highlight.
struct CelShading : EyeNormalPosition, BatchForm<BatchShader::cel>, shading::DisplayReferred {
  static constexpr float kLightLength = 5.19615242f;  // length(vec4(4, 3, 1, 1)) = sqrt 27
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const glm::vec3 p = shading::load3(f.v + kPosition);
    const glm::vec3 vertex_light = glm::vec3(4.0f, 3.0f, 1.0f) - p;
    const glm::vec3 n = glm::normalize(shading::load3(f.v));
    const glm::vec3 l = glm::normalize(vertex_light);
    const float n_dot_l = glm::dot(n, l);
    const float max_n_dot_l = std::max(n_dot_l, 0.0f);
    const float attenuation = kLightLength / glm::length(vertex_light);
    glm::vec3 color{0.0f, 0.3f, 0.0f};
    if (attenuation * max_n_dot_l >= 0.1f) color = {0.0f, 0.6f, 0.0f};
    const glm::vec3 v = glm::normalize(-p);
    if (glm::dot(v, n) < glm::mix(0.1f, 0.4f, max_n_dot_l)) color = glm::vec3(0.0f);
    const float specular = pow10(std::max(0.0f, glm::dot(glm::reflect(-l, n), v)));
    if (n_dot_l > 0.0f && attenuation * specular > 0.5f) color = 0.7f + 0.3f * color;
    return unorm8_output(color, u);
  }
};

// bump-normals / bump-poly: white Blinn-Phong, ambient 0.1, diffuse 0.8, specular 0.8 x 0.2.
inline glm::vec4 bump_light(glm::vec3 n, const DrawUniforms& u) {
  const float diffuse = 0.8f * std::max(glm::dot(n, kLightDirection), 0.0f);
  const float specular = 0.16f * pow100(std::max(glm::dot(n, kHalfVector), 0.0f));
  return unorm8_output(glm::vec3(0.1f + diffuse + specular), u);
}

// bump-normals.vert/.frag: the normal comes from the material's base colour map, which holds
// OBJECT-space normals as rgb = n * 0.5 + 0.5 (sampled NEAREST), and is turned to eye space
// per pixel by the NormalMatrix. The mesh needs no normals.
struct BumpNormalsShading : BatchForm<BatchShader::bump_normals>, shading::DisplayReferred {
  static constexpr int kVaryings = 2;
  static constexpr int kNormalSlot = -1;
  static constexpr int kBaseColorTexcoord = 0;  // sampled ahead, a batch at a time
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    shading::store(out, in.texcoord);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const glm::vec3 raw{shading::base_color_texel(f, u, 0)};
    return bump_light(glm::normalize(u.normal_matrix * (raw * 2.0f - 1.0f)), u);
  }
};

// bump-poly.vert/.frag (high-poly): the same light with the interpolated vertex normal.
struct BumpPolyShading : InterpolatedNormal,
                         BatchForm<BatchShader::bump_poly>,
                         shading::DisplayReferred {
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    return bump_light(glm::normalize(shading::load3(f.v)), u);
  }
};

}  // namespace facet::bench::glmark2
