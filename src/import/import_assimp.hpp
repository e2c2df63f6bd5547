// Internal to the assimp importer (import_assimp.cpp): the texture files a model references
// (import_textures.cpp), its materials (import_materials.cpp) and the maps derived for them
// (derived_maps.cpp), cameras and lights (import_assimp_objects.cpp).
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "facet/material.hpp"
#include "facet/texture.hpp"
#include "import/guarded_files.hpp"
#include "import/import_internal.hpp"

struct aiScene;
struct aiMaterial;

namespace facet::io {

// Loads the textures a model references, each (file, sRGB) pair once. A texture that is
// missing, refused (outside the model's folder, not a regular file: guarded_files.hpp) or cannot
// be decoded is warned about once per file name and comes back null.
class TextureLoader {
 public:
  TextureLoader(const aiScene& scene, const std::string& model_path, const ImportOptions& options);
  std::shared_ptr<const Texture> load(const std::string& reference, bool srgb);

 private:
  // The file to read, or empty: not found, or only refused files found (refusal says why).
  std::string resolve(const std::string& reference, std::string& refusal) const;
  int embedded_index(const std::string& reference) const;  // -1: not embedded
  std::shared_ptr<const Texture> decode_embedded(int index, bool srgb) const;
  void warn_once(const std::string& reference, const std::string& problem);

  const aiScene& scene_;
  std::string model_path_;
  std::string model_dir_;
  const ImportOptions& options_;
  ReferenceRules rules_;
  std::map<std::string, std::string> resolved_;  // reference -> file path, "*N" or "" (missing)
  std::map<std::pair<std::string, bool>, std::shared_ptr<const Texture>> cache_;
  std::set<std::string> warned_;
};

// How deep a height map's full range (black to white) is, in texel widths, for a bump
// multiplier of 1 (OBJ's map_bump -bm): the slope between two texels is their height difference
// times this. Measured on the one pair at hand, glmark2's asteroid height map and the
// tangent-space normal map made from it: the normal map leans 13 times the height map's step
// per texel (mean slope 0.124, mean step 0.0095 inside the disc), so its shapes come out as
// deep as their author made them.
inline constexpr float kBumpDepthTexels = 13.0f;

// A tangent-space normal map (linear RGBA8, +X along u, +Y along v, as glTF's) from a height
// map's grey values: n = normalize(-dh/du, -dh/dv, 1) from central differences (heights times
// kBumpDepthTexels x strength), wrapped at the edges as `sampler` wraps.
std::shared_ptr<const Texture> normal_map_from_heights(const Texture& heights, float strength,
                                                       const Sampler& sampler);

// The perceptual roughness (shading/shade_batch.cpp's, alpha = roughness^2) that matches a
// Phong/Blinn-Phong shininess exponent: alpha = sqrt(2 / (n + 2)) (Walter et al. 2007), so
// roughness = (2 / (n + 2))^(1/4).
float roughness_from_shininess(float exponent);

// The packed map the PBR shader reads (G roughness, B metalness, linear RGBA8) from separate
// grey maps, at the largest one's size: roughness from `roughness`, else from `gloss` (a
// shininess map whose grey scales gloss_exponent, as MTL's map_Ns scales Ns), else 1; metalness
// from `metalness`, else 1 (the material's factors multiply these, as glTF's do).
std::shared_ptr<const Texture> packed_metallic_roughness(const Texture* roughness,
                                                         const Texture* metalness,
                                                         const Texture* gloss,
                                                         float gloss_exponent);

// Every material of the scene, in assimp's order (aiMesh::mMaterialIndex indexes it).
// gltf: the file is glTF 2.0, so materials are metallic-roughness PBR with glTF conventions.
std::vector<Material> import_materials(const aiScene& scene, bool gltf, TextureLoader& textures);

// The file's cameras (Scene::cameras) and lights (Scene::lighting, has_file_lights), placed by
// the nodes they are named after; needs the scene's nodes and meshes (for its size).
void import_cameras_and_lights(const aiScene& ai, bool gltf, const std::string& path,
                               const ImportOptions& options,
                               const std::unordered_map<std::string, int>& node_by_name,
                               Scene& scene);

}  // namespace facet::io
