// The world-space positions of a scene's first drawn mesh, for tests of posed glTF models.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "facet/scene.hpp"

namespace facet::test {

// The positions of the first mesh a node draws, its node's world transform applied; empty when
// no node draws anything.
inline std::vector<glm::vec3> world_positions(const Scene& scene) {
  for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
    if (scene.nodes[n].instances.empty()) continue;
    const glm::mat4 world = scene.world_transform(static_cast<int>(n));
    std::vector<glm::vec3> out;
    for (const glm::vec3& p : scene.meshes.at(scene.nodes[n].instances[0].mesh)->positions)
      out.emplace_back(world * glm::vec4(p, 1.0f));
    return out;
  }
  return {};
}

}  // namespace facet::test
