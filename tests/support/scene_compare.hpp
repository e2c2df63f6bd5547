// Two imported scenes compared in everything the renderer, the instance ids and the outputs read:
// meshes, materials (and their textures' pixels), nodes, cameras, lights. Used where two readers
// of one file must agree (the fenced and the unfenced assimp read; facet's own OBJ reader and
// assimp's).
#pragma once

#include <cstdint>

#include "facet/scene.hpp"

namespace facet::test {

// Adds a GoogleTest failure for each difference. Positions and texture coordinates may differ by
// `ulps` units in the last place, and normals by twice that (made from positions that differ);
// every other value must be equal.
void expect_same_scene(const Scene& a, const Scene& b, std::int64_t ulps = 0);

}  // namespace facet::test
