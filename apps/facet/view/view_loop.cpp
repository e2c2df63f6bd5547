// The viewer's frame loop (see view_loop.hpp).
#include "view_loop.hpp"

#include <SDL.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "facet/error.hpp"
#include "facet/image_io.hpp"
#include "view_difference.hpp"

namespace facet::cli {
namespace {

// The sound's state as the overlay's line and the M key's message both say it: M mutes and
// unmutes even without an audio device, and then neither says the sound is on. Short: the
// overlay's panel is as wide as its longest line.
std::string sound_state(const IslandsSound& sound) {
  if (!sound.available()) return sound.muted() ? "muted (no device)" : "off (no device)";
  return sound.muted() ? "muted" : "on (M)";
}

constexpr double kSmoothing = 0.1;  // weight of the newest frame in the smoothed frame time

// PREFIX-N.png with the first N that is not taken.
std::string next_file_name(const char* prefix) {
  for (int n = 1;; ++n) {
    std::string name = prefix;
    name += "-";
    name += std::to_string(n);
    name += ".png";
    if (!std::filesystem::exists(name)) return name;
  }
}

// The keys that change a view setting (apply_setting_key): F1 to F11, B for the backend and T
// for the tone mapping.
bool is_setting_key(SDL_Keycode key) {
  return (key >= SDLK_F1 && key <= SDLK_F11) || key == SDLK_b || key == SDLK_t;
}

}  // namespace

ViewLoop::ViewLoop(ViewWindow& window, ViewSetup setup)
    : window_(window),
      setup_(std::move(setup)),
      settings_(setup_.settings),
      controls_(setup_.start, setup_.walk_speed, setup_.camera_mode),
      frame_(settings_.size.width, settings_.size.height, ColorFormat::rgba8_srgb,
             DepthImage::none),
      gl_frame_(frame_) {
  frame_.keep_cleared_tiles(true);  // rendered frame after frame
  for (const Material& m : setup_.scene->materials) own_shading_.push_back(m.shading);
  apply_shading();
  make_renderer();
  // Asked for on the command line: no OpenGL is an error there (one line, exit code 2).
  if (settings_.backend != ViewBackend::facet) gl_ = make_gl_backend(gl_settings());
  if (setup_.world) sound_ = std::make_unique<IslandsSound>(*setup_.world);
  if (settings_.fullscreen) window_.set_fullscreen(true);
}

ViewLoop::~ViewLoop() = default;

RenderSettings ViewLoop::gl_settings() const {
  RenderSettings rs;
  rs.clear_color = setup_.clear_color;
  rs.msaa = settings_.msaa;
  rs.tone_mapping = settings_.tone_mapping;
  return rs;
}

// Asked for with B: without OpenGL the viewer says why and goes back to facet's renderer.
bool ViewLoop::make_gl() {
  if (gl_ || settings_.backend == ViewBackend::facet) return true;
  try {
    gl_ = make_gl_backend(gl_settings());
    return true;
  } catch (const Error& error) {
    settings_.backend = ViewBackend::facet;
    double now = std::chrono::duration<double>(Clock::now() - begin_).count();
    overlay_.show_change(std::string("backend: facet (") + error.what() + ")", now);
    std::fprintf(stderr, "view: %s\n", error.what());
    return false;
  }
}

void ViewLoop::make_renderer() {
  RenderSettings rs;
  rs.threads = settings_.threads;
  rs.msaa = settings_.msaa;
  rs.clear_color = setup_.clear_color;
  rs.debug_view = settings_.debug_view();
  rs.tone_mapping = settings_.tone_mapping;
  rs.shadows = setup_.passes.shadows;
  rs.shadow_map_size = setup_.passes.shadow_map_size;
  rs.shadow_cascades = setup_.passes.shadow_cascades;
  rs.reflections = setup_.passes.reflections;
  renderer_ = std::make_unique<Renderer>(rs);
}

// Render modes and F7 set the shading model of every material; only that field changes, as
// the islands animate other fields (texture scrolling) every frame.
void ViewLoop::apply_shading() {
  std::optional<ShadingModel> forced = settings_.forced_shading();
  std::vector<Material>& materials = setup_.scene->materials;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    materials[i].shading = forced.value_or(own_shading_[i]);
  }
}

