// The lit shading models with specular light: Gouraud, Phong, Blinn-Phong and physically
// based (Cook-Torrance, metallic-roughness). See models.hpp for what a model provides.
#pragma once

#include "shading/brdf.hpp"
#include "shading/environment.hpp"
#include "shading/environment_light.hpp"
#include "shading/kernels.hpp"
#include "shading/models.hpp"

namespace facet::shading {

// Specular color of a Phong-family material at this fragment (factor x specular map). The map
// and reflectivity tests below are runtime branches on constants of the draw
// (BENCHMARKS.md, "Per-draw constants").
inline glm::vec3 specular_color(const Fragment& f, const DrawUniforms& u) {
  glm::vec3 s = u.material->specular_color;
  if (u.material->specular_map) s *= glm::vec3(sample_map(u.material->specular_map, f));
  return s;
}

// Mixes in the environment's mirror reflection for materials with reflectivity.
inline glm::vec3 reflect_environment(glm::vec3 color, const SurfacePoint& s,
                                     const DrawUniforms& u) {
  float r = u.material->reflectivity;
  if (r <= 0.0f || !u.frame->lighting->environment.reflections) return color;
  glm::vec3 mirror = glm::reflect(-s.view, s.normal);
  return glm::mix(color, environment_radiance(u.frame->lighting->environment, mirror), r);
}

// Phong (kBlinn = false) or Blinn-Phong (true), per pixel: ambient + diffuse + specular.
template <bool kBlinn>
struct PhongShadingT : BatchForm<kBlinn ? BatchModel::blinn_phong : BatchModel::phong>,
                       LightsBackFaces {
  static constexpr int kVaryings = kSurfaceVaryingsWithTangent;
  static constexpr int kNormalSlot = shading::kNormalSlot;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    surface_vertex<kVaryings>(in, u, out);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    SurfacePoint s = surface_point<true>(f, u);
    glm::vec3 albedo(s.albedo), spec = specular_color(f, u);
    float shininess = u.material->shininess;
    glm::vec3 color = albedo * u.frame->ambient;
    for (int i = 0; i < u.frame->light_count; ++i) {
      const LightData& light = u.frame->lights[i];
      IncidentLight in = incident(light, s.position);
      float n_dot_l = glm::dot(s.normal, in.direction);
      if (n_dot_l <= 0.0f) continue;
      in.radiance = received_radiance(light, in, s.position, s.normal);
      float highlight = kBlinn ? blinn_phong_specular(s.normal, s.view, in.direction, shininess)
                               : phong_specular(s.normal, s.view, in.direction, shininess);
      color += in.radiance * (albedo * n_dot_l + spec * highlight);
    }
    color = reflect_environment(color, s, u);
    return {color + emission(f, u), s.albedo.a};
  }
};
using PhongShading = PhongShadingT<false>;
using BlinnPhongShading = PhongShadingT<true>;

// Gouraud: Blinn-Phong evaluated at the vertices, shadows included (a shadow is sampled at
// each vertex, not per pixel); the pixel interpolates diffuse and specular light. GouraudLight is
// what both layouts share: the lighting, by the SIMD kernels of vertex_batch.hpp alone, writing
// the diffuse light at slots kDiffuse..kDiffuse+2 and the specular light at the next three, after
// the surface layout's texture coordinate and color if kWithSurface.
template <int kDiffuse, bool kWithSurface>
struct GouraudLight {
  static constexpr int kDiffuseSlot = kDiffuse;
  static constexpr int kSpecularSlot = kDiffuse + 3;
  static constexpr int kNormalSlot = -1;  // lit per vertex; see face_without_normals()
  static constexpr GouraudLayout kLayout{kDiffuse, kWithSurface};
  // The vertex stage lights every draw's vertices a run at a time.
  static bool batch_vertices(const DrawUniforms&) { return true; }
  static void vertex_batch(const DrawUniforms& u, const VertexBatchInput& in,
                           float (*out)[kVertexBatch]) {
    u.frame->kernels->gouraud_vertex_batch(u, in, kLayout, out);
  }
  // vertex(), every model's one-vertex form (models.hpp): the batch of one. (The vertex stage
  // itself takes the batch form for every draw.)
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    alignas(64) float normal[3][kVertexBatch] = {{in.normal.x}, {in.normal.y}, {in.normal.z}};
    alignas(64) float varyings[kSpecularSlot + 3][kVertexBatch];
    vertex_batch(u, {1, &in.position, {normal[0], normal[1], normal[2]}, &in.texcoord, &in.color},
                 varyings);
    for (int k = 0; k < kSpecularSlot + 3; ++k) out[k] = varyings[k][0];
  }
  // A mesh without normals is lit per triangle with its face normal at its centre: the light of
  // that one point at its three corners.
  static void face_without_normals(glm::vec3 normal, glm::vec3 centre, const DrawUniforms& u,
                                   float* v[3]) {
    alignas(64) float light[6][kVertexBatch];
    u.frame->kernels->gouraud_light_batch(u, {1, &centre, &normal}, light);
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 6; ++k) v[i][kDiffuseSlot + k] = light[k][0];
    }
  }
  // The pixel: albedo x interpolated diffuse light + specular light + emission.
  static glm::vec4 lit(glm::vec4 albedo, const Fragment& f, const DrawUniforms& u) {
    glm::vec3 color = glm::vec3(albedo) * load3(f.v + kDiffuseSlot) + load3(f.v + kSpecularSlot);
    return {color + emission(f, u), albedo.a};
  }
};

