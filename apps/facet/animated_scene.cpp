// Scenes posed by time (see animated_scene.hpp).
#include "animated_scene.hpp"

#include <filesystem>
#include <string>

namespace facet::cli {
namespace {

// Options that build_scene applies or checks once the scene is built (--fog-color and
// --env-projection are checked even where nothing uses them, so a typo never passes).
bool changes_scene(const SceneOptions& o) {
  return o.shading || o.cull || !o.lights.empty() || o.texture || o.environment || o.reflectivity ||
         o.fog || o.fog_color || o.environment_projection || changes_framing(o);
}

// Whether the path names a glTF file, the one format with animations.
bool is_gltf(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  return extension == ".gltf" || extension == ".glb" || extension == ".GLTF" || extension == ".GLB";
}

}  // namespace

AnimatedScene::AnimatedScene(const SceneOptions& options, std::optional<double> model_time) {
  SceneOptions o = options;
  if (!o.model.empty() && model_time) {
    o.model_time = model_time;
    model_time_ = model_time;
  }
  if (o.model.empty() && o.scene.value_or("") == "islands") {
    world_ = std::make_unique<IslandsWorld>(make_islands_world());
    // build_scene keeps node and material indices, so the world's handles stay valid.
    if (changes_scene(o)) world_->scene = build_scene(o);
  } else {
    scene_ = build_scene(o);
  }
  if (model_time_ && is_gltf(o.model)) {
    ImportOptions import;
    import.allow_outside_paths = o.allow_outside_paths;
    import.animation = o.animation.value_or(0);
    import.import_time_limit_seconds = o.import_timeout;
    import.warn = [](const std::string&){};  // build_scene's import said it once
    model_.emplace(o.model, import);
  }
}

Scene& AnimatedScene::at(double seconds) {
  if (world_) world_->animate(seconds);
  if (model_ && *model_time_ != seconds) {
    // Only what the pose moves is replaced: the options' changes to materials and lights, and
    // what the caller changed since (the fog's colour), stay.
    Scene posed = model_->pose(seconds);
    scene_.meshes = std::move(posed.meshes);
    scene_.nodes = std::move(posed.nodes);
    model_time_ = seconds;
  }
  return scene();
}

}  // namespace facet::cli