void ViewLoop::apply(const SettingUpdate& update) {
  switch (update.change) {
    case SettingChange::mode:
      apply_shading();
      make_renderer();
      break;
    case SettingChange::shading:
      apply_shading();
      break;
    case SettingChange::size:
      window_.set_render_size(settings_.size.width, settings_.size.height);
      frame_ = Framebuffer(settings_.size.width, settings_.size.height, ColorFormat::rgba8_srgb,
                           DepthImage::none);  // shown and saved as color only
      frame_.keep_cleared_tiles(true);
      gl_frame_ = frame_;
      break;
    case SettingChange::backend:
      if (!make_gl()) return;  // it said why
      break;
    case SettingChange::threads:
      make_renderer();
      break;
    case SettingChange::msaa:  // both renderers draw with the new setting
    case SettingChange::tone_mapping:
      make_renderer();
      if (gl_) {
        gl_.reset();
        if (!make_gl()) return;
      }
      break;
    case SettingChange::fullscreen:
      window_.set_fullscreen(settings_.fullscreen);
      break;
    default:
      break;
  }
  double now = std::chrono::duration<double>(Clock::now() - begin_).count();
  if (update.change != SettingChange::none) overlay_.show_change(update.message, now);
}

bool ViewLoop::handle_events() {
  double now = std::chrono::duration<double>(Clock::now() - begin_).count();
  SDL_Event event;
  bool running = true;
  while (SDL_PollEvent(&event)) {
    overlay_.handle(event);
    if (event.type == SDL_KEYDOWN && !event.key.repeat && is_setting_key(event.key.keysym.sym)) {
      apply(apply_setting_key(event.key.keysym.sym, settings_));
      continue;
    }
    switch (controls_.handle(event)) {
      case ViewAction::quit:
        running = false;
        break;
      case ViewAction::screenshot:
        save_frame_ = true;
        break;
      case ViewAction::window_screenshot:
        save_window_ = true;
        break;
      case ViewAction::toggle_mute:
        if (sound_) {
          sound_->set_muted(!sound_->muted());
          overlay_.show_change("sound: " + sound_state(*sound_), now);
        }
        break;
      case ViewAction::camera_mode:
        overlay_.show_change(
            controls_.mode() == CameraMode::orbit ? "camera: orbit" : "camera: first person", now);
        break;
      case ViewAction::none:
        break;
    }
  }
  return running;
}

Camera ViewLoop::camera(double t) const {
  float aspect = static_cast<float>(settings_.size.width) / settings_.size.height;
  if (!setup_.camera_path) return controls_.camera(settings_.fov_degrees, aspect);
  return setup_.camera_path->at(t).camera(settings_.fov_degrees, aspect, setup_.start.near_plane,
                                          setup_.start.far_plane);
}

void ViewLoop::render(double now, double dt) {
  // Animation follows time, never the frame count: the same t always gives the same image.
  double t = setup_.fixed_time.value_or(now);
  if (setup_.animated) {
    // A model's animation loops; the islands' clock runs on.
    const double length = setup_.animated->model_duration();
    setup_.animated->at(length > 0.0 && !setup_.fixed_time ? std::fmod(t, length) : t);
  }
  Camera view = camera(t);
  last_camera_ = view;
  if (sound_) sound_->update(*setup_.world, view, dt);
  auto start = Clock::now();
  render_scene(view);
  backend_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  render_ms_ += backend_ms_;

  OverlayInfo info;
  info.frame_ms = smoothed_ms_;
  info.fps = smoothed_ms_ > 0.0 ? 1000.0 / smoothed_ms_ : 0.0;
  info.size = settings_.size;
  info.fov_degrees = settings_.fov_degrees;
  info.triangles = settings_.backend == ViewBackend::gl ? setup_.scene->triangle_count()
                                                        : renderer_->stats().drawn;
  info.lines = renderer_->stats().lines_drawn;
  info.threads = settings_.threads;
  info.msaa = settings_.msaa;
  info.tone_mapping = to_string(settings_.tone_mapping);
  info.shadows = setup_.passes.shadows;
  info.reflections = setup_.passes.reflections;
  info.mode = to_string(settings_.mode);
  info.shading = settings_.shading_name();
  info.camera = setup_.camera_path                      ? "camera path"
                : controls_.mode() == CameraMode::orbit ? "orbit (Tab)"
                                                        : "first person (Tab)";
  if (sound_) info.sound = sound_state(*sound_);
  info.backend = to_string(settings_.backend);
  info.backend_ms = backend_ms_;
  if (gl_ && settings_.backend != ViewBackend::facet) info.gl_name = gl_->renderer_name();
  int window_width = 0, window_height = 0;
  window_.window_size(window_width, window_height);
  layer_ = overlay_.draw(frame_, info, settings_.overlay, settings_.help, window_width,
                         window_height, now, dt);
}