// Gouraud with a texture or vertex colors. Layout: texture coordinate and color as in the
// surface layout (so sample_map works), then diffuse light (6-8) and specular light (9-11).
struct GouraudShading : GouraudLight<kGouraudDiffuseSlot, true>, BatchForm<BatchModel::gouraud> {
  static constexpr int kVaryings = 12;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
  static_assert(kColorSlot + 4 <= kDiffuseSlot && kSpecularSlot + 3 == kVaryings);
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    glm::vec4 albedo = load4(f.v + kColorSlot);
    if (u.material->base_color_map) albedo *= base_color_texel(f, u);
    return lit(albedo, f, u);
  }
};

// Gouraud for a draw whose surface color is one constant: no base color or emissive map, no
// vertex colors (pipeline_for in pipeline/record/pipeline_table.cpp decides). It interpolates only
// the light, 6 varyings instead of 12: half the plane set-up and interpolation of scenes of many
// small triangles (million), and the color is the material's exactly, not an interpolated constant.
struct ConstantColorGouraudShading : GouraudLight<kConstantGouraudDiffuseSlot, false>,
                                     BatchForm<BatchModel::constant_gouraud> {
  static constexpr int kVaryings = 6;
  static_assert(kSpecularSlot + 3 == kVaryings);
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    return lit(u.material->base_color, f, u);
  }
};

// The light a PBR surface takes from the environment (environment_light.hpp): the irradiance
// through the diffuse albedo, and the split sum's specular from the mirror direction's radiance
// blurred by roughness, moving toward the irradiance around that direction (a cosine lobe, the
// widest GGX lobe's shape) as the surface roughens.
inline glm::vec3 environment_light(const PbrSurface& surface, glm::vec3 f0, const SurfacePoint& s,
                                   const DrawUniforms& u) {
  const IrradianceHarmonics& light = *u.frame->environment_light;
  const Environment& environment = u.frame->lighting->environment;
  const glm::vec3 diffuse =
      surface.albedo * (1.0f - surface.metallic) * irradiance(light, s.normal) * (1.0f / kPi);
  const glm::vec3 mirror = glm::reflect(-s.view, s.normal);
  const float spread = surface.roughness * surface.roughness;
  const glm::vec3 seen =
      glm::mix(environment_radiance(environment, mirror, surface.roughness * 8.0f),
               irradiance(light, mirror) * (1.0f / kPi), spread);
  const SpecularIntegral brdf = specular_integral(glm::dot(s.normal, s.view), surface.roughness);
  return diffuse + seen * (f0 * brdf.scale + brdf.bias);
}

// Physically based: Cook-Torrance (GGX, Smith, Schlick), metallic-roughness, occlusion,
// emission, and the environment's light (image-based lighting) or, when reflections are on,
// its mirror image.
// Lights are scaled by pi so a white Lambertian surface under a unit light looks as bright as
// in the Lambert model (the "punctual light" convention of glTF viewers).
struct PbrShading : LightsBackFaces {
  static constexpr int kVaryings = kSurfaceVaryingsWithTangent;
  static constexpr int kNormalSlot = shading::kNormalSlot;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    surface_vertex<kVaryings>(in, u, out);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const Material& m = *u.material;
    SurfacePoint s = surface_point<true>(f, u);
    PbrSurface surface{glm::vec3(s.albedo), m.metallic, m.roughness};
    if (m.metallic_roughness_map) {
      glm::vec4 mr = sample_map(m.metallic_roughness_map, f);
      surface.roughness *= mr.g;  // glTF packing: roughness in green, metallic in blue
      surface.metallic *= mr.b;
    }
    float occlusion = 1.0f;
    if (m.occlusion_map) {
      occlusion = 1.0f + m.occlusion_strength * (sample_map(m.occlusion_map, f).r - 1.0f);
    }
    glm::vec3 color(0.0f);
    for (int i = 0; i < u.frame->light_count; ++i) {
      const LightData& light = u.frame->lights[i];
      IncidentLight in = incident(light, s.position);
      float n_dot_l = glm::dot(s.normal, in.direction);
      if (n_dot_l <= 0.0f) continue;
      in.radiance = received_radiance(light, in, s.position, s.normal);
      color +=
          cook_torrance(surface, s.normal, s.view, in.direction) * in.radiance * (n_dot_l * kPi);
    }
    glm::vec3 f0 = glm::mix(glm::vec3(0.04f), surface.albedo, surface.metallic);
    glm::vec3 diffuse_albedo = surface.albedo * (1.0f - surface.metallic);
    glm::vec3 ambient = u.frame->ambient * (diffuse_albedo + f0 * 0.5f);
    if (u.frame->environment_light) {
      ambient = environment_light(surface, f0, s, u);
    } else if (u.frame->lighting->environment.reflections) {
      // Split-sum-free approximation: the mirror direction, blurred by roughness (mip level).
      glm::vec3 mirror = glm::reflect(-s.view, s.normal);
      glm::vec3 fresnel = fresnel_schlick(f0, glm::dot(s.normal, s.view));
      float blur = surface.roughness * 8.0f;
      ambient += environment_radiance(u.frame->lighting->environment, mirror, blur) * fresnel *
                 (1.0f - surface.roughness * 0.7f);
    }
    color += ambient * occlusion;
    return {color + emission(f, u), s.albedo.a};
  }
};

}  // namespace facet::shading
