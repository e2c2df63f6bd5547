// libFuzzer target for facet's PLY reader (src/import/ply_header.cpp, ply_values.hpp,
// ply_format.cpp): any input must either give a mesh that passes Mesh::validate() with the
// reader's promises kept (points finite and unindexed; triangles whole, every vertex used; unit
// normals; finite texture coordinates and colors) or throw facet::Error. A crash, a hang, a
// sanitizer report or an inconsistent mesh is a bug. Run with `make test-fuzz` (corpus:
// corpus/ply/).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>
#include <string_view>
#include <vector>

#include "facet/error.hpp"
#include "import/import_internal.hpp"

namespace {

bool finite(glm::vec4 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

void check(const facet::Mesh& mesh) {
  mesh.validate();
  if (mesh.topology == facet::Topology::points) {
    if (!mesh.indices.empty()) __builtin_trap();
    for (const glm::vec3& p : mesh.positions) {
      if (!finite(glm::vec4(p, 0.0f))) __builtin_trap();
    }
  } else {
    if (mesh.topology != facet::Topology::triangles) __builtin_trap();
    std::vector<bool> used(mesh.positions.size(), false);
    for (std::uint32_t index : mesh.indices) used[index] = true;
    for (bool u : used) {
      if (!u) __builtin_trap();
    }
  }
  for (const glm::vec3& n : mesh.normals) {
    if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f)) __builtin_trap();
  }
  for (const glm::vec2& uv : mesh.texcoords) {
    if (!finite(glm::vec4(uv, 0.0f, 0.0f))) __builtin_trap();
  }
  for (const glm::vec4& c : mesh.colors) {
    if (!finite(c)) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    check(facet::io::parse_ply_geometry(bytes, "fuzz.ply").mesh);
  } catch (const facet::Error&) {
    // Malformed input: the expected outcome for most fuzz inputs.
  }
  return 0;
}
