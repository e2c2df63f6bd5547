// Mesh bookkeeping: how many primitives a mesh draws and whether its arrays agree.
// Written by whoever builds a mesh (loaders, procedural shapes); read by the draw entry points.
#include "facet/mesh.hpp"

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

// Lists must hold whole primitives; strips may have any count (fewer than 3 draws nothing).
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
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= positions.size()) {
      throw Error("mesh: index " + std::to_string(i) + " is " + std::to_string(indices[i]) +
                  " but the mesh has " + std::to_string(positions.size()) + " vertices");
    }
  }
}

}  // namespace facet
