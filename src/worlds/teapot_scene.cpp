// The built-in `teapot` scene: the Utah teapot alone, with no ground, under three-point lights
// set from the framing camera — the classic test of smooth normals and specular highlights.
#include <glm/mat4x4.hpp>
#include <utility>

#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/scene.hpp"
#include "facet/teapot.hpp"

namespace facet {

Scene make_teapot_scene() {
  Material material;
  material.name = "porcelain";
  material.shading = ShadingModel::blinn_phong;
  material.base_color = {0.8f, 0.75f, 0.65f, 1.0f};  // warm off-white, linear
  material.specular_color = glm::vec3(0.5f);
  material.shininess = 48.0f;

  Scene scene;
  scene.add_object(teapot(12), std::move(material), glm::mat4(1.0f), "teapot");
  // The lights follow the view, so the camera comes first.
  scene.framing = Framing{};
  scene.camera = frame_scene(scene, 16.0f / 9.0f, *scene.framing);
  scene.lighting.lights = three_point_lights(scene.camera.forward(), scene.camera.right());
  return scene;
}

}  // namespace facet
