// Welding by position (core/mesh_normals.cpp, which smooths normals across a mesh's seams, and
// the shadow passes' closed casters, pipeline/shadow/closed_surface.cpp).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace facet {

// Each vertex's position id: two vertices share one exactly when their positions are bit for bit
// equal (-0 and +0 alike), numbered in order of first appearance; `count` gets how many there are.
std::vector<std::uint32_t> position_ids(const std::vector<glm::vec3>& positions,
                                        std::uint32_t& count);

}  // namespace facet
