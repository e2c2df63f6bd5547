// Benchmark scenes for `facet bench`: each records one frame at a given time into a renderer.
// Built-in (shapes, teapot, bunny-close, bunny-far, million, overdraw, overdraw-front-to-back,
// islands) here, each a Scene that the OpenGL twin can draw too; the glmark2-equivalent scenes in
// glmark2_scenes.cpp, which record their own draws. Models come from Debian's glmark2-data.
#pragma once

#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"

namespace facet::bench {

class BenchScene {
 public:
  virtual ~BenchScene() = default;
  // Records the frame at time t seconds (animations follow the clock) for a width x height
  // target: begin_frame + draws (and any frames of the scene's own render targets before them).
  // The renderer's finish() of that last frame is the caller's.
  virtual void record(Renderer& renderer, double t, int width, int height) = 0;
  // The same frame as a Scene seen by `camera`, for renderers that draw whole scenes (the
  // OpenGL twin: facet bench --backend gl); nullptr for a scene that records its own draws with
  // shading only facet has (the glmark2 equivalents). The scene lives as long as this object.
  virtual const Scene* scene_at(double /*t*/, float /*aspect*/, Camera& /*camera*/) {
    return nullptr;
  }
  virtual glm::vec4 clear_color() const { return {0.0f, 0.0f, 0.0f, 1.0f}; }
};

// Every scene name, in the order `--scene all` runs them.
std::vector<std::string> bench_scene_names();
// Loads the scene (models, textures: setup, not timed). Throws facet::Error for an unknown
// name or a missing data file.
std::unique_ptr<BenchScene> make_bench_scene(const std::string& name);

// The glmark2-equivalent scenes (glmark2_scenes.cpp): names, and the factory (nullptr for a
// name it does not know).
std::vector<std::string> glmark2_scene_names();
std::unique_ptr<BenchScene> make_glmark2_scene(const std::string& name);

}  // namespace facet::bench
