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
  return mix_reflection(u.frame->lighting->environment, r, color, s.view, s.normal);
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
// the lighting both layouts share: the diffuse light at slots kDiffuse..kDiffuse+2, the specular
// light at the next three, after the surface layout's texture coordinate and color if kWithSurface.
template <int kDiffuse, bool kWithSurface>
struct GouraudLight {
  static constexpr int kDiffuseSlot = kDiffuse;
  static constexpr int kSpecularSlot = kDiffuse + 3;
  static constexpr int kNormalSlot = -1;  // lit in vertex(); see face_without_normals()
  static constexpr GouraudLayout kLayout{kDiffuse, kWithSurface};
  static void light_vertex(glm::vec3 position, glm::vec3 normal, const DrawUniforms& u,
                           float* out) {
    glm::vec3 view = safe_normalize(u.frame->eye - position);
    glm::vec3 diffuse = u.frame->ambient, specular(0.0f);
    for (int i = 0; i < u.frame->light_count; ++i) {
      const LightData& light = u.frame->lights[i];
      IncidentLight in = incident(light, position);
      float n_dot_l = glm::dot(normal, in.direction);
      if (n_dot_l <= 0.0f) continue;
      in.radiance = received_radiance(light, in, position, normal);
      diffuse += in.radiance * n_dot_l;
      specular += in.radiance * u.material->specular_color *
                  blinn_phong_specular(normal, view, in.direction, u.material->shininess);
    }
    store(out + kDiffuseSlot, diffuse);
    store(out + kSpecularSlot, specular);
  }
  // vertex() for a run of vertices at once, with SIMD (vertex_batch.hpp), for draws lit by
  // directional lights only.
  static bool batch_vertices(const DrawUniforms& u) { return gouraud_batches_vertices(u); }
  static void vertex_batch(const DrawUniforms& u, const VertexBatchInput& in,
                           float (*out)[kVertexBatch]) {
    u.frame->kernels->gouraud_vertex_batch(u, in, kLayout, out);
  }
  // A mesh without normals is lit per triangle with its face normal at its centre.
  static void face_without_normals(glm::vec3 normal, glm::vec3 centre, const DrawUniforms& u,
                                   float* v[3]) {
    for (int i = 0; i < 3; ++i) light_vertex(centre, normal, u, v[i]);  // writes the light
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
  static_assert(kColorSlot + 4 <= kDiffuseSlot);
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    glm::vec3 position = glm::vec3(u.model * glm::vec4(in.position, 1.0f));
    light_vertex(position, in.normal, u, out);
    store(out + kTexcoordSlot, in.texcoord);
    store(out + kColorSlot, material_color(in, u));
  }
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
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    light_vertex(glm::vec3(u.model * glm::vec4(in.position, 1.0f)), in.normal, u, out);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    return lit(u.material->base_color, f, u);
  }
};

// Physically based: Cook-Torrance (GGX, Smith, Schlick), metallic-roughness, occlusion,
// emission, and the environment's light (image-based lighting) or, when reflections are on,
// its mirror image.
// Lights are scaled by pi so a white Lambertian surface under a unit light looks as bright as
// in the Lambert model (the "punctual light" convention of glTF viewers).
struct PbrShading : BatchForm<BatchModel::pbr>, LightsBackFaces {
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
    const Environment& environment = u.frame->lighting->environment;
    if (u.frame->environment_light) {
      ambient = environment_light(*u.frame->environment_light, environment, surface, f0, s.normal,
                                  s.view);
    } else if (environment.reflections) {
      ambient += environment_reflection(environment, surface, f0, s.normal, s.view);
    }
    color += ambient * occlusion;
    return {color + emission(f, u), s.albedo.a};
  }
};

}  // namespace facet::shading
