// Vertex normals and tangents for meshes that come without them. Written by the importers
// (assimp, `.d`) once per mesh at load time; read by the vertex stage like any other attribute.
//
// Smooth normals: each corner of a triangle gets the sum of the area-weighted normals of the
// faces around its position that lie within the crease angle of its own face, so a cube stays
// faceted and a sphere stays smooth. Corners are first welded by position (so UV seams do not
// break smoothing), then a vertex is duplicated only where its corners need different normals.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <span>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "core/parallel.hpp"
#include "core/position_ids.hpp"
#include "facet/mesh_tools.hpp"

namespace facet {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// Runs body(begin, end) over [0, faces) in ranges of kFacesPerTask, on all cores: enough faces
// per task to outweigh a task's start.
constexpr std::size_t kFacesPerTask = 4096;
template <class Body>
void for_each_face_range(std::size_t faces, const Body& body) {
  const int tasks = static_cast<int>((faces + kFacesPerTask - 1) / kFacesPerTask);
  parallel_tasks(tasks, default_workers(), [&](int task, int) {
    const std::size_t begin = static_cast<std::size_t>(task) * kFacesPerTask;
    body(begin, std::min(faces, begin + kFacesPerTask));
  });
}

// The triangles a mesh draws, as vertex indices (strips unrolled with their winding kept).
std::vector<Triangle> triangles_of(const Mesh& mesh) {
  std::vector<Triangle> out;
  const std::size_t count = mesh.element_count();
  auto at = [&](std::size_t i) {
    return mesh.indices.empty() ? static_cast<std::uint32_t>(i) : mesh.indices[i];
  };
  if (mesh.topology == Topology::triangles) {
    out.reserve(count / 3);
    for (std::size_t i = 0; i + 2 < count; i += 3) out.push_back({at(i), at(i + 1), at(i + 2)});
  } else if (mesh.topology == Topology::triangle_strip) {
    for (std::size_t i = 0; i + 2 < count; ++i) {
      // Every other strip triangle is wound the other way round (GL 4.6 §10.1.8).
      if (i % 2 == 0)
        out.push_back({at(i), at(i + 1), at(i + 2)});
      else
        out.push_back({at(i + 1), at(i), at(i + 2)});
    }
  }
  return out;
}

// Bit-exact keys: welding must only merge vertices that are truly identical. Fixed size (a
// vertex's attributes are at most 3 + 3 + 2 + 4 + 4 floats), so that keys never allocate:
// loading a big mesh makes hundreds of thousands of them.
struct Bits {
  static constexpr int kMaxWords = 16;
  std::array<std::uint32_t, kMaxWords> words;
  int count = 0;
  void clear() { count = 0; }
  void push_back(std::uint32_t w) { words[count++] = w; }
  bool operator==(const Bits& other) const {
    return count == other.count &&
           std::equal(words.begin(), words.begin() + count, other.words.begin());
  }
};
struct BitsHash {
  std::size_t operator()(const Bits& b) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the words
    for (int i = 0; i < b.count; ++i) h = (h ^ b.words[i]) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

template <class V>
void append_bits(Bits& key, const V& value) {
  for (int i = 0; i < V::length(); ++i) {
    float f = value[i];
    if (f == 0.0f) f = 0.0f;  // -0 and +0 weld
    std::uint32_t w;
    std::memcpy(&w, &f, sizeof w);
    key.push_back(w);
  }
}

// What smoothing welds by: ids such that two vertices share an id exactly when every attribute
// but the normal is identical (the id of the first of them), and ids for positions alone (the
// smoothing neighbourhood).
struct Welding {
  std::vector<std::uint32_t> vertex_id;
  std::vector<std::uint32_t> position_id;
  std::uint32_t position_count = 0;
};

// For each item i < n, the first item whose key (key_of(item, Bits&)) equals its own. An
// open-addressing table of item indices whose keys are rebuilt to compare them: nothing is
// stored or allocated per key.
template <class KeyOf>
std::vector<std::uint32_t> first_with_equal_key(std::size_t n, const KeyOf& key_of) {
  constexpr std::uint32_t kEmpty = ~std::uint32_t{0};
  std::size_t size = 16;
  while (size < 2 * n) size *= 2;  // at most half full
  std::vector<std::uint32_t> table(size, kEmpty);
  std::vector<std::uint32_t> first(n);
  Bits key, other;
  for (std::uint32_t i = 0; i < n; ++i) {
    key_of(i, key);
    const std::uint64_t h = BitsHash{}(key);
    for (std::size_t slot = (h ^ (h >> 32)) & (size - 1);; slot = (slot + 1) & (size - 1)) {
      const std::uint32_t j = table[slot];
      if (j == kEmpty) {
        table[slot] = first[i] = i;
        break;
      }
      key_of(j, other);
      if (other == key) {
        first[i] = j;
        break;
      }
    }
  }
  return first;
}

// For each vertex, the first vertex whose attributes are all identical to its own (normals
// compared only if `with_normals`).
std::vector<std::uint32_t> identical_vertices(const Mesh& mesh, bool with_normals) {
  return first_with_equal_key(mesh.positions.size(), [&](std::uint32_t i, Bits& key) {
    key.clear();
    append_bits(key, mesh.positions[i]);
    if (with_normals && !mesh.normals.empty()) append_bits(key, mesh.normals[i]);
    if (!mesh.texcoords.empty()) append_bits(key, mesh.texcoords[i]);
    if (!mesh.colors.empty()) append_bits(key, mesh.colors[i]);
    if (!mesh.tangents.empty()) append_bits(key, mesh.tangents[i]);
  });
}

Welding weld(const Mesh& mesh) {
  Welding w;
  w.position_id = position_ids(mesh.positions, w.position_count);
  w.vertex_id = identical_vertices(mesh, false);  // the normals are being replaced
  return w;
}

struct Face {
  glm::vec3 weighted;  // cross product: length is twice the area
  glm::vec3 unit;
  bool degenerate;
};

Face face_normal(const Mesh& mesh, const Triangle& t) {
  const glm::vec3& a = mesh.positions[t[0]];
  glm::vec3 n = glm::cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a);
  float length = glm::length(n);
  if (!(length > 1e-30f) || !std::isfinite(length)) return {glm::vec3(0.0f), glm::vec3(0.0f), true};
  return {n, n / length, false};
}

// The faces around each welded position, in face order (so equal sets sum to equal bits): the
// faces around position p are list[offset[p]] .. list[offset[p + 1] - 1].
struct FacesAround {
  std::vector<std::uint32_t> offset;
  std::vector<std::uint32_t> list;
  std::span<const std::uint32_t> of(std::uint32_t position) const {
    return {list.data() + offset[position], list.data() + offset[position + 1]};
  }
};

FacesAround faces_around(const std::vector<Triangle>& triangles, const std::vector<Face>& faces,
                         const Welding& w) {
  // Each face once per distinct position among its corners.
  auto for_each_position = [&](std::size_t f, auto&& visit) {
    const Triangle& t = triangles[f];
    const std::uint32_t p0 = w.position_id[t[0]], p1 = w.position_id[t[1]],
                        p2 = w.position_id[t[2]];
    visit(p0);
    if (p1 != p0) visit(p1);
    if (p2 != p0 && p2 != p1) visit(p2);
  };
  FacesAround around;
  around.offset.assign(w.position_count + 1, 0);
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    if (!faces[f].degenerate)
      for_each_position(f, [&](std::uint32_t p) { ++around.offset[p + 1]; });
  }
  for (std::uint32_t p = 0; p < w.position_count; ++p) around.offset[p + 1] += around.offset[p];
  around.list.resize(around.offset.back());
  std::vector<std::uint32_t> filled(around.offset.begin(), around.offset.end() - 1);
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    if (faces[f].degenerate) continue;
    for_each_position(
        f, [&](std::uint32_t p) { around.list[filled[p]++] = static_cast<std::uint32_t>(f); });
  }
  return around;
}

