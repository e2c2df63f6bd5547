// glmark2's shaders (2023.01, /usr/share/glmark2/shaders) as facet shading models, formula for
// formula (GLMARK2_SCENES.md §2), for the glmark2-equivalent benchmark scenes. See
// shading/models.hpp for what a shading model provides. Each model's vertex stage is here; its
// pixels are shaded by its SIMD kernel alone (glmark2_batch.cpp, through BatchForm), which
// computes the formula each model's comment gives, then shows the color as glmark2's RGBA8
// UNORM buffer stores it: clamped to [0, 1] and rounded to the nearest of 256 codes, returned as
// a display value (shading/models.hpp).
//
// Spaces: the scenes put facet's camera at the origin looking down -Z, so facet's world space
// is glmark2's eye space: u.model is glmark2's ModelView, u.normal_matrix the rotation part of
// it (= glmark2's NormalMatrix applied to (n, 1), §1.3), and VertexInput::normal is already
// normalize(NormalMatrix * n). Lights given in eye space are used as they are.
//
// glmark2 has no fog, and neither have these models: the scenes draw them without (and check it,
// glmark2_scenes.cpp). The textured ones need their map: the scenes refuse to build without it.
#pragma once

#include <algorithm>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scenes/glmark2_batch.hpp"
#include "shading/models.hpp"
#include "shading/surface.hpp"
#include "shading/uniforms.hpp"
#include "shading/vertex_batch.hpp"

namespace facet::bench::glmark2 {

using shading::DrawUniforms;
using shading::VertexInput;

// The default light "position" (20, 20, 10), used as a direction: normalize(20, 20, 10).
inline const glm::vec3 kLightDirection{2.0f / 3.0f, 2.0f / 3.0f, 1.0f / 3.0f};
// Blinn half vector with the viewer at infinity: normalize(L + (0, 0, 1)) = (1, 1, 2) / sqrt 6.
inline const glm::vec3 kHalfVector{0.40824829f, 0.40824829f, 0.81649658f};

// light-basic.vert/.frag (build, gouraud): Lambert per vertex, no ambient, no specular.
// Color = max(N.L, 0) x MaterialDiffuse (the material's base colour); the pixel shows the
// interpolated colour.
struct BasicLightShading : BatchForm<BatchShader::basic_light>, shading::DisplayReferred {
  static constexpr int kVaryings = 3;
  static constexpr int kNormalSlot = -1;  // the scenes' meshes carry normals
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    const float diffuse = std::max(glm::dot(in.normal, kLightDirection), 0.0f);
    shading::store(out, diffuse * glm::vec3(u.material->base_color));
  }
};

// light-basic.vert + light-basic-tex.frag (texture): the per-vertex light above times the
// texel of the material's base colour map (its sampler: bilinear or trilinear, clamped), which
// the draw must have. Layout: colour (3), texture coordinate (2).
struct BasicLightTextureShading : BatchForm<BatchShader::basic_light_texture>,
                                  shading::DisplayReferred {
  static constexpr int kVaryings = 5;
  static constexpr int kNormalSlot = -1;
  static constexpr int kTexcoord = 3;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    BasicLightShading::vertex(in, u, out);
    shading::store(out + kTexcoord, in.texcoord);
  }
  static constexpr int kBaseColorTexcoord = kTexcoord;  // sampled ahead, a batch at a time
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
// of the shader, not uniforms. With N = normalize(interpolated normal):
//   rgb = 0.1 + 0.8 max(N.L, 0) (0, 0, 1) + 0.8 max(N.H, 0)^100 (1, 1, 1).
struct BlinnPhongInfShading : InterpolatedNormal,
                              BatchForm<BatchShader::blinn_phong_inf>,
                              shading::DisplayReferred {};

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
// With P the eye position, E = normalize(-P), Ld = normalize((0, 1, 0) - P),
// N = normalize(interpolated normal) and R = reflect(-Ld, N):
//   rgb = 0.8 max(R.E, 0)^100 + 0.02 + 0.8 max(N.Ld, 0) x MaterialDiffuse.
struct PhongShading : EyeNormalPosition, BatchForm<BatchShader::phong>, shading::DisplayReferred {};

