// The lit shading models with specular light: Gouraud, Phong, Blinn-Phong and physically
// based (Cook-Torrance, metallic-roughness). See models.hpp for what a model provides.
#pragma once

#include "shading/kernels.hpp"
#include "shading/models.hpp"

namespace facet::shading {

// Phong (kBlinn = false) or Blinn-Phong (true), per pixel: ambient + diffuse + specular.
template <bool kBlinn>
struct PhongShadingT : BatchForm<kBlinn ? BatchModel::blinn_phong : BatchModel::phong>,
                       LightsBackFaces,
                       SurfaceVertexBatch<kSurfaceVaryingsWithTangent> {
  static constexpr int kVaryings = kSurfaceVaryingsWithTangent;
  static constexpr int kNormalSlot = shading::kNormalSlot;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
};
using PhongShading = PhongShadingT<false>;
using BlinnPhongShading = PhongShadingT<true>;

// Gouraud: Blinn-Phong evaluated at the vertices, shadows included (a shadow is sampled at
// each vertex, not per pixel); the pixel interpolates diffuse and specular light. GouraudLight is
// what both layouts share: the lighting, by the SIMD kernels of vertex_batch.hpp alone, writing
// the diffuse light at slots kDiffuse..kDiffuse+2 and the specular light at the next three (under
// gray light, kGray, one slot each: GouraudLayout), after the surface layout's texture coordinate
// and color if kWithSurface.
template <int kDiffuse, bool kWithSurface, bool kGray = false>
struct GouraudLight {
  static constexpr int kDiffuseSlot = kDiffuse;
  static constexpr int kSpecularSlot = kDiffuse + (kGray ? 1 : 3);
  static constexpr int kNormalSlot = -1;  // lit per vertex; see face_without_normals()
  static constexpr bool kLightsVertices = true;
  static constexpr GouraudLayout kLayout{kDiffuse, kWithSurface, kGray};
  // The vertex stage lights every draw's vertices a run at a time.
  static void vertex_batch(const DrawUniforms& u, const VertexBatchInput& in,
                           float (*out)[kVertexBatch]) {
    u.frame->kernels->gouraud_vertex_batch(u, in, kLayout, out);
  }
  // A mesh without normals is lit per triangle with its face normal at its centre: the light of
  // that one point at its three corners.
  static void face_without_normals(glm::vec3 normal, glm::vec3 centre, const DrawUniforms& u,
                                   float* v[3]) {
    alignas(64) float light[6][kVertexBatch];
    u.frame->kernels->gouraud_light_batch(u, {1, &centre, &normal, true, kGray}, light);
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < (kGray ? 2 : 6); ++k) v[i][kDiffuseSlot + k] = light[k][0];
    }
  }
};

// Gouraud with a texture or vertex colors. Layout: texture coordinate and color as in the
// surface layout (the maps are read there), then diffuse light (6-8) and specular light (9-11).
struct GouraudShading : GouraudLight<kGouraudDiffuseSlot, true>, BatchForm<BatchModel::gouraud> {
  static constexpr int kVaryings = 12;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
  static_assert(kColorSlot + 4 <= kDiffuseSlot && kSpecularSlot + 3 == kVaryings);
};

// Gouraud for a draw whose surface color is one constant: no base color or emissive map, no
// vertex colors (pipeline_for in pipeline/record/pipeline_table.cpp decides). It interpolates only
// the light, 6 varyings instead of 12: half the plane set-up and interpolation of scenes of many
// small triangles (million), and the color is the material's exactly, not an interpolated constant.
struct ConstantColorGouraudShading : GouraudLight<kConstantGouraudDiffuseSlot, false>,
                                     BatchForm<BatchModel::constant_gouraud> {
  static constexpr int kVaryings = 6;
  static_assert(kSpecularSlot + 3 == kVaryings);
};

// Constant-color Gouraud under gray light (GouraudLayout; pipeline_table.cpp decides): 2 varyings,
// the lights' diffuse and specular light, each standing for its three equal channels; the pixel
// adds the ambient light to the diffuse. A third of ConstantColorGouraudShading's plane set-up and
// interpolation; its colors differ only in rounding (the ambient light added after interpolation
// instead of before).
struct GrayLightGouraudShading : GouraudLight<kConstantGouraudDiffuseSlot, false, true>,
                                 BatchForm<BatchModel::gray_gouraud> {
  static constexpr int kVaryings = 2;
  static_assert(kSpecularSlot + 1 == kVaryings);
};

// Physically based: Cook-Torrance (GGX, Smith, Schlick), metallic-roughness, occlusion,
// emission, and the environment's light (image-based lighting) or, when reflections are on,
// its mirror image.
// Lights are scaled by pi so a white Lambertian surface under a unit light looks as bright as
// in the Lambert model (the "punctual light" convention of glTF viewers).
struct PbrShading : BatchForm<BatchModel::pbr>,
                    LightsBackFaces,
                    SurfaceVertexBatch<kSurfaceVaryingsWithTangent> {
  static constexpr int kVaryings = kSurfaceVaryingsWithTangent;
  static constexpr int kNormalSlot = shading::kNormalSlot;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
};

}  // namespace facet::shading
