// The view module's entry point (modules.hpp): `facet view` once its flags are parsed
// (view_command.cpp): the window, the scene and the start camera; then the frames
// (view_loop.cpp).
#include <chrono>
#include <cstdio>
#include <memory>

#include "animated_scene.hpp"
#include "facet/image_io.hpp"
#include "facet/scene.hpp"
#include "modules.hpp"
#include "view_command.hpp"
#include "view_loop.hpp"
#include "view_window.hpp"

namespace facet::cli {
namespace {

int open_viewer(const ViewOptions& o, const ViewArguments& a) {
  ViewSetup setup;
  if (!o.camera_path.empty()) setup.camera_path = CameraPath::load(o.camera_path);
  // The window first: with no display the command fails before loading anything.
  ViewWindow window("facet view", a.size.width, a.size.height);

  // A model is posed by the clock (or --time): a glTF model's animation plays, looped
  // (--animation picks which); the islands move through their world.
  AnimatedScene loaded(o.scene, o.scene.model.empty() ? std::nullopt : std::optional(0.0));
  Scene& scene = loaded.scene();
  if (!o.scene.fog_color) scene.lighting.fog.color = a.background;
  setup.scene = &scene;
  setup.world = loaded.world();
  setup.animated = &loaded;
  setup.start = build_camera(o.scene, scene, static_cast<float>(a.size.width) / a.size.height);
  setup.camera_mode = o.scene.model.empty() ? CameraMode::first_person : CameraMode::orbit;
  setup.walk_speed = walking_speed(scene);
  setup.settings.size = a.size;
  setup.settings.threads = o.threads;
  setup.settings.msaa = o.msaa;
  setup.settings.tone_mapping = a.tone_mapping;
  setup.passes = a.passes;
  setup.settings.fov_degrees = setup.start.fov_y_degrees;
  setup.settings.overlay = o.overlay == "on" || (o.overlay == "auto" && o.frames == 0);
  setup.settings.fullscreen = o.fullscreen;
  setup.settings.backend = a.backend == Backend::gl ? ViewBackend::gl : ViewBackend::facet;
  setup.clear_color = glm::vec4(a.background, 1.0f);
  setup.fixed_time = o.time;
  setup.frames = o.frames;

  auto begin = std::chrono::steady_clock::now();
  ViewLoop loop(window, std::move(setup));
  int frames = loop.run();
  if (!o.screenshot.empty() && frames > 0) write_image(loop.last_frame(), o.screenshot);

  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  double average_ms = frames ? seconds * 1000.0 / frames : 0.0;
  std::printf("view: %d frames, %.2f ms/frame average (render %.2f ms), %.1f fps\n", frames,
              average_ms, frames ? loop.render_ms() / frames : 0.0,
              seconds > 0 ? frames / seconds : 0.0);
  return 0;
}

}  // namespace
}  // namespace facet::cli

extern "C" int facet_view_run(const facet::cli::ViewOptions& options,
                              const facet::cli::ViewArguments& arguments) {
  return facet::cli::open_viewer(options, arguments);
}
