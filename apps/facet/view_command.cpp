// `facet view` (see view_command.hpp): flags, the scene, and the frame loop.
#include "view_command.hpp"

#include <SDL.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "arguments.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/islands.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "view_controls.hpp"
#include "view_window.hpp"

namespace facet::cli {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kBackground = "0.53,0.66,0.82";  // sRGB sky blue, as `facet render`
constexpr float kWalkSecondsAcross = 20.0f;        // walking speed: the scene's size in this time

// Options that change the scene after it is built (build_scene applies them).
bool changes_scene(const SceneOptions& o) {
  return o.shading || o.cull || !o.lights.empty() || o.texture || o.environment || o.reflectivity ||
         o.fog;
}

// The islands world keeps its animation handles; everything else is a static scene.
struct ViewScene {
  std::unique_ptr<IslandsWorld> world;
  Scene scene;
  Scene& get() { return world ? world->scene : scene; }
};

ViewScene load_scene(const SceneOptions& o) {
  ViewScene v;
  if (o.model.empty() && o.scene.value_or("") == "islands") {
    v.world = std::make_unique<IslandsWorld>(make_islands_world());
    // build_scene keeps node and material indices, so the world's handles stay valid.
    if (changes_scene(o)) v.world->scene = build_scene(o);
  } else {
    v.scene = build_scene(o);
  }
  return v;
}

// facet-screenshot-N.png with the first N that is not taken.
std::string next_screenshot_name() {
  for (int n = 1;; ++n) {
    std::string name = "facet-screenshot-" + std::to_string(n) + ".png";
    if (!std::filesystem::exists(name)) return name;
  }
}

}  // namespace

CLI::App* add_view_command(CLI::App& app, ViewOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Open a window on a model or a built-in scene: W/A/S/D move, Q/E or Ctrl/Space down/up, "
      "arrows turn, Shift runs, click for mouse look (Esc releases, Esc again quits), F12 saves "
      "a screenshot");
  add_scene_options(*cmd, o.scene);
  cmd->add_option("--size", o.size,
                  "Render resolution WIDTHxHEIGHT; the window scales it with letterboxing")
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads, 0 = all cores")->capture_default_str();
  cmd->add_option("--frames", o.frames, "Render this many frames, then quit (0: until closed)")
      ->capture_default_str();
  cmd->add_option("--screenshot", o.screenshot, "Save the last frame to this PNG or PPM file");
  cmd->add_option("--time", o.time,
                  "Fixed animation time in seconds (default: the real clock from the start)");
  return cmd;
}

int run_view(const ViewOptions& o) {
  ImageSize size = parse_size("--size", o.size);
  if (o.threads < 0) {
    throw Error("--threads: must be 0 (all cores) or more, got " + std::to_string(o.threads));
  }
  if (o.frames < 0) throw Error("--frames: must be 0 (until closed) or more");
  if (o.time && !std::isfinite(*o.time)) throw Error("--time: must be a finite number of seconds");
  if (!o.screenshot.empty()) check_writable(o.screenshot);
  glm::vec3 background = parse_color("--background", kBackground);
  // The window first: with no display the command fails before loading anything.
  ViewWindow window("facet view", size.width, size.height);

  ViewScene loaded = load_scene(o.scene);
  Scene& scene = loaded.get();
  if (!o.scene.fog_color) scene.lighting.fog.color = background;
  Camera start = build_camera(o.scene, scene, static_cast<float>(size.width) / size.height);
  Bounds bounds = scene.bounds();
  float extent = bounds.empty() ? 10.0f : glm::length(bounds.max - bounds.min);
  ViewControls controls(start, extent / kWalkSecondsAcross);

  RenderSettings settings;
  settings.threads = o.threads;
  settings.clear_color = glm::vec4(background, 1.0f);
  Renderer renderer(settings);
  Framebuffer framebuffer(size.width, size.height);

  int frames = 0;
  double render_ms = 0.0;
  auto begin = Clock::now();
  auto last = begin;
  for (bool running = true; running;) {
    SDL_Event event;
    bool screenshot = false;
    while (SDL_PollEvent(&event)) {
      ViewAction action = controls.handle(event);
      if (action == ViewAction::quit) running = false;
      if (action == ViewAction::screenshot) screenshot = true;
    }
    if (!running) break;
    auto now = Clock::now();
    controls.update(std::chrono::duration<double>(now - last).count());
    last = now;
    // Animation follows time, never the frame count: the same t always gives the same image.
    if (loaded.world) {
      loaded.world->animate(o.time.value_or(std::chrono::duration<double>(now - begin).count()));
    }
    auto start_render = Clock::now();
    renderer.begin_frame(controls.camera(), scene.lighting);
    draw_scene(renderer, scene);
    renderer.finish(framebuffer);
    render_ms += std::chrono::duration<double, std::milli>(Clock::now() - start_render).count();
    window.present(framebuffer);
    ++frames;
    if (screenshot) {
      std::string name = next_screenshot_name();
      write_image(framebuffer, name);
      std::printf("view: saved %s\n", name.c_str());
      std::fflush(stdout);
    }
    if (o.frames > 0 && frames >= o.frames) running = false;
  }
  if (!o.screenshot.empty() && frames > 0) write_image(framebuffer, o.screenshot);

  double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
  double average_ms = frames ? seconds * 1000.0 / frames : 0.0;
  std::printf("view: %d frames, %.2f ms/frame average (render %.2f ms), %.1f fps\n", frames,
              average_ms, frames ? render_ms / frames : 0.0, seconds > 0 ? frames / seconds : 0.0);
  return 0;
}

}  // namespace facet::cli
