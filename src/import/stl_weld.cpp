// stl::weld(): an STL file's triangle soup (three corners a triangle, each position written
// again for every triangle around it) made an indexed mesh, on all cores, at load time. The
// mesh the renderer reads then holds each position once: a fifth of the soup's bytes.
//
// Four passes over the corners, each split into fixed ranges (so the result never depends on
// the schedule):
//   1. insert every corner into an open-addressing table keyed by its position's bits; a slot
//      keeps the smallest corner index with that position (an atomic minimum, so whichever
//      thread comes first, the slot ends with the same corner), and note each corner's slot;
//   2. note whether each corner is its slot's smallest corner (the "first");
//   3. number the firsts in corner order (a prefix sum over the ranges) and write the number
//      into their slot, and their position into the mesh;
//   4. each corner's index is its slot's number.
// The table holds only corner indices; keys are compared by reading the corners, so nothing is
// stored per key. Positions are compared bit for bit; the reader has made -0 into +0.
#include <atomic>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "import/stl_format.hpp"

namespace facet::io::stl {
namespace {

constexpr std::uint32_t kEmpty = ~std::uint32_t{0};
constexpr std::uint32_t kFirst = 0x8000'0000u;  // marks a first corner's slot in pass 2
constexpr std::size_t kCornersPerTask = 1 << 16;

bool same(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::uint64_t hash(const glm::vec3& p) {
  std::uint32_t w[3];
  std::memcpy(w, &p, sizeof w);
  // Mixes the three words (a multiply-xorshift, as in splitmix64) so that the regular
  // coordinates of a tessellated grid still spread over the table.
  std::uint64_t h = (std::uint64_t{w[0]} << 32 | w[1]) * 0x9E3779B97F4A7C15ull;
  h ^= (h >> 29) ^ (std::uint64_t{w[2]} * 0xBF58476D1CE4E5B9ull);
  h *= 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

template <class Body>
void for_each_range(std::size_t n, const Body& body) {
  const int tasks = static_cast<int>((n + kCornersPerTask - 1) / kCornersPerTask);
  parallel_tasks(tasks, [&](int task) {
    const std::size_t begin = static_cast<std::size_t>(task) * kCornersPerTask;
    body(task, begin, std::min(n, begin + kCornersPerTask));
  });
}

}  // namespace

Mesh weld(std::vector<glm::vec3> corners) {
  Mesh mesh;
  const std::size_t n = corners.size();
  if (n == 0) return mesh;
  // At most two thirds full even when no two corners share a position; slot numbers stay below
  // kFirst because kMaxTriangles (3 corners each) keeps the table within 2^31 slots.
  const std::size_t size = std::bit_ceil(std::max<std::size_t>(16, n + n / 2));
  const std::size_t mask = size - 1;
  std::vector<std::uint32_t> table(size, kEmpty);

  // Pass 1: every corner in the table, each slot ending with its position's smallest corner;
  // each corner's slot noted in its index (slots never move once taken).
  mesh.indices.resize(n);
  for_each_range(n, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const glm::vec3& p = corners[i];
      const auto me = static_cast<std::uint32_t>(i);
      std::size_t slot = hash(p) & mask;
      for (;; slot = (slot + 1) & mask) {
        std::atomic_ref<std::uint32_t> cell(table[slot]);
        std::uint32_t held = cell.load(std::memory_order_relaxed);
        if (held == kEmpty) {
          if (cell.compare_exchange_strong(held, me, std::memory_order_relaxed)) break;
          // Taken meanwhile: `held` is what took it, compared below.
        }
        if (!same(corners[held], p)) continue;
        while (me < held && !cell.compare_exchange_weak(held, me, std::memory_order_relaxed)) {
        }
        break;
      }
      mesh.indices[i] = static_cast<std::uint32_t>(slot);
    }
  });

  // Pass 2: the corners that are their position's first, marked and counted per range.
  const int tasks = static_cast<int>((n + kCornersPerTask - 1) / kCornersPerTask);
  std::vector<std::uint32_t> firsts(static_cast<std::size_t>(tasks) + 1, 0);
  for_each_range(n, [&](int task, std::size_t begin, std::size_t end) {
    std::uint32_t count = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const bool first = table[mesh.indices[i]] == i;
      mesh.indices[i] |= first ? kFirst : 0u;
      count += first;
    }
    firsts[static_cast<std::size_t>(task) + 1] = count;
  });
  for (int t = 0; t < tasks; ++t) firsts[t + 1] += firsts[t];

  // Pass 3: the firsts numbered in corner order; their slots now hold the number.
  mesh.positions.resize(firsts.back());
  for_each_range(n, [&](int task, std::size_t begin, std::size_t end) {
    std::uint32_t id = firsts[static_cast<std::size_t>(task)];
    for (std::size_t i = begin; i < end; ++i) {
      if (!(mesh.indices[i] & kFirst)) continue;
      table[mesh.indices[i] & ~kFirst] = id;
      mesh.positions[id++] = corners[i];
    }
  });
  corners = {};

  // Pass 4: every corner's vertex.
  for_each_range(n, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) mesh.indices[i] = table[mesh.indices[i] & ~kFirst];
  });
  return mesh;
}

}  // namespace facet::io::stl
