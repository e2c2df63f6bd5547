// libFuzzer target for facet's reader of plain OBJ geometry (src/import/obj_plain.cpp): any input
// must either give a mesh that passes Mesh::validate() with the reader's promises kept (a vertex
// per corner, in order: indices 0, 1, 2, ...; finite positions, not all alike; normals and
// texture coordinates per corner or none, finite, normals of non-zero length) or nothing (the
// file is then assimp's to read). It never throws. A crash, a hang, a sanitizer report or an
// inconsistent mesh is a bug. Run with `make test-fuzz` (corpus: corpus/obj/).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "import/import_internal.hpp"

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check(const facet::Mesh& mesh) {
  mesh.validate();
  const std::size_t corners = mesh.positions.size();
  if (mesh.topology != facet::Topology::triangles || corners == 0 || corners % 3 != 0)
    __builtin_trap();
  if (mesh.indices.size() != corners) __builtin_trap();
  for (std::size_t i = 0; i < corners; ++i) {
    if (mesh.indices[i] != i || !finite(mesh.positions[i])) __builtin_trap();
  }
  if (!mesh.normals.empty() && mesh.normals.size() != corners) __builtin_trap();
  if (!mesh.texcoords.empty() && mesh.texcoords.size() != corners) __builtin_trap();
  for (const glm::vec3& n : mesh.normals) {
    if (!finite(n) || (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f)) __builtin_trap();
  }
  for (const glm::vec2& t : mesh.texcoords) {
    if (!std::isfinite(t.x) || !std::isfinite(t.y)) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<facet::Mesh> mesh =
      facet::io::read_plain_obj(std::string_view(reinterpret_cast<const char*>(data), size));
  if (mesh) check(*mesh);
  return 0;
}