// The normal of one corner: adjacent faces within the crease of its own face. A degenerate
// face has no normal to compare against, so its corners take every face around them.
glm::vec3 corner_normal(std::span<const std::uint32_t> around, const std::vector<Face>& faces,
                        std::uint32_t face, float cos_crease) {
  glm::vec3 sum(0.0f);
  const Face& own = faces[face];
  for (std::uint32_t g : around) {
    if (own.degenerate || glm::dot(own.unit, faces[g].unit) >= cos_crease) sum += faces[g].weighted;
  }
  float length = glm::length(sum);
  if (length > 1e-30f && std::isfinite(length)) return sum / length;
  return own.degenerate ? glm::vec3(0.0f, 0.0f, 1.0f) : own.unit;
}

// Corners around a busy position (the centre of a finely divided disc) mostly share their
// face's normal, so their result is cached: such a vertex costs O(faces), not O(faces^2). One
// per thread: the cache only saves work, each normal is the same whichever computes it.
constexpr std::size_t kBusyPosition = 64;

class CornerNormals {
 public:
  CornerNormals(const Welding& w, const std::vector<Face>& faces, const FacesAround& around,
                float cos_crease)
      : w_(w), faces_(faces), around_(around), cos_crease_(cos_crease) {}

  glm::vec3 operator()(std::uint32_t vertex, std::uint32_t face) {
    const std::uint32_t position = w_.position_id[vertex];
    const std::span<const std::uint32_t> here = around_.of(position);
    if (here.size() <= kBusyPosition) return corner_normal(here, faces_, face, cos_crease_);
    key_.clear();
    key_.push_back(position);
    key_.push_back(faces_[face].degenerate ? 1u : 0u);
    append_bits(key_, faces_[face].unit);
    auto [it, fresh] = busy_.try_emplace(key_);
    if (fresh) it->second = corner_normal(here, faces_, face, cos_crease_);
    return it->second;
  }

