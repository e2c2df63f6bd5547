// The viewer's frame loop: reads events (function keys, camera input, overlay input), moves
// the camera (input or a camera path), animates and sounds the islands world, renders with
// facet, draws the overlay (into the frame, or the help over the window), shows it, and saves
// screenshots.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "animated_scene.hpp"
#include "camera_path.hpp"
#include "facet/framebuffer.hpp"
#include "facet/islands.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "render_backend.hpp"
#include "view_controls.hpp"
#include "view_overlay.hpp"
#include "view_settings.hpp"
#include "view_sound.hpp"
#include "view_window.hpp"

namespace facet::cli {

// What the loop runs on; built by run_view from the command line.
struct ViewSetup {
  Scene* scene = nullptr;
  IslandsWorld* world = nullptr;      // non-null: the islands, with sound
  AnimatedScene* animated = nullptr;  // the scene, posed by the clock (the islands, a model)
  Camera start;
  CameraMode camera_mode = CameraMode::first_person;
  float walk_speed = 1.0f;
  ViewSettings settings;
  glm::vec4 clear_color{0.0f};
  std::optional<CameraPath> camera_path;
  // --shadows, its map size and cascades, and --reflections (those fields of RenderSettings; the
  // rest unused).
  RenderSettings passes;
  std::optional<double> fixed_time;  // --time
  int frames = 0;                    // 0: until closed
};

class ViewLoop {
 public:
  ViewLoop(ViewWindow& window, ViewSetup setup);
  ~ViewLoop();

  // Runs until quit (or `frames` frames); returns the frames rendered.
  int run();
  const Framebuffer& last_frame() const { return frame_; }
  double render_ms() const { return render_ms_; }  // summed over all frames

 private:
  using Clock = std::chrono::steady_clock;
  bool handle_events();  // false: quit
  void apply(const SettingUpdate& update);
  void apply_shading();
  void make_renderer();
  // The OpenGL twin, the first time a backend needs it; false (and back to facet's renderer,
  // with a message) when there is no OpenGL.
  bool make_gl();
  RenderSettings gl_settings() const;
  void render_scene(const Camera& view);
  void render(double now, double dt);
  Camera camera(double t) const;
  void save_frame();
  void save_window();
  void save_screenshots();  // the requested ones; a failure is reported, not thrown

  ViewWindow& window_;
  ViewSetup setup_;
  ViewSettings& settings_;  // setup_.settings
  ViewControls controls_;
  std::vector<ShadingModel> own_shading_;  // each material's own model
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<GlBackend> gl_;
  Framebuffer frame_;
  Framebuffer gl_frame_;  // the twin's image, for the difference view
  ViewOverlay overlay_;
  WindowLayer layer_;  // what the overlay draws at the window's resolution this frame
  std::unique_ptr<IslandsSound> sound_;
  Clock::time_point begin_;
  Camera last_camera_;  // what the last frame was rendered with
  double smoothed_ms_ = 0.0;
  double backend_ms_ = 0.0;  // the last frame's render time in the backend that drew it
  double render_ms_ = 0.0;
  bool save_frame_ = false, save_window_ = false;
};

}  // namespace facet::cli
