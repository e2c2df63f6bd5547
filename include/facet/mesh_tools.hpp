// Mesh tools (facet::core): normals and tangents for meshes that come without, texture
// projections, and transforming or merging meshes. Used by the importers and the worlds alike.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "facet/mesh.hpp"

namespace facet {

// Smooth vertex normals for a triangle mesh (area-weighted, split at crease_angle_degrees):
// vertices are duplicated where the split needs it.
void compute_smooth_normals(Mesh& mesh, float crease_angle_degrees = 80.0f);
// Makes vertices whose attributes are all identical (bit for bit, -0 and +0 alike) one vertex,
// the first of them, with indices; the triangles and what they draw stay the same.
void join_identical_vertices(Mesh& mesh);
// The opposite: each index becomes a vertex of its own (every attribute read through the
// indices), and the indices are dropped; the same primitives, drawn without indices.
void expand_indices(Mesh& mesh);
// Tangents (xyz, w = handedness) from positions, normals and texture coordinates.
void compute_tangents(Mesh& mesh);

// Texture projections for meshes without texture coordinates (the classic course renderers'
// way to put a brick or marble image on a cow). Computed from object-space positions around
// `centre`, so the texture stays fixed to the model as it turns.
enum class TextureProjection {
  spherical,    // u = longitude, v = latitude of the direction from the centre
  cylindrical,  // u = angle around +Y, v = height within the bounds
  planar,       // u, v = x, y within the bounds (projected along Z)
};
// Replaces the mesh's texture coordinates; vertices of triangles that straddle the
// longitude seam are duplicated so the texture does not smear across it.
void project_texcoords(Mesh& mesh, TextureProjection projection, glm::vec3 centre);

// Returns the mesh with positions (and normals, tangents) transformed by m.
Mesh transformed(Mesh mesh, const glm::mat4& m);
// Appends b to a (same topology required); used to merge shapes into one draw.
void append(Mesh& a, const Mesh& b);

}  // namespace facet
