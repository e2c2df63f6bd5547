// The built-in unlit, Lambert, Phong, Blinn-Phong, PBR and Gouraud models and the normals view:
// one SIMD kernel (shade_batch.cpp, compiled for every target Highway supports) that shades a
// batch of pixels at once, and the models' only implementation. The raster loop
// (pipeline/raster/raster.hpp) packs the covered pixels of a triangle (or of several small
// ones), samples the material's maps for them (texel_batch.hpp), then shades them together.
#pragma once

#include "core/simd_target.hpp"
#include "shading/uniforms.hpp"
#include "shading/varyings.hpp"

namespace facet::shading {

inline constexpr int kShadeBatch = 64;

// constant_unlit: unlit with the material's base color instead of an interpolated color;
// gouraud, constant_gouraud and gray_gouraud: the Gouraud models (lit_models.hpp), whose pixels
// combine the light interpolated from their vertices; pbr: physically based (metallic-roughness).
enum class BatchModel {
  unlit,
  constant_unlit,
  lambert,
  phong,
  blinn_phong,
  normals,
  depth_view,
  texcoords_view,
  gouraud,
  constant_gouraud,
  gray_gouraud,
  pbr
};

// The material's maps besides the base color map, which the raster loop samples ahead for a
// batch of pixels (texel_batch.hpp) for the models that read them (maps_read).
enum MaterialMap { kEmissiveMap, kNormalMap, kSpecularMap, kMetallicRoughnessMap, kOcclusionMap };
inline constexpr int kMaterialMaps = 5;
inline constexpr unsigned map_bit(MaterialMap map) { return 1u << map; }

inline const TextureMap& material_map(const Material& m, MaterialMap map) {
  switch (map) {
    case kEmissiveMap:
      return m.emissive_map;
    case kNormalMap:
      return m.normal_map;
    case kSpecularMap:
      return m.specular_map;
    case kMetallicRoughnessMap:
      return m.metallic_roughness_map;
    default:
      return m.occlusion_map;
  }
}

// Which maps (map_bit) a model reads: every model its emission's, but the normals view and the
// constant-color Gouraud models, which have no texture coordinate (pipeline/record/
// pipeline_table.cpp takes it for draws without maps); Phong and Blinn-Phong their normal and
// specular maps; PBR its normal, metallic-roughness and occlusion maps.
inline constexpr unsigned maps_read(BatchModel model) {
  switch (model) {
    case BatchModel::normals:
    case BatchModel::depth_view:
    case BatchModel::texcoords_view:
    case BatchModel::constant_gouraud:
    case BatchModel::gray_gouraud:
      return 0;
    case BatchModel::phong:
    case BatchModel::blinn_phong:
      return map_bit(kEmissiveMap) | map_bit(kNormalMap) | map_bit(kSpecularMap);
    case BatchModel::pbr:
      return map_bit(kEmissiveMap) | map_bit(kNormalMap) | map_bit(kMetallicRoughnessMap) |
             map_bit(kOcclusionMap);
    default:
      return map_bit(kEmissiveMap);
  }
}

// The maps of material m that a model reading the maps `maps_read` (maps_read()) samples: out[k] is
// map k, or null where the model does not read it or the material has none; the emissive map only
// with an emissive factor (without, emission is zero).
inline void maps_to_sample(unsigned maps_read, const Material& m,
                           const TextureMap* out[kMaterialMaps]) {
  for (int k = 0; k < kMaterialMaps; ++k) {
    const auto map = static_cast<MaterialMap>(k);
    const TextureMap& texture_map = material_map(m, map);
    const bool read = (maps_read & map_bit(map)) != 0 && texture_map &&
                      (map != kEmissiveMap || m.emissive != glm::vec3(0.0f));
    out[k] = read ? &texture_map : nullptr;
  }
}

// Where the Gouraud models keep their interpolated diffuse light (the specular light follows):
// after the surface layout's texture coordinate and color, or first for one constant color.
inline constexpr int kGouraudDiffuseSlot = 6;
inline constexpr int kConstantGouraudDiffuseSlot = 0;

// Packed pixels of one draw (of one triangle, or of several small ones: pipeline/
// small_triangles.hpp): n-th pixel's clip w is w[n], its window depth z[n], its varying k is
// v[k][n]. Arrays
// hold kShadeBatch entries; those from count up to the next multiple of 8 must be readable
// (they are computed, then ignored).
struct ShadeInput {
  int count = 0;
  const float* w = nullptr;
  const float* z = nullptr;
  const float (*v)[kShadeBatch] = nullptr;
  const float (*base_texel)[4] = nullptr;  // the base color map's texel per pixel, or null
  const Fog* fog = nullptr;                // fog to apply to the colors, or null
  // Where pixel n's color goes: rgba[(n / 8) * rgba_row_stride + n % 8]. 8 for a packed array;
  // a whole 8x8 block (count 64) may go straight into a tile's rows with the tile's stride.
  int rgba_row_stride = 8;
  // Or, for the display-referred models (models.hpp's DisplayReferred) into a tile of 8-bit codes
  // (pipeline::TileContext::codes): where not null, pixel n's codes go to codes[(n / 8) *
  // rgba_row_stride + n % 8], its four bytes RGBA, and nothing to rgba.
  std::uint32_t* codes = nullptr;
  // Alpha written as 1 whatever the model computes: an opaque draw covers what it draws
  // (pipeline::blend_into). Every batch form honours it (the built-in kernels here, glmark2's,
  // whose colors are display codes with alpha 1 anyway).
  bool opaque = false;
  // Each MaterialMap's texel per pixel, where the material has the map and the model reads it
  // (maps_read); else null.
  const float (*map_texel[kMaterialMaps])[4] = {};
};

// Linear RGBA of every pixel, shaded by `model` (then fogged, if in.fog).
// rgba holds kShadeBatch colors (with in.rgba_row_stride 8): those from in.count up to the
// next multiple of 8 are written too, as scratch.
using ShadeBatchKernel = void (*)(BatchModel model, const DrawUniforms& u, const ShadeInput& in,
                                  float (*rgba)[4]);
ShadeBatchKernel shade_batch_kernel(SimdTarget target);

// Fogs the colors of in.count pixels already in rgba (laid out as ShadeBatchKernel writes them)
// in place, if in.fog: what the batch kernel does after shading, for colors shaded otherwise.
using FogBatchKernel = void (*)(const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]);
FogBatchKernel fog_batch_kernel(SimdTarget target);

}  // namespace facet::shading
