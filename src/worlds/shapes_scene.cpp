// The built-in `shapes` scene: the five basic solids on a ground rectangle under one sun —
// the smallest scene that exercises every shading model and the clipper (the ground runs
// past the view on every side).
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/error.hpp"
#include "facet/procedural.hpp"
#include "facet/worlds.hpp"

namespace facet {
namespace {

glm::vec4 rgb(float r, float g, float b) { return {r, g, b, 1.0f}; }

// The color lives in the vertices (a gentle light-to-dark ramp from top to bottom), so the
// vertex_color view shows the scene too; the material's base color stays white.
void add(Scene& scene, Mesh mesh, glm::vec4 color, glm::vec3 position, float turn_degrees = 0) {
  float low = mesh.positions.empty() ? 0.0f : mesh.positions[0].y, high = low;
  for (const auto& p : mesh.positions) low = std::min(low, p.y), high = std::max(high, p.y);
  for (const auto& p : mesh.positions) {
    float t = high > low ? (p.y - low) / (high - low) : 1.0f;
    mesh.colors.push_back(glm::vec4(glm::vec3(color) * (0.7f + 0.3f * t), color.a));
  }
  Material material;
  material.shading = ShadingModel::lambert;
  glm::mat4 transform = glm::rotate(glm::translate(glm::mat4(1.0f), position),
                                    glm::radians(turn_degrees), glm::vec3(0, 1, 0));
  scene.add_object(std::move(mesh), material, transform);
}

}  // namespace

Scene make_shapes_scene() {
  Scene scene;
  scene.metres_per_unit = 1.0f;  // a cube 1.4 m wide, seen from 2.6 m up
  add(scene, plane(40.0f, 40.0f, 8, 8), rgb(0.32f, 0.42f, 0.30f), {0, 0, 0});
  add(scene, cube(1.4f), rgb(0.80f, 0.18f, 0.14f), {-3.2f, 0.7f, 0.2f}, 25.0f);
  add(scene, uv_sphere(0.85f, 48, 24), rgb(0.15f, 0.35f, 0.80f), {-1.0f, 0.85f, -0.4f});
  add(scene, pyramid(1.6f, 1.6f, 1.7f), rgb(0.90f, 0.70f, 0.15f), {1.1f, 0.0f, 0.3f}, 20.0f);
  add(scene, prism(8, 0.75f, 1.6f), rgb(0.20f, 0.65f, 0.60f), {3.2f, 0.0f, -0.3f}, 10.0f);
  scene.lighting.lights = {Light::directional({0.45f, -1.0f, -0.55f})};
  scene.lighting.ambient = {0.16f, 0.17f, 0.20f};
  scene.camera = Camera::look_at({0.8f, 2.6f, 6.4f}, {0.0f, 0.5f, 0.0f}, {0, 1, 0}, 50.0f,
                                 16.0f / 9.0f, 0.1f, 100.0f);
  return scene;
}

}  // namespace facet
