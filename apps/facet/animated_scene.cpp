// Scenes posed by time (see animated_scene.hpp).
#include "animated_scene.hpp"

namespace facet::cli {
namespace {

// Options that build_scene applies or checks once the scene is built (--fog-color and
// --env-projection are checked even where nothing uses them, so a typo never passes).
bool changes_scene(const SceneOptions& o) {
  return o.shading || o.cull || !o.lights.empty() || o.texture || o.environment || o.reflectivity ||
         o.fog || o.fog_color || o.environment_projection || changes_framing(o);
}

}  // namespace

AnimatedScene::AnimatedScene(const SceneOptions& options, std::optional<double> model_time)
    : options_(options) {
  const SceneOptions& o = options_;
  if (!o.model.empty() && model_time) {
    options_.model_time = model_time;
    model_time_ = model_time;
  }
  if (o.model.empty() && o.scene.value_or("") == "islands") {
    world_ = std::make_unique<IslandsWorld>(make_islands_world());
    // build_scene keeps node and material indices, so the world's handles stay valid.
    if (changes_scene(o)) world_->scene = build_scene(o);
  } else {
    scene_ = build_scene(o);
  }
}

Scene& AnimatedScene::at(double seconds) {
  if (world_) world_->animate(seconds);
  if (model_time_ && *model_time_ != seconds) {
    // Only what the pose moves is replaced: the options' changes to materials and lights, and
    // what the caller changed since (the fog's colour), stay.
    options_.model_time = seconds;
    Scene posed = build_scene(options_);
    scene_.meshes = std::move(posed.meshes);
    scene_.nodes = std::move(posed.nodes);
    model_time_ = seconds;
  }
  return scene();
}

}  // namespace facet::cli
