// The scene `facet render` and `facet view` draw, posed by time: the islands world keeps its
// animation handles and moves with the clock; any other scene (a model, shapes, teapot) stands
// still.
#pragma once

#include <memory>

#include "facet/islands.hpp"
#include "facet/scene.hpp"
#include "scene_options.hpp"

namespace facet::cli {

class AnimatedScene {
 public:
  // Builds the scene the options ask for (build_scene), with the islands' handles kept.
  explicit AnimatedScene(const SceneOptions& options);

  Scene& scene() { return world_ ? world_->scene : scene_; }
  IslandsWorld* world() { return world_.get(); }  // null unless the islands
  // Poses the scene for `seconds` on the animation clock; the same time always gives the
  // same scene, whatever was posed before.
  Scene& at(double seconds);

 private:
  std::unique_ptr<IslandsWorld> world_;
  Scene scene_;
};

}  // namespace facet::cli
