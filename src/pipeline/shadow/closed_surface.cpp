// Stage: the shadow maps' passes, which casters are closed surfaces (see closed_surface.hpp).
// Run once per mesh, the first time a shadow pass draws it, so it must cost little next to
// drawing the mesh: positions welded as smoothing welds them (core/position_ids.hpp), edges in a
// flat hash table (open addressing) rather than a node-based set.
#include "pipeline/shadow/closed_surface.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "core/position_ids.hpp"

namespace facet::pipeline {
namespace {

std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  return h ^ (h >> 33);
}

// A power of two at least twice n: probes stay short.
std::size_t table_size(std::size_t n) { return std::bit_ceil(2 * n + 1); }

}  // namespace

Closure closed_surface(const Mesh& mesh) {
  if (mesh.topology != Topology::triangles) return Closure::open;
  const std::size_t triangles = mesh.primitive_count();
  if (triangles == 0 || triangles > kMaxClosedSurfaceTriangles) return Closure::open;
  for (const glm::vec3& p : mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return Closure::open;
  }
  std::uint32_t positions = 0;
  const std::vector<std::uint32_t> id = position_ids(mesh.positions, positions);
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