// light-cel.frag: its own light at eye Lp = (4, 3, 1), two-tone green, a black outline where
// the surface turns away from the viewer, and a thresholded white highlight. With P the eye
// position, v = Lp - P, N = normalize(interpolated normal), L = normalize(v), d = N.L,
// att = |(4, 3, 1, 1)| / |v|, V = normalize(-P) and R = reflect(-L, N):
//   c = (0, 0.6, 0) if att max(d, 0) >= 0.1, else (0, 0.3, 0);
//   c = black if V.N < mix(0.1, 0.4, max(d, 0));
//   c = 0.7 + 0.3 c if d > 0 and att max(R.V, 0)^10 > 0.5.
struct CelShading : EyeNormalPosition, BatchForm<BatchShader::cel>, shading::DisplayReferred {
  static constexpr float kLightLength = 5.19615242f;  // length(vec4(4, 3, 1, 1)) = sqrt 27
};

// bump-normals.vert/.frag: the normal comes from the material's base colour map, which holds
// OBJECT-space normals as rgb = n * 0.5 + 0.5 (sampled NEAREST), and is turned to eye space
// per pixel by the NormalMatrix: N = normalize(NormalMatrix (texel * 2 - 1)). White
// Blinn-Phong, ambient 0.1, diffuse 0.8, specular 0.8 x 0.2:
//   rgb = 0.1 + 0.8 max(N.L, 0) + 0.16 max(N.H, 0)^100, grey.
// The mesh needs no normals; the draw must have the map.
struct BumpNormalsShading : BatchForm<BatchShader::bump_normals>, shading::DisplayReferred {
  static constexpr int kVaryings = 2;
  static constexpr int kNormalSlot = -1;
  static constexpr int kBaseColorTexcoord = 0;  // sampled ahead, a batch at a time
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    shading::store(out, in.texcoord);
  }
};

// bump-poly.vert/.frag (high-poly): the same light as bump-normals with
// N = normalize(interpolated vertex normal).
struct BumpPolyShading : InterpolatedNormal,
                         BatchForm<BatchShader::bump_poly>,
                         shading::DisplayReferred {};

// glmark2's LightMatrix (shadow, refract) for a light at `light`: B P lookAt(light -> 0, up y),
// P the frame's projection and B the bias matrix, clip space's [-1, 1] to [0, 1] on x, y and z.
inline glm::mat4 light_matrix(const glm::vec3& light, const DrawUniforms& u) {
  const glm::mat4 bias{0.5f, 0.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.0f, 0.0f,
                       0.0f, 0.0f, 0.5f, 0.0f, 0.5f, 0.5f, 0.5f, 1.0f};
  return bias * u.frame->projection *
         glm::lookAt(light, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

// shadow's light (0, 3, 2), a direction here as in light-basic: normalize(0, 3, 2).
inline const glm::vec3 kShadowLightDirection{0.0f, 0.83205029f, 0.55470020f};
inline const glm::vec3 kShadowLightPosition{0.0f, 3.0f, 2.0f};

// light-basic.vert/.frag with shadow's light (the horse of shadow): max(N.L, 0) x
// MaterialDiffuse per vertex, L = normalize(0, 3, 2).
struct ShadowHorseShading : BatchForm<BatchShader::basic_light>, shading::DisplayReferred {
  static constexpr int kVaryings = 3;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    const float diffuse = std::max(glm::dot(in.normal, kShadowLightDirection), 0.0f);
    shading::store(out, diffuse * glm::vec3(u.material->base_color));
  }
};

// shadow.vert/.frag (the ground of shadow): ShadowCoord = B P lookAt((0, 3, 2) -> 0, up y)
// (x, y, 0, 1) of the quad's UNTRANSFORMED vertex (neither the ground's ModelView nor the
// horse's turn is in it: glmark2 projects the depth map as if the quad stood upright at z = 0,
// GLMARK2_SCENES.md §2.6): light_matrix() of the vertex. Per pixel, with
// s = ShadowCoord / ShadowCoord.w and d the light's window depth at s.xy (the material's base
// colour map, the light pass's depth texture, sampled NEAREST and clamped):
//   rgb = 0.3 x (0.5 if ShadowCoord.w > 0 and d < s.z + 0.1505, else 1), grey.
// Facet's window depth is GL's, z_ndc x 0.5 + 0.5 (to_screen, pipeline/reference.hpp), and B maps z
// the same way, so d and s.z are on one scale, as in glmark2. The draw must have the map.
struct ShadowGroundShading : BatchForm<BatchShader::shadow_ground>, shading::DisplayReferred {
  static constexpr int kVaryings = 4;  // ShadowCoord
  static constexpr int kNormalSlot = -1;
  static constexpr float kDepthBias = 0.1505f;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    shading::store(out, light_matrix(kShadowLightPosition, u) *
                            glm::vec4(in.position.x, in.position.y, 0.0f, 1.0f));
  }
};

