// The `.d` format read from a file: as a mesh (read_d_file) or as a scene to render
// (import_d_scene). The parsing is d_format.cpp's.
#include <glm/vec3.hpp>
#include <string>
#include <utility>

#include "facet/material.hpp"
#include "facet/scene.hpp"
#include "import/import_internal.hpp"

namespace facet {
namespace io {

Scene import_d_scene(const std::string& path, const ImportOptions& options) {
  Mesh mesh = parse_d_geometry(read_whole_file(path), path);
  compute_smooth_normals(mesh, options.crease_angle_degrees);
  Material material;
  material.name = "d";
  material.shading = ShadingModel::blinn_phong;
  material.base_color = {0.62f, 0.60f, 0.57f, 1.0f};  // a warm grey that shows the shape
  material.specular_color = glm::vec3(0.3f);
  material.shininess = 32.0f;
  // Open models (a terrain patch) are seen from both sides; the format has no winding rule.
  material.cull = CullMode::none;
  Scene scene;
  scene.add_object(std::move(mesh), std::move(material), glm::mat4(1.0f), "d");
  return scene;
}

}  // namespace io

Mesh read_d_file(const std::string& path) { return parse_d(io::read_whole_file(path), path); }

}  // namespace facet