 private:
  const Welding& w_;
  const std::vector<Face>& faces_;
  const FacesAround& around_;
  float cos_crease_;
  Bits key_;
  std::unordered_map<Bits, glm::vec3, BitsHash> busy_;
};

template <class T>
void copy_attribute(std::vector<T>& out, const std::vector<T>& in, std::uint32_t from) {
  if (!in.empty()) out.push_back(in[from]);
}

}  // namespace

void compute_smooth_normals(Mesh& mesh, float crease_angle_degrees) {
  mesh.validate();  // the helpers above trust the indices
  if (mesh.topology == Topology::lines || mesh.topology == Topology::points) return;  // no faces
  if (mesh.positions.empty()) return;
  const std::vector<Triangle> triangles = triangles_of(mesh);
  const Welding w = weld(mesh);
  std::vector<Face> faces(triangles.size());
  for_each_face_range(triangles.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) faces[f] = face_normal(mesh, triangles[f]);
  });
  const FacesAround around = faces_around(triangles, faces, w);
  // A little slack so faces that are coplanar up to rounding always smooth together.
  const float crease = std::clamp(crease_angle_degrees, 0.0f, 180.0f);
  const float cos_crease = std::cos(glm::radians(crease)) - 1e-5f;

  // The normal of each corner (3 per face), on all cores: each depends on its face and the
  // faces around its position only.
  std::vector<glm::vec3> corner(triangles.size() * 3);
  for_each_face_range(triangles.size(), [&](std::size_t begin, std::size_t end) {
    CornerNormals corner_normals(w, faces, around, cos_crease);
    for (std::size_t f = begin; f < end; ++f) {
      for (int k = 0; k < 3; ++k)
        corner[f * 3 + k] = corner_normals(triangles[f][k], static_cast<std::uint32_t>(f));
    }
  });

  Mesh out;
  out.topology = Topology::triangles;
  out.indices.reserve(triangles.size() * 3);
  // Output vertices are (source vertex, normal) pairs, in order of first use. Each source
  // vertex has one or a few (more only along creases): a chain of them per source.
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> first_output(mesh.positions.size(), kNone), next_output;
  Bits normal_bits, other_bits;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t source = w.vertex_id[triangles[f][k]];
      const glm::vec3 n = corner[f * 3 + k];
      normal_bits.clear();
      append_bits(normal_bits, n);
      std::uint32_t o = first_output[source];
      for (; o != kNone; o = next_output[o]) {
        other_bits.clear();
        append_bits(other_bits, out.normals[o]);
        if (other_bits == normal_bits) break;
      }
      if (o == kNone) {
        o = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(mesh.positions[source]);
        out.normals.push_back(n);
        copy_attribute(out.texcoords, mesh.texcoords, source);
        copy_attribute(out.colors, mesh.colors, source);
        copy_attribute(out.tangents, mesh.tangents, source);
        next_output.push_back(first_output[source]);
        first_output[source] = o;
      }
      out.indices.push_back(o);
    }
  }
  mesh = std::move(out);
}

