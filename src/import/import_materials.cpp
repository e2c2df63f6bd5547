// assimp materials to facet Materials. Runs once per model at load time.
//
// Which shading model a material gets (the renderer's --shading overrides it for a scene):
//   glTF 2.0                     pbr (metallic-roughness; specular-glossiness converted), or
//                                unlit for KHR_materials_unlit
//   a specular color and shininess (OBJ Ks/Ns, 3DS, FBX, COLLADA)   blinn_phong
//   assimp says flat / unlit     flat / unlit
//   separate roughness, metalness or gloss maps (MTL map_Pr, map_Pm, map_Ns)   pbr, the maps
//                                packed as glTF packs them (derived_maps.cpp)
//   anything else                lambert, or blinn_phong without a highlight when it has a
//                                normal map (Lambert reads none)
// Colors are taken as stored (glTF factors are linear by definition; MTL and 3DS colors are
// used as linear too, as Blender's importers do).
#include <assimp/GltfMaterial.h>
#include <assimp/ObjMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <optional>
#include <string>

#include "import/import_assimp.hpp"

namespace facet::io {
namespace {

// glTF sampler filter enums (glTF 2.0 §5.26, the OpenGL values).
constexpr int kGlNearest = 9728;
constexpr int kGlLinear = 9729;

std::optional<float> get_float(const aiMaterial& m, const char* key, unsigned type,
                               unsigned index) {
  float value = 0.0f;
  if (m.Get(key, type, index, value) != AI_SUCCESS || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> get_int(const aiMaterial& m, const char* key, unsigned type, unsigned index) {
  int value = 0;
  if (m.Get(key, type, index, value) != AI_SUCCESS) return std::nullopt;
  return value;
}

// Colors stored with 3 components read back with alpha 1.
std::optional<glm::vec4> get_color(const aiMaterial& m, const char* key, unsigned type,
                                   unsigned index) {
  aiColor4D c;
  if (m.Get(key, type, index, c) != AI_SUCCESS) return std::nullopt;
  glm::vec4 v(c.r, c.g, c.b, c.a);
  if (!std::isfinite(v.x + v.y + v.z + v.w)) return std::nullopt;
  return glm::max(v, glm::vec4(0.0f));
}

Wrap wrap_from(int mode) {
  switch (mode) {
    case aiTextureMapMode_Clamp:
    case aiTextureMapMode_Decal:  // outside [0, 1] shows the border: the closest we have
      return Wrap::clamp_to_edge;
    case aiTextureMapMode_Mirror:
      return Wrap::mirrored_repeat;
    default:
      return Wrap::repeat;
  }
}

// assimp's aiUVTransform, applied the way its TextureTransform step applies it (every format
// but glTF):
// uv' = C * S * R * C^-1 * T * uv, rotating and scaling about the centre C = (0.5, 0.5).
glm::mat3 uv_matrix(const aiUVTransform& t) {
  auto translate = [](float x, float y) {
    glm::mat3 m(1.0f);
    m[2] = glm::vec3(x, y, 1.0f);
    return m;
  };
  glm::mat3 scale(1.0f);
  scale[0][0] = t.mScaling.x;
  scale[1][1] = t.mScaling.y;
  const float c = std::cos(t.mRotation), s = std::sin(t.mRotation);
  glm::mat3 rotate(1.0f);
  rotate[0] = glm::vec3(c, s, 0.0f);
  rotate[1] = glm::vec3(-s, c, 0.0f);
  return translate(0.5f, 0.5f) * scale * rotate * translate(-0.5f, -0.5f) *
         translate(t.mTranslation.x, t.mTranslation.y);
}

// glTF: assimp encodes KHR_texture_transform into aiUVTransform with its own change of
// coordinates (glTF2Importer.cpp), which its TextureTransform step does not undo correctly for
// rotations (the glTF TextureTransformTest's arrows miss their markers). So the glTF values are
// recovered from assimp's encoding and the transform is rebuilt for v-up texture coordinates:
// glTF's uv' = T(offset) R(rotation) S(scale) uv with v pointing down, conjugated by v -> 1 - v.
glm::mat3 gltf_uv_matrix(const aiUVTransform& t) {
  const float rotation = -t.mRotation, sx = t.mScaling.x, sy = t.mScaling.y;
  const float c = std::cos(rotation), s = std::sin(rotation);
  const float offset_x = t.mTranslation.x - 0.5f * sx * (1.0f - c + s);
  const float offset_y = 0.5f * sy * (s + c - 1.0f) + 1.0f - sy - t.mTranslation.y;
  glm::mat3 m(1.0f);  // columns
  m[0] = glm::vec3(c * sx, s * sx, 0.0f);
  m[1] = glm::vec3(-s * sy, c * sy, 0.0f);
  m[2] = glm::vec3(offset_x + s * sy, 1.0f - offset_y - c * sy, 1.0f);
  return m;
}

Sampler sampler_for(const aiMaterial& m, aiTextureType type) {
  Sampler sampler;
  sampler.wrap_u = wrap_from(get_int(m, AI_MATKEY_MAPPINGMODE_U(type, 0)).value_or(0));
  sampler.wrap_v = wrap_from(get_int(m, AI_MATKEY_MAPPINGMODE_V(type, 0)).value_or(0));
  const int mag = get_int(m, AI_MATKEY_GLTF_MAPPINGFILTER_MAG(type, 0)).value_or(0);
  const int min = get_int(m, AI_MATKEY_GLTF_MAPPINGFILTER_MIN(type, 0)).value_or(0);
  if (mag == kGlNearest) {
    sampler.filter = Filter::nearest;  // pixel art asks for crisp texels
  } else if (min == kGlNearest || min == kGlLinear) {
    sampler.filter = Filter::bilinear;  // the file asks for no mipmaps
  }
  return sampler;
}

// OBJ and 3DS files put either a tangent-space normal map or a height (bump) map where
// assimp reads aiTextureType_HEIGHT, so the image decides. A normal map's texels decode
// (2c - 1) to unit vectors facing out (z > 0); a height map is grey. Grey texels are left out
// of the count (they are heights, or the flat white or black padding of a texture atlas, as in
// glmark2's asteroid-normal-map-tangent.png, half of which is white): a normal map is an image
// whose other texels are, nearly all, unit vectors facing out.
bool looks_like_normal_map(const Texture& texture) {
  if (texture.format() != Texture::Format::rgba8) return false;
  const Texture::Level& level = texture.level(0);
  const std::size_t count = static_cast<std::size_t>(level.width) * level.height;
  if (count == 0 || level.rgba8.size() < count * 4) return false;
  constexpr int kGreyTolerance = 8;  // codes: JPEG noise on a grey texel stays grey
  const std::size_t step = std::max<std::size_t>(1, count / 4096);
  std::size_t coloured = 0, normals = 0;
  for (std::size_t i = 0; i < count; i += step) {
    const std::uint8_t* p = &level.rgba8[i * 4];
    if (std::abs(p[0] - p[1]) <= kGreyTolerance && std::abs(p[1] - p[2]) <= kGreyTolerance &&
        std::abs(p[0] - p[2]) <= kGreyTolerance) {
      continue;
    }
    ++coloured;
    const glm::vec3 n = glm::vec3(p[0], p[1], p[2]) / 127.5f - 1.0f;
    const float length = glm::length(n);
    normals += n.z > 0.0f && length > 0.8f && length < 1.2f;
  }
  return coloured > 0 && normals >= coloured * 9 / 10;
}

class MaterialConverter {
 public:
  MaterialConverter(const aiMaterial& m, bool gltf, TextureLoader& textures)
      : m_(m), gltf_(gltf), textures_(textures) {}

  Material convert() {
    aiString name;
    if (m_.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out_.name = name.C_Str();
    colors();
    gltf_ ? pbr() : classic();
    if (get_int(m_, AI_MATKEY_TWOSIDED).value_or(0) != 0) out_.cull = CullMode::none;
    maps();
    return out_;
  }

 private:
  void colors() {
    auto base = get_color(m_, AI_MATKEY_BASE_COLOR);
    if (!base) base = get_color(m_, AI_MATKEY_COLOR_DIFFUSE);
    if (base) out_.base_color = *base;
    if (auto emissive = get_color(m_, AI_MATKEY_COLOR_EMISSIVE)) {
      out_.emissive = glm::vec3(*emissive) *
                      std::max(get_float(m_, AI_MATKEY_EMISSIVE_INTENSITY).value_or(1.0f), 0.0f);
    }
  }

  // glTF: alpha is the base color's own alpha (assimp copies it into opacity as well).
  void pbr() {
    out_.shading = ShadingModel::pbr;
    out_.metallic = std::clamp(get_float(m_, AI_MATKEY_METALLIC_FACTOR).value_or(1.0f), 0.f, 1.f);
    out_.roughness = std::clamp(get_float(m_, AI_MATKEY_ROUGHNESS_FACTOR).value_or(1.f), 0.f, 1.f);
    if (auto glossiness = get_float(m_, AI_MATKEY_GLOSSINESS_FACTOR)) {
      glm::vec3 specular =
          glm::vec3(get_color(m_, AI_MATKEY_COLOR_SPECULAR).value_or(glm::vec4(1)));
      convert_specular_glossiness(out_.base_color, specular, *glossiness, out_);
    }
    aiString mode;
    if (m_.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS) {
      if (std::strcmp(mode.C_Str(), "MASK") == 0) out_.alpha_mode = AlphaMode::mask;
      if (std::strcmp(mode.C_Str(), "BLEND") == 0) out_.alpha_mode = AlphaMode::blend;
    }
    out_.alpha_cutoff = get_float(m_, AI_MATKEY_GLTF_ALPHACUTOFF).value_or(0.5f);
    if (shading_mode() == aiShadingMode_Unlit) out_.shading = ShadingModel::unlit;
  }

  void classic() {
    if (auto opacity = get_float(m_, AI_MATKEY_OPACITY)) {
      out_.base_color.a = std::clamp(*opacity, 0.0f, 1.0f);
    }
    if (out_.base_color.a < 1.0f) out_.alpha_mode = AlphaMode::blend;
    glm::vec3 specular = glm::vec3(get_color(m_, AI_MATKEY_COLOR_SPECULAR).value_or(glm::vec4(0)));
    specular *= std::max(get_float(m_, AI_MATKEY_SHININESS_STRENGTH).value_or(1.0f), 0.0f);
    // assimp: a shininess of 0 means no specular highlight at all.
    const float shininess = get_float(m_, AI_MATKEY_SHININESS).value_or(out_.shininess);
    if (std::max({specular.r, specular.g, specular.b}) > 1e-4f && shininess > 0.0f) {
      out_.shading = ShadingModel::blinn_phong;
      out_.specular_color = specular;
      out_.shininess = std::clamp(shininess, 1.0f, 4096.0f);
    }
    const int mode = shading_mode();
    if (mode == aiShadingMode_Flat) out_.shading = ShadingModel::flat;
    if (mode == aiShadingMode_NoShading) out_.shading = ShadingModel::unlit;
  }

  int shading_mode() const { return get_int(m_, AI_MATKEY_SHADING_MODEL).value_or(0); }

  void maps() {
    out_.base_color_map = load(aiTextureType_BASE_COLOR, true);
    if (!out_.base_color_map) out_.base_color_map = load(aiTextureType_DIFFUSE, true);
    out_.normal_map = load(aiTextureType_NORMALS, false);
    out_.normal_scale = get_float(m_, AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0))
                            .value_or(out_.normal_scale);
    if (!out_.normal_map && !gltf_) bump_map();
    out_.emissive_map = load(aiTextureType_EMISSIVE, true);
    // glTF multiplies by emissiveFactor as the spec says; an MTL map_Ke without Ke still glows.
    if (out_.emissive_map && !gltf_ && glm::length(out_.emissive) == 0.0f) {
      out_.emissive = glm::vec3(1.0f);
    }
    if (gltf_) {
      out_.metallic_roughness_map = load(aiTextureType_UNKNOWN, false);  // glTF's packed map
    } else {
      out_.specular_map = load(aiTextureType_SPECULAR, true);
      metal_rough_maps();
    }
    // Lambert reads no normal map: a bumped Lambert material is Blinn-Phong without a
    // highlight, the same light with the map's normals.
    if (out_.normal_map && out_.shading == ShadingModel::lambert) {
      out_.shading = ShadingModel::blinn_phong;
      out_.specular_color = glm::vec3(0.0f);
    }
    out_.occlusion_map = load(aiTextureType_LIGHTMAP, false);  // glTF occlusion lands here
    if (!out_.occlusion_map) out_.occlusion_map = load(aiTextureType_AMBIENT_OCCLUSION, false);
    out_.occlusion_strength =
        get_float(m_, AI_MATKEY_GLTF_TEXTURE_STRENGTH(aiTextureType_LIGHTMAP, 0))
            .value_or(out_.occlusion_strength);
  }

  // aiTextureType_HEIGHT: a normal map as it is, or a height map turned into one (the file's
  // bump multiplier, OBJ's -bm, scales the heights).
  void bump_map() {
    TextureMap bump = load(aiTextureType_HEIGHT, false, /*checker_when_missing=*/false);
    if (!bump) return;
    if (!looks_like_normal_map(*bump.texture)) {
      const float strength = get_float(m_, AI_MATKEY_OBJ_BUMPMULT_HEIGHT(0)).value_or(1.0f);
      bump.texture = normal_map_from_heights(*bump.texture, strength, bump.sampler);
    }
    out_.normal_map = bump;
  }

  // Roughness, metalness and gloss as separate grey maps (MTL map_Pr, map_Pm, map_Ns; the same
  // kinds from FBX and others): combined into the packed map the PBR shader reads, and the
  // material made PBR, the model these maps belong to. The maps give the values (the factors
  // become 1), but for one that is absent, whose factor stays the file's (MTL Pr, Pm), or for
  // metalness 0 without Pm. A gloss map is used for roughness only when there is no roughness
  // map: its grey scales the shininess exponent (MTL: Ns x map_Ns), converted to roughness as
  // roughness_from_shininess says.
  void metal_rough_maps() {
    TextureMap rough = load(aiTextureType_DIFFUSE_ROUGHNESS, false, false);
    TextureMap metal = load(aiTextureType_METALNESS, false, false);
    TextureMap gloss = load(aiTextureType_SHININESS, false, false);
    if (!rough && !metal && !gloss) return;
    if (out_.shading == ShadingModel::flat || out_.shading == ShadingModel::unlit) return;
    const float exponent = get_float(m_, AI_MATKEY_SHININESS).value_or(out_.shininess);
    out_.shading = ShadingModel::pbr;
    out_.metallic =
        metal ? 1.0f : std::clamp(get_float(m_, AI_MATKEY_METALLIC_FACTOR).value_or(0.f), 0.f, 1.f);
    out_.roughness =
        rough || gloss
            ? 1.0f
            : std::clamp(get_float(m_, AI_MATKEY_ROUGHNESS_FACTOR).value_or(out_.roughness), 0.f,
                         1.f);
    const TextureMap& first = rough ? rough : gloss ? gloss : metal;  // its sampler and transform
    out_.metallic_roughness_map = first;
    out_.metallic_roughness_map.texture = packed_metallic_roughness(
        rough.texture.get(), metal.texture.get(), gloss.texture.get(), exponent);
  }

  TextureMap load(aiTextureType type, bool srgb, bool checker_when_missing = true) {
    TextureMap map;
    aiString file;
    if (m_.GetTextureCount(type) == 0 || m_.GetTexture(type, 0, &file) != AI_SUCCESS) return map;
    map.texture = textures_.load(file.C_Str(), srgb);
    if (!map.texture && !checker_when_missing) return map;
    if (!map.texture) map.texture = missing_texture();
    map.sampler = sampler_for(m_, type);
    aiUVTransform transform;
    if (aiGetMaterialUVTransform(&m_, AI_MATKEY_UVTRANSFORM(type, 0), &transform) == AI_SUCCESS) {
      map.transform = gltf_ ? gltf_uv_matrix(transform) : uv_matrix(transform);
    }
    return map;
  }

  const aiMaterial& m_;
  bool gltf_;
  TextureLoader& textures_;
  Material out_;
};

}  // namespace

std::vector<Material> import_materials(const aiScene& scene, bool gltf, TextureLoader& textures) {
  std::vector<Material> materials;
  for (unsigned i = 0; scene.mMaterials && i < scene.mNumMaterials; ++i) {
    materials.push_back(scene.mMaterials[i]
                            ? MaterialConverter(*scene.mMaterials[i], gltf, textures).convert()
                            : Material{});
  }
  if (materials.empty()) materials.emplace_back();  // meshes always have a material to use
  return materials;
}

}  // namespace facet::io
