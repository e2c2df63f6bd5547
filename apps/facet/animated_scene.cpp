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

AnimatedScene::AnimatedScene(const SceneOptions& o) {
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
  return scene();
}

}  // namespace facet::cli