void join_identical_vertices(Mesh& mesh) {
  mesh.validate();
  const std::vector<std::uint32_t> first = identical_vertices(mesh, true);
  // The first vertex of each set of identical ones is kept, in their order.
  std::vector<std::uint32_t> new_index(mesh.positions.size());
  std::uint32_t kept = 0;
  for (std::size_t i = 0; i < new_index.size(); ++i) {
    new_index[i] = first[i] == i ? kept++ : new_index[first[i]];
  }
  if (kept == mesh.positions.size()) return;  // nothing to join
  auto compact = [&](auto& attribute) {
    if (attribute.empty()) return;
    for (std::size_t i = 0; i < new_index.size(); ++i) {
      if (first[i] == i) attribute[new_index[i]] = attribute[i];
    }
    attribute.resize(kept);
  };
  compact(mesh.positions);
  compact(mesh.normals);
  compact(mesh.texcoords);
  compact(mesh.colors);
  compact(mesh.tangents);
  if (mesh.indices.empty()) {
    mesh.indices = std::move(new_index);  // vertex i of the old list is now this one
  } else {
    for (std::uint32_t& index : mesh.indices) index = new_index[index];
  }
}

void expand_indices(Mesh& mesh) {
  if (mesh.indices.empty()) return;
  auto expand = [&](auto& attribute) {
    if (attribute.empty()) return;
    std::remove_reference_t<decltype(attribute)> expanded;
    expanded.reserve(mesh.indices.size());
    for (std::uint32_t index : mesh.indices) expanded.push_back(attribute[index]);
    attribute = std::move(expanded);
  };
  expand(mesh.positions), expand(mesh.normals), expand(mesh.texcoords);
  expand(mesh.colors), expand(mesh.tangents);
  mesh.indices.clear();
}

void compute_tangents(Mesh& mesh) {
  mesh.validate();
  if (mesh.topology == Topology::lines || mesh.topology == Topology::points) return;  // no faces
  if (mesh.positions.empty()) return;
  if (mesh.normals.size() != mesh.positions.size()) compute_smooth_normals(mesh);
  const std::size_t n = mesh.positions.size();
  std::vector<glm::vec3> tangent(n, glm::vec3(0.0f)), bitangent(n, glm::vec3(0.0f));
  if (mesh.texcoords.size() == n) {
    for (const Triangle& t : triangles_of(mesh)) {
      glm::vec3 e1 = mesh.positions[t[1]] - mesh.positions[t[0]];
      glm::vec3 e2 = mesh.positions[t[2]] - mesh.positions[t[0]];
      glm::vec2 d1 = mesh.texcoords[t[1]] - mesh.texcoords[t[0]];
      glm::vec2 d2 = mesh.texcoords[t[2]] - mesh.texcoords[t[0]];
      float det = d1.x * d2.y - d2.x * d1.y;
      if (!(std::abs(det) > 1e-20f) || !std::isfinite(det)) continue;  // no uv area: no frame
      // Solve [e1 e2] = [T B] [d1 d2] for the directions of +u (T) and +v (B) on the surface.
      glm::vec3 tu = (e1 * d2.y - e2 * d1.y) / det;
      glm::vec3 tv = (e2 * d1.x - e1 * d2.x) / det;
      if (!std::isfinite(glm::dot(tu, tu)) || !std::isfinite(glm::dot(tv, tv))) continue;
      for (std::uint32_t v : t) {
        tangent[v] += tu;
        bitangent[v] += tv;
      }
    }
  }
  mesh.tangents.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 normal = mesh.normals[i];
    // Gram-Schmidt: the part of the accumulated tangent perpendicular to the normal.
    glm::vec3 t = tangent[i] - normal * glm::dot(normal, tangent[i]);
    float length = glm::length(t);
    if (!(length > 1e-12f) || !std::isfinite(length)) {
      // No usable uv: any direction perpendicular to the normal keeps normal mapping harmless.
      glm::vec3 axis = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
      t = glm::cross(axis, normal);
      length = glm::length(t);
      mesh.tangents[i] = length > 0.0f ? glm::vec4(t / length, 1.0f) : glm::vec4(1, 0, 0, 1);
      continue;
    }
    float w = glm::dot(glm::cross(normal, t), bitangent[i]) < 0.0f ? -1.0f : 1.0f;
    mesh.tangents[i] = glm::vec4(t / length, w);
  }
}

std::vector<std::uint32_t> position_ids(const std::vector<glm::vec3>& positions,
                                        std::uint32_t& count) {
  const std::size_t n = positions.size();
  const std::vector<std::uint32_t> same_position =
      first_with_equal_key(n, [&](std::uint32_t i, Bits& key) {
        key.clear();
        append_bits(key, positions[i]);
      });
  std::vector<std::uint32_t> ids(n);
  count = 0;
  for (std::size_t i = 0; i < n; ++i) {  // numbered in order of first appearance
    ids[i] = same_position[i] == i ? count++ : ids[same_position[i]];
  }
  return ids;
}

}  // namespace facet
