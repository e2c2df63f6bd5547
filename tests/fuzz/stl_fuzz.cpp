// libFuzzer target for facet's STL reader (src/import/stl_format.cpp, stl_weld.cpp): any input
// must either give a welded mesh that passes Mesh::validate() with the reader's promises kept
// (indexed triangles, every position finite, used and distinct, no normals) or throw
// facet::Error. A crash, a hang, a sanitizer report or an inconsistent mesh is a bug. Run with
// `make test-fuzz` (corpus: corpus/stl/).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <unordered_set>
#include <vector>

#include "facet/error.hpp"
#include "import/stl_format.hpp"

namespace {

struct BitsHash {
  std::size_t operator()(const glm::vec3& p) const {
    std::uint32_t w[3];
    std::memcpy(w, &p, sizeof w);
    return (std::size_t{w[0]} * 31 + w[1]) * 31 + w[2];
  }
};
struct BitsEqual {
  bool operator()(const glm::vec3& a, const glm::vec3& b) const {
    return std::memcmp(&a, &b, sizeof a) == 0;
  }
};

void check(const facet::Mesh& mesh) {
  mesh.validate();
  if (mesh.topology != facet::Topology::triangles || !mesh.normals.empty()) __builtin_trap();
  if (mesh.indices.size() % 3 != 0) __builtin_trap();
  std::vector<bool> used(mesh.positions.size(), false);
  for (std::uint32_t index : mesh.indices) used[index] = true;
  for (bool u : used) {
    if (!u) __builtin_trap();
  }
  std::unordered_set<glm::vec3, BitsHash, BitsEqual> seen;
  for (const glm::vec3& p : mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
    if (!seen.insert(p).second) __builtin_trap();  // welding left two the same
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto source = facet::io::stl::memory_source(reinterpret_cast<const char*>(data), size);
  try {
    check(facet::io::stl::parse(source, "fuzz.stl").mesh);
  } catch (const facet::Error&) {
    // Malformed input: the expected outcome for most fuzz inputs.
  }
  return 0;
}
