// The scene `facet render` and `facet view` draw, posed by time: the islands world keeps its
// animation handles and moves with the clock; a glTF model asked to be posed (--time, --frames,
// --animation, or the viewer's clock) is posed again for each time from the file read once
// (AnimatedModel), keeping its materials, lights and view from the first; any other scene
// (shapes, teapot, a model at rest) stands still.
#pragma once

#include <memory>
#include <optional>

#include "facet/import.hpp"
#include "facet/islands.hpp"
#include "facet/scene.hpp"
#include "scene_options.hpp"

namespace facet::cli {

class AnimatedScene {
 public:
  // Builds the scene the options ask for (build_scene), with the islands' handles kept. With
  // `model_time`, a model is posed at that time (its animation sampled) and again at every
  // other time at() is given.
  explicit AnimatedScene(const SceneOptions& options, std::optional<double> model_time = {});

  Scene& scene() { return world_ ? world_->scene : scene_; }
  IslandsWorld* world() { return world_.get(); }  // null unless the islands
  // The length of the model's animation in seconds; 0 for a model without one, or not posed.
  double model_duration() const { return model_ ? model_->duration() : 0.0; }
  // Poses the scene for `seconds` on the animation clock; the same time always gives the
  // same scene, whatever was posed before.
  Scene& at(double seconds);

 private:
  std::unique_ptr<IslandsWorld> world_;
  Scene scene_;
  std::optional<AnimatedModel> model_;  // a posed glTF model, read once
  std::optional<double> model_time_;    // the time the model is posed at; empty: not posed
};

}  // namespace facet::cli
