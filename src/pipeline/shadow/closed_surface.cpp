// Stage: the shadow maps' passes, which casters are closed surfaces (see closed_surface.hpp).
// Run once per mesh, the first time a shadow pass draws it, so it must cost little next to
// drawing the mesh: flat hash tables (open addressing) rather than node-based sets.
#include "pipeline/shadow/closed_surface.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

namespace facet::pipeline {
namespace {

constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();

std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  return h ^ (h >> 33);
}

// A power of two at least twice n: probes stay short.
std::size_t table_size(std::size_t n) { return std::bit_ceil(2 * n + 1); }

// Each vertex's welded id: the first vertex at its position (+0 and -0 alike). Empty when a
// position is not finite.
std::vector<std::uint32_t> welded_ids(const std::vector<glm::vec3>& positions) {
  struct Slot {
    std::uint32_t x, y, z, id = kEmpty;
  };
  const std::size_t mask = table_size(positions.size()) - 1;
  std::vector<Slot> table(mask + 1);
  std::vector<std::uint32_t> ids(positions.size());
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3 p = positions[v] + glm::vec3(0.0f);  // -0 + 0 is +0
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return {};
    const Slot key{std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
                   std::bit_cast<std::uint32_t>(p.z)};
    std::size_t at = mix(key.x ^ mix(key.y ^ mix(key.z))) & mask;
    for (;; at = (at + 1) & mask) {
      Slot& slot = table[at];
      if (slot.id == kEmpty) {
        slot = {key.x, key.y, key.z, next++};
        break;
      }
      if (slot.x == key.x && slot.y == key.y && slot.z == key.z) break;
    }
    ids[v] = table[at].id;
  }
  return ids;
}

}  // namespace

Closure closed_surface(const Mesh& mesh) {
  if (mesh.topology != Topology::triangles) return Closure::open;
  const std::size_t triangles = mesh.primitive_count();
  if (triangles == 0 || triangles > kMaxClosedSurfaceTriangles) return Closure::open;
  const std::vector<std::uint32_t> id = welded_ids(mesh.positions);
  if (id.empty()) return Closure::open;
  // Each edge once, by its two welded ends, with the directions triangles run along it (bit 0:
  // from the lower id, bit 1: from the higher). A closed, consistently wound surface runs along
  // every edge once each way.
  struct Edge {
    std::uint64_t ends = std::numeric_limits<std::uint64_t>::max();
    std::uint8_t runs = 0;
  };
  const std::size_t mask = table_size(3 * triangles) - 1;
  std::vector<Edge> edges(mask + 1);
  std::size_t edge_count = 0, both_ways = 0;
  const auto index = [&](std::size_t i) { return mesh.indices.empty() ? i : mesh.indices[i]; };
  double volume = 0.0;  // six times the enclosed volume: the sum of p0 . (p1 x p2)
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::size_t v[3] = {index(3 * t), index(3 * t + 1), index(3 * t + 2)};
    const std::uint32_t corner[3] = {id[v[0]], id[v[1]], id[v[2]]};
    // Two corners at one position (a uv sphere's poles): a line at most, which covers nothing.
    if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) continue;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = corner[i], b = corner[(i + 1) % 3];
      const std::uint64_t ends = a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
      const std::uint8_t run = a < b ? 1 : 2;
      std::size_t at = mix(ends) & mask;
      while (edges[at].ends != ends && edges[at].runs != 0) at = (at + 1) & mask;
      Edge& edge = edges[at];
      if (edge.runs & run) return Closure::open;  // a second triangle runs the same way
      if (edge.runs == 0) edge.ends = ends, ++edge_count;
      edge.runs |= run;
      both_ways += edge.runs == 3;
    }
    const glm::dvec3 p0(mesh.positions[v[0]]), p1(mesh.positions[v[1]]), p2(mesh.positions[v[2]]);
    volume += glm::dot(p0, glm::cross(p1, p2));
  }
  if (edge_count == 0 || both_ways != edge_count) return Closure::open;  // a border
  if (volume == 0.0) return Closure::open;                               // flat: no side is outside
  return volume > 0.0 ? Closure::fronts_out : Closure::fronts_in;
}

}  // namespace facet::pipeline
