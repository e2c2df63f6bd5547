// Mesh bookkeeping: how many primitives a mesh draws and whether its arrays agree.
// Written by whoever builds a mesh (loaders, procedural shapes); read by the draw entry points.
#include "facet/mesh.hpp"

#include <algorithm>
#include <string>

#include "facet/error.hpp"

namespace facet {
namespace {

// Each optional attribute is either absent or one per position; anything else is a bug upstream.
void check_attribute_size(std::size_t count, std::size_t positions, const char* name) {
  if (count != 0 && count != positions) {
    throw Error("mesh: " + std::to_string(count) + " " + name + " for " +
                std::to_string(positions) + " positions");
  }
}

// Lists must hold whole primitives; strips and points may have any count (a strip of fewer
// than 3 draws nothing).
void check_whole_primitives(const Mesh& mesh) {
  const std::size_t per_primitive = mesh.topology == Topology::triangles ? 3
                                    : mesh.topology == Topology::lines   ? 2
                                                                         : 1;
  const std::size_t count = mesh.element_count();
  if (count % per_primitive == 0) return;
  throw Error("mesh: " + std::to_string(count) + (mesh.indices.empty() ? " vertices" : " indices") +
              " do not make whole " +
              (mesh.topology == Topology::triangles ? "triangles" : "lines"));
}

}  // namespace

std::size_t Mesh::primitive_count() const {
  const std::size_t count = element_count();
  switch (topology) {
    case Topology::triangles:
      return count / 3;
    case Topology::triangle_strip:
      return count >= 3 ? count - 2 : 0;
    case Topology::lines:
      return count / 2;
    case Topology::points:
      return count;
  }
  return 0;
}

void Mesh::validate() const {
  check_attribute_size(normals.size(), positions.size(), "normals");
  check_attribute_size(texcoords.size(), positions.size(), "texcoords");
  check_attribute_size(colors.size(), positions.size(), "colors");
  check_attribute_size(tangents.size(), positions.size(), "tangents");
  check_whole_primitives(*this);
  // Non-finite positions are allowed on purpose: the pipeline skips the triangles that use them.
  // Every draw of every frame validates its mesh on the recording thread, so the common case is
  // one pass without an early exit, which the compiler vectorizes: the largest index.
  std::uint32_t largest = 0;
  for (std::uint32_t index : indices) largest = std::max(largest, index);
  if (indices.empty() || largest < positions.size()) return;
  const auto bad = std::find_if(indices.begin(), indices.end(),
                                [&](std::uint32_t index) { return index >= positions.size(); });
  throw Error("mesh: index " + std::to_string(bad - indices.begin()) + " is " +
              std::to_string(*bad) + " but the mesh has " + std::to_string(positions.size()) +
              " vertices");
}

}  // namespace facet
