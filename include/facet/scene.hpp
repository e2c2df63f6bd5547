// Scene: a list of meshes with materials and transforms, its lighting and a default camera.
// Built-in scenes (the `shapes` teaching scene) are made here; draw_scene records a whole scene.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/renderer.hpp"

namespace facet {

struct SceneObject {
  std::shared_ptr<const Mesh> mesh;
  Material material;
  glm::mat4 transform{1.0f};
};

struct Scene {
  std::vector<SceneObject> objects;
  Lighting lighting;
  Camera camera;  // a good default view
};

// A rectangle ground, a cube, a sphere, a pyramid and an octagonal prism under one sun.
Scene make_shapes_scene();

// Names of the built-in scenes, and the scene for a name (throws facet::Error if unknown).
std::vector<std::string> builtin_scene_names();
Scene make_builtin_scene(const std::string& name);

// Records every object of the scene (the scene must live until renderer.finish()).
void draw_scene(Renderer& renderer, const Scene& scene);

}  // namespace facet
