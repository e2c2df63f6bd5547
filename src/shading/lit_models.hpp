// The lit shading models with specular light: Gouraud, Phong, Blinn-Phong and physically
// based (Cook-Torrance, metallic-roughness). See models.hpp for what a model provides.
#pragma once

#include "shading/brdf.hpp"
#include "shading/environment.hpp"
#include "shading/environment_light.hpp"
#include "shading/kernels.hpp"
#include "shading/models.hpp"

namespace facet::shading {

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
};

}  // namespace facet::shading
