// Command-line options that choose and adjust what is drawn — a model file or a built-in
// scene, the camera, lights, shading overrides, environment, fog — shared by the subcommands
// that render a scene (render and view).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli_fwd.hpp"
#include "facet/camera.hpp"
#include "facet/scene.hpp"

namespace facet::cli {

struct SceneOptions {
  std::string model;  // positional MODEL; empty: a built-in scene
  std::optional<std::string> scene;
  std::optional<std::string> eye, target, up;
  std::optional<float> fov, near_plane, far_plane;
  std::optional<float> azimuth, elevation;  // turn the automatic view (Framing)
  std::optional<int> camera_index;
  std::optional<std::string> shading, cull;
  std::vector<std::string> lights;
  std::optional<std::string> environment, environment_projection;
  std::optional<std::string> fog, fog_color;
  std::optional<std::string> texture, projection;
  std::optional<float> reflectivity;
  std::optional<float> point_size;
  bool allow_outside_paths = false;  // ImportOptions::allow_outside_paths
  std::optional<int> animation;      // --animation N: ImportOptions::animation
  // ImportOptions::time: not a flag of its own; AnimatedScene sets it from --time or the frame's
  // time when the model is to be posed.
  std::optional<double> model_time;
  double import_timeout = 60.0;  // ImportOptions::import_time_limit_seconds
};

// Adds the options to a subcommand. With `models`, the positional takes any number of model
// files and folders into it (render's batch) instead of the one options.model.
void add_scene_options(CLI::App& command, SceneOptions& options,
                       std::vector<std::string>* models = nullptr);

// --allow-outside-paths, for every command that imports a model.
void add_allow_outside_paths_flag(CLI::App& command, bool& allow_outside_paths);
// --import-timeout S, for every command that imports a model.
void add_import_timeout_option(CLI::App& command, double& seconds);

// Imports the model or builds the built-in scene (default `shapes`), then applies the
// options; --up AXIS, --azimuth and --elevation make the scene's default view the automatic
// framing they describe (Scene::framing), for a built-in scene too. Throws facet::Error naming
// the flag or file at fault.
Scene build_scene(const SceneOptions& options);

// The camera the options ask for: --camera N, else the scene's (scene_camera: the automatic
// view framed for this aspect), then --eye/--target/... on top.
Camera build_camera(const SceneOptions& options, const Scene& scene, float aspect);

// --up's axis form: +X, -X, +Y, -Y, +Z or -Z (the sign optional, either case) as a unit vector;
// nothing for anything else (the x,y,z form).
std::optional<glm::vec3> parse_up_axis(const std::string& text);

// Whether the options ask to turn the automatic view (--up AXIS, --azimuth, --elevation).
bool changes_framing(const SceneOptions& options);

}  // namespace facet::cli
