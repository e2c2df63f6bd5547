// Command-line options that choose and adjust what is drawn — a model file or a built-in
// scene, the camera, lights, shading overrides, environment, fog — shared by the subcommands
// that render a scene (render and view).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/scene.hpp"

namespace facet::cli {

struct SceneOptions {
  std::string model;  // positional MODEL; empty: a built-in scene
  std::optional<std::string> scene;
  std::optional<std::string> eye, target, up;
  std::optional<float> fov, near_plane, far_plane;
  std::optional<int> camera_index;
  std::optional<std::string> shading, cull;
  std::vector<std::string> lights;
  std::optional<std::string> environment, environment_projection;
  std::optional<std::string> fog, fog_color;
  std::optional<std::string> texture, projection;
  std::optional<float> reflectivity;
  std::optional<float> point_size;
};

// Adds the options to a subcommand.
void add_scene_options(CLI::App& command, SceneOptions& options);

// Imports the model or builds the built-in scene (default `shapes`), then applies the
// options. Throws facet::Error naming the flag or file at fault.
Scene build_scene(const SceneOptions& options);

// The camera the options ask for: --camera N, else the scene's, then --eye/--target/... on top.
Camera build_camera(const SceneOptions& options, const Scene& scene, float aspect);

}  // namespace facet::cli
