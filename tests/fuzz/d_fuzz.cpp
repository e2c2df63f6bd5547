// libFuzzer target for facet's `.d` reader (src/io/d_format.cpp) and the smooth normals it
// computes (src/scene/normals.cpp): any input must either give a mesh that passes
// Mesh::validate() with one unit normal per vertex, or throw facet::Error. A crash, a sanitizer
// report or an inconsistent mesh is a bug. Run with `make test-fuzz` (corpus: corpus/d/).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>
#include <string>

#include "facet/error.hpp"
#include "facet/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const facet::Mesh mesh = facet::parse_d(text, "fuzz.d");
    mesh.validate();
    if (mesh.normals.size() != mesh.positions.size()) __builtin_trap();
    for (const glm::vec3& n : mesh.normals) {
      if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f)) __builtin_trap();
    }
  } catch (const facet::Error&) {
    // Malformed input: the expected outcome for most fuzz inputs.
  }
  return 0;
}
