// Whether a mesh bounds a solid, and which way its triangles face, for the shadow maps' passes
// (shadow_passes.cpp): along a ray from outside, the nearest point of a closed surface lies on a
// triangle whose outer side faces the ray, so a map needs only the triangles facing its light.
#pragma once

#include <cstddef>

#include "facet/mesh.hpp"

namespace facet::pipeline {

// Meshes of more triangles are taken as open. The test costs about 0.1-0.2 us a triangle, once
// per mesh: for a big model rendered once (a thumbnail) more than the culling saves; a world's
// many small meshes (the islands' largest closed one has under 4,000) pay it once.
inline constexpr std::size_t kMaxClosedSurfaceTriangles = std::size_t{1} << 13;

// Closed: the mesh's triangles, their vertices welded where their positions are equal, share
// every edge with exactly one other triangle, which runs along it the other way (a closed,
// consistently wound surface; triangles with two corners at one position, a line at most, are left
// out). Its front faces (counter-clockwise) then face out when the volume they enclose, by the
// divergence theorem, is positive, and in when it is negative. Open for strips, lines and points,
// for non-finite positions, and past kMaxClosedSurfaceTriangles.
enum class Closure { open, fronts_out, fronts_in };
Closure closed_surface(const Mesh& mesh);

}  // namespace facet::pipeline
