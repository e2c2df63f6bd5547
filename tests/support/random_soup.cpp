// Random triangle soups for the comparisons against the reference rasterizer.
#include "support/random_soup.hpp"

#include <glm/glm.hpp>

namespace facet::test {

std::vector<glm::vec3> random_soup(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 4);
  std::uniform_int_distribution<int> count(1, 24);
  std::vector<glm::vec3> positions;
  int n = count(rng);
  for (int t = 0; t < n; ++t) {
    float depth = 1.0f + 9.0f * (unit(rng) + 1.0f);
    glm::vec3 centre{unit(rng) * depth, unit(rng) * depth * 0.6f, -depth};
    glm::vec3 v[3];
    switch (kind(rng)) {
      case 0:  // small
        for (auto& p : v) p = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 0.3f;
        break;
      case 1:  // large, partly off screen
        for (auto& p : v) p = centre + glm::vec3(unit(rng), unit(rng), unit(rng) * 0.3f) * 25.0f;
        break;
      case 2: {  // sliver: the third vertex almost on the line of the first two
        v[0] = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 4.0f;
        v[1] = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 4.0f;
        v[2] = glm::mix(v[0], v[1], 0.5f * (unit(rng) + 1.0f)) + glm::vec3(unit(rng)) * 0.002f;
        break;
      }
      case 3:  // crossing the near plane / behind the eye
        for (auto& p : v) p = glm::vec3(unit(rng) * 4.0f, unit(rng) * 3.0f, unit(rng) * 3.0f);
        break;
      default:  // shared edge with the previous triangle, when there is one
        if (positions.size() >= 3) {
          v[0] = positions[positions.size() - 1];
          v[1] = positions[positions.size() - 2];
        } else {
          v[0] = centre, v[1] = centre + glm::vec3(1, 0, 0);
        }
        v[2] = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 3.0f;
        break;
    }
    positions.insert(positions.end(), {v[0], v[1], v[2]});
  }
  return positions;
}

}  // namespace facet::test