// The frame by the chosen backend: facet's renderer, the OpenGL twin, or both and where they
// differ. The twin draws offscreen through the same EGL path as `facet render --backend gl`,
// and its pixels are shown exactly as facet's are.
void ViewLoop::render_scene(const Camera& view) {
  const Scene& scene = *setup_.scene;
  if (settings_.backend == ViewBackend::gl) {
    gl_->render(scene, view, frame_);
    return;
  }
  renderer_->begin_frame(view, scene.lighting);
  draw_scene(*renderer_, scene);
  renderer_->finish(frame_);
  if (settings_.backend == ViewBackend::difference) {
    gl_->render(scene, view, gl_frame_);
    show_difference(frame_, gl_frame_);
  }
}

// Saves the frame and says on stdout what it shows: the settings and the camera, so scripts
// (and the tests) can check what each input did.
void ViewLoop::save_frame() {
  std::string name = next_file_name("facet-screenshot");
  write_image(frame_, name);
  const Camera& c = last_camera_;
  glm::vec3 f = c.forward();
  int ww = 0, wh = 0;
  window_.window_size(ww, wh);
  const char* camera_mode = controls_.mode() == CameraMode::orbit ? "orbit" : "first person";
  const char* sound = !sound_ ? "none" : sound_->muted() ? "muted" : "on";
  std::printf(
      "view: saved %s (render %dx%d, window %dx%d, eye %.4f,%.4f,%.4f, forward %.4f,%.4f,%.4f, "
      "fov %.1f, mode %s, shading %s, threads %d, msaa %d, camera %s, sound %s)\n",
      name.c_str(), frame_.width(), frame_.height(), ww, wh, c.eye.x, c.eye.y, c.eye.z, f.x, f.y,
      f.z, c.fov_y_degrees, std::string(to_string(settings_.mode)).c_str(),
      settings_.shading_name().c_str(), settings_.threads, settings_.msaa, camera_mode, sound);
  // A line of its own, so that scripts reading the line above need not change.
  const bool gl_drew = gl_ && settings_.backend != ViewBackend::facet;
  std::printf("view: %s drawn by backend %s%s%s\n", name.c_str(),
              std::string(to_string(settings_.backend)).c_str(), gl_drew ? ", OpenGL " : "",
              gl_drew ? gl_->description().c_str() : "");
  std::fflush(stdout);
}

void ViewLoop::save_window() {
  std::string name = next_file_name("facet-window");
  Framebuffer shot = window_.capture(frame_, layer_);
  write_image(shot, name);
  std::printf("view: saved %s (window %dx%d)\n", name.c_str(), shot.width(), shot.height());
  std::fflush(stdout);
}

// A failed save (read-only directory, full disk) must not end an interactive session: say so
// in one line and go on.
void ViewLoop::save_screenshots() {
  try {
    if (save_frame_) save_frame();
    if (save_window_) save_window();
  } catch (const Error& error) {
    std::fprintf(stderr, "view: cannot save the screenshot: %s\n", error.what());
  }
  save_frame_ = save_window_ = false;
}

int ViewLoop::run() {
  int frames = 0;
  begin_ = Clock::now();
  auto last = begin_;
  while (handle_events()) {
    auto now = Clock::now();
    double dt = std::chrono::duration<double>(now - last).count();
    last = now;
    smoothed_ms_ =
        frames == 0 ? dt * 1000.0 : smoothed_ms_ + (dt * 1000.0 - smoothed_ms_) * kSmoothing;
    controls_.update(dt);
    render(std::chrono::duration<double>(now - begin_).count(), dt);
    window_.present(frame_, layer_);
    ++frames;
    if (save_frame_ || save_window_) save_screenshots();
    if (setup_.frames > 0 && frames >= setup_.frames) break;
  }
  return frames;
}

}  // namespace facet::cli
