// OBJ read from a file into a scene to render (import_obj_scene): plain geometry by facet's own
// reader (obj_plain.cpp), every other file by assimp's. The scene of a plain file is what
// assimp's reader gives it, so models look, and number their instances, as they did: a root
// node named after the file, one child "defaultobject" drawing the one mesh in assimp's default
// OBJ material (Lambert, diffuse 0.6 grey), smooth normals (with the crease angle) where the
// file has none.
#include <filesystem>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "facet/material.hpp"
#include "facet/scene.hpp"
#include "import/import_internal.hpp"

namespace facet::io {

Scene import_obj_scene(const std::string& path, const ImportOptions& options) {
  std::optional<Mesh> mesh = read_plain_obj(read_whole_file(path));
  if (!mesh) return import_assimp_scene(path, options);
  Material material;
  material.name = "DefaultMaterial";
  material.shading = ShadingModel::lambert;
  material.base_color = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
  finish_mesh(*mesh, material, options, path + ": mesh 0");
  Scene scene;
  scene.lighting.lights.clear();  // the file has none (import_scene lights it)
  scene.materials.push_back(std::move(material));
  scene.meshes.push_back(std::make_shared<const Mesh>(std::move(*mesh)));
  SceneNode root;
  root.name = std::filesystem::path(path).filename().string();
  scene.nodes.push_back(std::move(root));
  SceneNode object;
  object.name = "defaultobject";
  object.parent = 0;
  object.instances.push_back({0, 0});
  scene.nodes.push_back(std::move(object));
  return scene;
}

}  // namespace facet::io
