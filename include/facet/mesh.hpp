// Mesh: vertex attributes plus optional indices, drawn as triangle lists, strips, lines or points.
// Attributes other than positions are optional: empty, or one per vertex.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace facet {

enum class Topology {
  triangles,       // every 3 vertices (or indices) form a triangle
  triangle_strip,  // each new vertex forms a triangle with the two before it
  lines,           // every 2 vertices (or indices) form a line segment
  // Every vertex (or index) is a point: a square Material::point_size pixels a side, in the
  // vertex color times the material's base color, unlit (src/pipeline/raster/point.cpp).
  points,
};

struct Mesh {
  Topology topology = Topology::triangles;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // empty: face normals are used
  std::vector<glm::vec2> texcoords;    // empty: (0, 0)
  std::vector<glm::vec4> colors;       // linear RGBA; empty: white
  std::vector<glm::vec4> tangents;     // xyz tangent, w handedness; empty: none
  std::vector<std::uint32_t> indices;  // empty: non-indexed

  // Number of vertices the topology walks (indices if present, else positions).
  std::size_t element_count() const { return indices.empty() ? positions.size() : indices.size(); }
  // Triangles (or line segments for Topology::lines, points for Topology::points) this mesh
  // draws.
  std::size_t primitive_count() const;

  // Throws facet::Error naming the first inconsistency (attribute sizes, index out of range).
  void validate() const;
};

}  // namespace facet
