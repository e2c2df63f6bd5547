// Mesh tools (see facet/mesh_tools.hpp): transforming a mesh and merging two. Used by the
// procedural worlds to build their meshes and by programs that assemble their own.
#include "facet/mesh_tools.hpp"

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

#include "facet/error.hpp"

namespace facet {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

template <class T>
std::string text(T value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void make_indexed(Mesh& mesh) {
  if (!mesh.indices.empty()) return;
  mesh.indices.resize(mesh.positions.size());
  std::iota(mesh.indices.begin(), mesh.indices.end(), 0u);
}

void reverse_winding(Mesh& mesh) {
  // Lines and points have no side.
  if (mesh.topology == Topology::lines || mesh.topology == Topology::points) return;
  if (mesh.positions.empty()) return;
  make_indexed(mesh);
  if (mesh.topology == Topology::triangles) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }
  } else {
    // A strip alternates winding with each triangle's position, so moving every triangle one
    // place on (behind a degenerate one) reverses them all.
    mesh.indices.insert(mesh.indices.begin(), mesh.indices.front());
  }
}

const char* topology_name(Topology topology) {
  constexpr const char* kNames[] = {"triangles", "triangle_strip", "lines",
                                    "points"};  // enum order
  return kNames[static_cast<int>(topology)];
}

// Appends b's values of one attribute to a's; a mesh without the attribute contributes `fill`
// for each of its vertices. Both empty stays empty.
template <class T>
void append_attribute(std::vector<T>& a, std::size_t a_vertices, const std::vector<T>& b,
                      std::size_t b_vertices, T fill) {
  if (a.empty() && b.empty()) return;
  a.resize(a_vertices, fill);
  a.insert(a.end(), b.begin(), b.end());
  a.resize(a_vertices + b_vertices, fill);  // only does something when b lacks the attribute
}

void append_indices(Mesh& a, const Mesh& b, std::uint32_t offset) {
  const std::size_t count = b.element_count();
  if (count == 0) return;
  auto b_index = [&](std::size_t i) {
    return offset + (b.indices.empty() ? static_cast<std::uint32_t>(i) : b.indices[i]);
  };
  if (a.topology == Topology::triangle_strip && !a.indices.empty()) {
    // Join the strips with degenerate triangles: repeat a's last and b's first index, once more
    // if needed so that b's first triangle keeps an even position and so its winding.
    a.indices.push_back(a.indices.back());
    a.indices.push_back(b_index(0));
    if (a.indices.size() % 2 == 1) a.indices.push_back(b_index(0));
  }
  for (std::size_t i = 0; i < count; ++i) a.indices.push_back(b_index(i));
}

}  // namespace

// --- transforming and merging --------------------------------------------------------------

Mesh transformed(Mesh mesh, const glm::mat4& m) {
  const glm::mat3 linear(m);
  const float det = glm::determinant(linear);
  if (!(std::abs(det) > 0.0f && std::isfinite(det))) {
    throw Error("transformed: the matrix is singular (determinant " + text(det) + ")");
  }
  // Normals stay perpendicular to the surface under the inverse transpose; tangents lie in the
  // surface and so move with it.
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  for (vec3& p : mesh.positions) p = vec3(m * vec4(p, 1.0f));  // affine: w is ignored
  for (vec3& n : mesh.normals) n = glm::normalize(normal_matrix * n);
  for (vec4& t : mesh.tangents) {
    // A mirror turns the (tangent, bitangent, normal) frame left-handed.
    t = vec4(glm::normalize(linear * vec3(t)), det < 0.0f ? -t.w : t.w);
  }
  // A mirror also turns counter-clockwise into clockwise; swap back so front faces stay front.
  if (det < 0.0f) reverse_winding(mesh);
  return mesh;
}

void append(Mesh& a, const Mesh& b) {
  if (a.topology != b.topology) {
    throw Error(std::string("append: cannot append a ") + topology_name(b.topology) +
                " mesh to a " + topology_name(a.topology) + " mesh");
  }
  b.validate();
  const std::size_t a_vertices = a.positions.size(), b_vertices = b.positions.size();
  if (a_vertices + b_vertices > std::numeric_limits<std::uint32_t>::max()) {
    throw Error("append: " + text(a_vertices + b_vertices) + " vertices do not fit 32-bit indices");
  }
  // Inventing normals would light the mesh wrongly without a trace; better to say so.
  if (a_vertices > 0 && b_vertices > 0 && a.normals.empty() != b.normals.empty()) {
    throw Error("append: one mesh has normals and the other does not");
  }
  // Strips are always indexed here, since joining them needs repeated indices.
  if (!a.indices.empty() || !b.indices.empty() || a.topology == Topology::triangle_strip) {
    make_indexed(a);
    append_indices(a, b, static_cast<std::uint32_t>(a_vertices));
  }
  append_attribute(a.normals, a_vertices, b.normals, b_vertices, vec3(0.0f, 1.0f, 0.0f));
  append_attribute(a.texcoords, a_vertices, b.texcoords, b_vertices, vec2(0.0f));
  append_attribute(a.colors, a_vertices, b.colors, b_vertices, vec4(1.0f));
  append_attribute(a.tangents, a_vertices, b.tangents, b_vertices, vec4(1.0f, 0.0f, 0.0f, 1.0f));
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
}
}  // namespace facet
