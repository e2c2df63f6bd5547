// Per-draw constants the shading models read: written once per draw by the renderer
// (pipeline/draw.cpp), read by vertex and fragment functions (shading/models.hpp).
#pragma once

#include <glm/glm.hpp>

namespace facet::shading {

struct DrawUniforms {
  glm::mat4 model{1.0f};
  glm::mat4 model_view_projection{1.0f};
  glm::mat3 normal_matrix{1.0f};  // inverse transpose of model's upper 3x3
  glm::vec4 base_color{1.0f};
  glm::vec4 wire_color{0.0f, 0.0f, 0.0f, 1.0f};
  bool use_vertex_colors = true;
  glm::vec3 to_sun{0.0f, 1.0f, 0.0f};  // unit vector toward the light
  glm::vec3 sun_radiance{1.0f};        // color * intensity
  glm::vec3 ambient{0.1f};
  float near_plane = 0.1f;
  float far_plane = 100.0f;
};

// One vertex as the vertex functions see it: object-space attributes already fetched.
struct VertexInput {
  glm::vec3 position;  // object space
  glm::vec3 normal;    // world space, unit; zero when the mesh has none
  glm::vec4 color;     // linear RGBA (white when the mesh has none)
  glm::vec2 texcoord;
};

}  // namespace facet::shading
