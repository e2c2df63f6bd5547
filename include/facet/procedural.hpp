// Procedural meshes (facet::worlds): the building blocks of the built-in worlds. Every mesh has
// outward unit normals, texture coordinates in [0, 1] and counter-clockwise front faces (seen from
// outside). The solids (box, cube, pyramid, uv_sphere, prism, cone) close bit for bit: copies of a
// vertex at a seam or a pole have the same position, so shadow maps can draw only their faces
// toward the light.
#pragma once

#include <glm/vec3.hpp>

#include "facet/mesh.hpp"
#include "facet/mesh_tools.hpp"  // transformed, append: how the worlds combine these

namespace facet {

// A rectangle in the XZ plane centred on the origin, facing +Y, split into segments.
Mesh plane(float width, float depth, int segments_x = 1, int segments_z = 1);
// A rectangle in the XY plane centred on the origin, facing +Z.
Mesh rectangle(float width, float height);
// A quad through four points given counter-clockwise as seen from its front.
Mesh quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3);
// One triangle, counter-clockwise as seen from its front.
Mesh triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c);
// A rectangular prism centred on the origin with the given edge lengths; hard edges.
Mesh box(glm::vec3 size);
Mesh cube(float size = 1.0f);
// A square-based pyramid: base centred on the origin in the XZ plane, apex at +Y height.
Mesh pyramid(float base_width, float base_depth, float height);
// A UV sphere centred on the origin.
Mesh uv_sphere(float radius = 0.5f, int segments = 32, int rings = 16);
// An n-sided prism around +Y (a cylinder for large n; n = 8 gives the octagonal prism),
// base at y = 0, top at y = height, with caps. Sides are flat-shaded for n <= 12.
Mesh prism(int sides, float radius, float height);
// A cone around +Y: base disk at y = 0, apex at y = height.
Mesh cone(float radius, float height, int segments = 32);

}  // namespace facet