// refract's light (1, 1, 2), in eye space: the pass into the distance target looks from it at
// the origin, and the bunny's highlight comes from it. The bunny's refractive index is 1.2.
inline const glm::vec3 kRefractLightPosition{1.0f, 1.0f, 2.0f};
inline constexpr float kRefractiveIndex = 1.2f;

// depth.vert/.frag (refract's pass into the distance target, back faces only): the interpolated
// OBJECT-space normal, stored clamped to [0, 1] as an 8-bit code per channel, alpha 1 (the
// scene reads the target's codes back as data: RenderTextureOptions::srgb_texture false).
// The draw only turns the model (by Ry(θ)), so the object normal is the world normal turned
// back: transpose(normal_matrix) x normal.
struct RefractBackNormalShading : BatchForm<BatchShader::refract_back_normal>,
                                  shading::DisplayReferred {
  static constexpr int kVaryings = 3;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    shading::store(out, glm::transpose(u.normal_matrix) * in.normal);
  }
};

// light-refract.vert/.frag (refract's bunny). Varyings (world space is eye space: the scene's
// view is the identity): the eye normal N, the eye position P
// (ModelView x p) and MapCoord = light_matrix() x p of the OBJECT-space p (the bunny's turn is
// not in it, as in glmark2).
// The material's maps carry the shader's three textures: base_color_map the image (nasa1,
// bilinear), normal_map the back faces' normals (the distance target's color, trilinear),
// occlusion_map their depth seen from the light (its depth texture, nearest), all clamped.
// Per pixel, with refract(I, N, e) = 0 if k = 1 - e e (1 - (N.I)^2) < 0, else
// e I - (e (N.I) + sqrt k) N, and reflect(I, N) = I - 2 (N.I) N:
//   E = normalize(-P), N = normalize(N), T1 = refract(E, N, 1.2),
//   m = MapCoord.xyz / MapCoord.w + T1, dist = depth at m.xy 0.5 + 0.5 (the bias a second time),
//   Pb = P + T1 dist, Nb = normals at Pb.xy 0.5 + 0.5 (not remapped to [-1, 1]),
//   T2 = refract(Pb, Nb, 1 / 1.2) (neither normalized), texel = image at T2.xy 0.5 + 0.5,
//   Ld = normalize(P - (1, 1, 2)), s = max(reflect(Ld, N).E, 0)^100,
//   rgb = texel.rgb + 0.8 s.
// OpenGL takes Nb's level of detail from the screen-space derivatives of Pb.xy across a 2x2
// quad. The kernel shades packed pixels, which have no neighbours, so it differentiates the
// part of Pb that is the surface point: the footprint of a pixel on the plane through P normal
// to N (the refracted offset T1 dist, smooth where the surface is, is left out).
struct RefractShading : BatchForm<BatchShader::refract>, shading::DisplayReferred {
  static constexpr int kVaryings = 10;
  static constexpr int kNormalSlot = -1;
  static constexpr int kPosition = 3;
  static constexpr int kMapCoord = 6;
  static void vertex_batch(const DrawUniforms& u, const shading::VertexBatchInput& in,
                           float (*out)[shading::kVertexBatch]) {
    const glm::mat4 map_matrix = light_matrix(kRefractLightPosition, u);
    for (int n = 0; n < in.count; ++n) {
      const glm::vec4 p(in.positions[n], 1.0f);
      const glm::vec3 eye = glm::vec3(u.model * p);
      const glm::vec4 map_coord = map_matrix * p;
      for (int k = 0; k < 3; ++k) {
        out[k][n] = in.normal[k][n];
        out[kPosition + k][n] = eye[k];
      }
      for (int k = 0; k < 4; ++k) out[kMapCoord + k][n] = map_coord[k];
    }
  }
};

}  // namespace facet::bench::glmark2
