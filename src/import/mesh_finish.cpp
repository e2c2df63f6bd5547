// finish_mesh(): what every imported mesh goes through before it enters a Scene, whichever
// reader made it (import_assimp.cpp, the glTF reader gltf_meshes.cpp): validated, bad
// per-vertex data repaired, normals and tangents made where the file has none. Runs once per
// mesh at load time.
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "facet/error.hpp"
#include "facet/mesh_tools.hpp"
#include "import/import_internal.hpp"

namespace facet::io {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Bad per-vertex data that the pipeline could not shade sensibly is repaired or recomputed;
// positions that are not finite make the model unusable and are reported.
void repair_attributes(Mesh& mesh, const std::string& where) {
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!finite(mesh.positions[i])) {
      throw Error(where + ": vertex " + std::to_string(i) + " has a non-finite position");
    }
  }
  for (glm::vec3& normal : mesh.normals) {
    float length = glm::length(normal);
    if (!(length > 1e-12f) || !std::isfinite(length)) {
      mesh.normals.clear();  // recomputed below: one broken normal spoils a smooth surface
      break;
    }
    normal /= length;
  }
  for (glm::vec2& uv : mesh.texcoords) {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
  }
  for (glm::vec4& color : mesh.colors) {
    if (!finite(glm::vec3(color)) || !std::isfinite(color.w)) color = glm::vec4(1.0f);
  }
  for (const glm::vec4& t : mesh.tangents) {
    if (!finite(glm::vec3(t)) || !(glm::length(glm::vec3(t)) > 1e-12f)) {
      mesh.tangents.clear();
      break;
    }
  }
}

}  // namespace

void finish_mesh(Mesh& mesh, const Material& material, const ImportOptions& options,
                 const std::string& where) {
  try {
    mesh.validate();
  } catch (const Error& e) {
    std::string what = e.what();
    if (what.rfind("mesh: ", 0) == 0) what.erase(0, 6);
    throw Error(where + ": " + what);
  }
  repair_attributes(mesh, where);
  if (mesh.topology == Topology::lines || mesh.topology == Topology::points) return;
  // Either joins identical vertices (assimp hands each face corner its own).
  if (mesh.normals.empty()) {
    compute_smooth_normals(mesh, options.crease_angle_degrees);
  } else {
    join_identical_vertices(mesh);
  }
  if (material.normal_map && !mesh.texcoords.empty() && mesh.tangents.empty()) {
    compute_tangents(mesh);
  }
}

}  // namespace facet::io
