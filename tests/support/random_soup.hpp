// Random triangle soups for the comparisons against the reference rasterizer (reference_test,
// simd_targets_test): every kind of triangle the fast path must agree on.
#pragma once

#include <glm/vec3.hpp>
#include <random>
#include <vector>

namespace facet::test {

// Small, large, slivers, partly off screen, crossing the near plane or with vertices behind
// the eye (for a camera at the origin looking down -Z), and shared edges; every 3 positions a
// triangle.
std::vector<glm::vec3> random_soup(std::mt19937& rng);

}  // namespace facet::test
