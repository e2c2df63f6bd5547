// The built-in worlds (facet::worlds): the scenes `facet render --scene` and `facet view`
// draw, by name, and the procedural meshes, the teapot and the islands they are made of.
#pragma once

#include <string>
#include <vector>

#include "facet/islands.hpp"
#include "facet/procedural.hpp"
#include "facet/scene.hpp"
#include "facet/teapot.hpp"

namespace facet {

// A rectangle ground, a cube, a sphere, a pyramid and an octagonal prism under one sun.
Scene make_shapes_scene();

// Names of the built-in scenes, and the scene for a name (throws facet::Error if unknown).
std::vector<std::string> builtin_scene_names();
Scene make_builtin_scene(const std::string& name);

}  // namespace facet
