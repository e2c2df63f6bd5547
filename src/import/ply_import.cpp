// PLY read from a file into a scene to render (import_ply_scene); the parsing is ply_format.cpp's.
// The scene is what assimp's PLY reader gave before facet read PLY itself, so models look as
// they did: one node, one mesh, a white Blinn-Phong material seen from both sides (PLY says
// nothing about winding), vertex colors on, smooth normals where the file has none.
#include <algorithm>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <system_error>
#include <utility>

#include "facet/error.hpp"
#include "facet/material.hpp"
#include "facet/scene.hpp"
#include "facet/texture.hpp"
#include "import/guarded_files.hpp"
#include "import/import_internal.hpp"

namespace facet::io {
namespace {

namespace fs = std::filesystem;

// The material assimp 5.2's PLY reader makes for a file without one: diffuse and specular white,
// shininess left at its default, two-sided unless the file is a point cloud.
Material ply_material(bool points) {
  Material material;
  material.shading = ShadingModel::blinn_phong;
  material.base_color = glm::vec4(1.0f);
  material.specular_color = glm::vec3(1.0f);
  if (!points) material.cull = CullMode::none;
  return material;
}

// `comment TextureFile NAME` (MeshLab's): the image next to the model, held to the rules every
// referenced file is (guarded_files.hpp). A refused, missing or undecodable file is one warning
// and the missing-texture checker.
TextureMap texture_map(const std::string& model, const std::string& name,
                       const ImportOptions& options) {
  TextureMap map;
  map.texture = missing_texture();
  fs::path folder = fs::path(model).parent_path();
  if (folder.empty()) folder = ".";
  const fs::path file = folder / name;
  const std::string refusal = ReferenceRules(model, options).refusal(file);
  if (!refusal.empty()) {
    warn(options, model + ": texture '" + name + "' " + refusal + ": not used");
    return map;
  }
  std::error_code error;
  if (!fs::exists(file, error)) {
    warn(options, model + ": texture '" + name + "' not found");
    return map;
  }
  try {
    const std::string bytes = read_regular_file(file.string());
    map.texture = load_texture_from_memory(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                           bytes.size(), /*srgb=*/true, file.string());
  } catch (const Error& e) {
    warn(options, e.what());
  }
  return map;
}

}  // namespace

Scene import_ply_scene(const std::string& path, const ImportOptions& options) {
  PlyGeometry ply = parse_ply_geometry(read_whole_file(path), path);
  Mesh& mesh = ply.mesh;
  const bool points = mesh.topology == Topology::points;
  if (ply.non_finite > 0) {
    warn(options, path + ": " + std::to_string(ply.non_finite) +
                      (points ? " points with a non-finite position left out"
                              : " vertices with a non-finite position: the triangles that use "
                                "them are not drawn"));
  }
  Material material = ply_material(points);
  if (!ply.texture_file.empty())
    material.base_color_map = texture_map(path, ply.texture_file, options);
  if (!points) {
    if (mesh.normals.empty()) {
      compute_smooth_normals(mesh, options.crease_angle_degrees);
    } else {
      join_identical_vertices(mesh);  // the file's duplicates, as assimp's path joined them
    }
  }
  Scene scene;
  if (material.base_color_map) scene.textures.push_back(material.base_color_map.texture);
  scene.add_object(std::move(mesh), std::move(material), glm::mat4(1.0f),
                   fs::path(path).filename().string());
  return scene;
}

}  // namespace facet::io
