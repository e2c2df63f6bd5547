// The viewer's function keys (see view_settings.hpp).
#include "view_settings.hpp"

#include <SDL.h>

#include <algorithm>
#include <cstdio>
#include <thread>

namespace facet::cli {
namespace {

constexpr float kFovStep = 5.0f;
constexpr float kMinFov = 10.0f;
constexpr float kMaxFov = 150.0f;

// F7 cycles the lit models (the debug models are render modes, F2), then back to the
// materials' own.
constexpr ShadingModel kLitModels[] = {ShadingModel::unlit,       ShadingModel::vertex_color,
                                       ShadingModel::flat,        ShadingModel::lambert,
                                       ShadingModel::gouraud,     ShadingModel::phong,
                                       ShadingModel::blinn_phong, ShadingModel::pbr};

long pixels(const ImageSize& s) { return static_cast<long>(s.width) * s.height; }

// The next listed resolution below (step -1) or above (+1) the current one by pixel count, so
// a --size that is not in the list still steps to its neighbours.
ImageSize step_resolution(const ImageSize& current, int step) {
  if (step < 0) {
    for (auto it = std::rbegin(kViewResolutions); it != std::rend(kViewResolutions); ++it) {
      if (pixels(*it) < pixels(current)) return *it;
    }
  } else {
    for (const ImageSize& s : kViewResolutions) {
      if (pixels(s) > pixels(current)) return s;
    }
  }
  return current;
}

// 1, 2, ... cores, then 0 (all cores, as the renderer counts them), then 1 again.
int next_thread_count(int threads) {
  int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (threads == 0) return 1;
  return threads >= cores ? 0 : threads + 1;
}

std::optional<ShadingModel> next_shading(std::optional<ShadingModel> current) {
  if (!current) return kLitModels[0];
  auto it = std::find(std::begin(kLitModels), std::end(kLitModels), *current);
  if (it == std::end(kLitModels) || it + 1 == std::end(kLitModels)) return std::nullopt;
  return *(it + 1);
}

std::string size_text(const ImageSize& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

}  // namespace

std::string_view to_string(RenderMode mode) {
  switch (mode) {
    case RenderMode::shaded:
      return "shaded";
    case RenderMode::wireframe:
      return "wireframe";
    case RenderMode::wire_overlay:
      return "wire overlay";
    case RenderMode::depth:
      return "depth";
    case RenderMode::normals:
      return "normals";
    case RenderMode::overdraw:
      return "overdraw heat map";
    case RenderMode::tile_bins:
      return "tile bins";
  }
  return "?";
}

std::string_view to_string(ViewBackend backend) {
  switch (backend) {
    case ViewBackend::gl:
      return "gl";
    case ViewBackend::difference:
      return "difference";
    default:
      return "facet";
  }
}

std::optional<ShadingModel> ViewSettings::forced_shading() const {
  switch (mode) {
    case RenderMode::wireframe:
      return ShadingModel::wireframe;
    case RenderMode::wire_overlay:
      return ShadingModel::wire_overlay;
    case RenderMode::depth:
      return ShadingModel::depth;
    case RenderMode::normals:
      return ShadingModel::normals;
    default:
      return shading;
  }
}

DebugView ViewSettings::debug_view() const {
  if (mode == RenderMode::overdraw) return DebugView::overdraw;
  if (mode == RenderMode::tile_bins) return DebugView::tile_bins;
  return DebugView::none;
}

std::string ViewSettings::shading_name() const {
  return shading ? std::string(to_string(*shading)) : std::string("material");
}

SettingUpdate apply_setting_key(int keycode, ViewSettings& s) {
  SettingUpdate u;
  switch (keycode) {
    case SDLK_F1:
      s.help = !s.help;
      return {SettingChange::help, s.help ? "help: shown" : "help: hidden"};
    case SDLK_F2:
      s.mode = static_cast<RenderMode>((static_cast<int>(s.mode) + 1) %
                                       (static_cast<int>(RenderMode::tile_bins) + 1));
      u = {SettingChange::mode, "render mode: "};
      u.message += to_string(s.mode);
      return u;
    case SDLK_F3:
    case SDLK_F4:
      s.fov_degrees =
          std::clamp(s.fov_degrees + (keycode == SDLK_F3 ? -kFovStep : kFovStep), kMinFov, kMaxFov);
      u = {SettingChange::fov, "field of view: "};
      u.message += std::to_string(static_cast<int>(s.fov_degrees + 0.5f)) + " degrees";
      return u;
    case SDLK_F5:
    case SDLK_F6:
      s.size = step_resolution(s.size, keycode == SDLK_F5 ? -1 : 1);
      u = {SettingChange::size, "render resolution: "};
      u.message += size_text(s.size);
      return u;
    case SDLK_F7:
      s.shading = next_shading(s.shading);
      u = {SettingChange::shading, "shading: "};
      u.message += s.shading_name();
      return u;
    case SDLK_F8:
      s.threads = next_thread_count(s.threads);
      u = {SettingChange::threads, "threads: "};
      u.message += s.threads == 0 ? std::string("all cores") : std::to_string(s.threads);
      return u;
    case SDLK_F9:
      s.overlay = !s.overlay;
      return {SettingChange::overlay, s.overlay ? "overlay: on" : "overlay: off"};
    case SDLK_F10:
      s.msaa = s.msaa >= 16 ? 1 : s.msaa * 2;
      u = {SettingChange::msaa, "anti-aliasing: "};
      u.message += s.msaa == 1 ? std::string("off (1 sample)") : std::to_string(s.msaa) + "x MSAA";
      return u;
    case SDLK_b:
      s.backend = static_cast<ViewBackend>((static_cast<int>(s.backend) + 1) % 3);
      u = {SettingChange::backend, "backend: "};
      u.message += to_string(s.backend);
      return u;
    case SDLK_t:
      s.tone_mapping = s.tone_mapping == ToneMapping::pbr_neutral ? ToneMapping::aces
                       : s.tone_mapping == ToneMapping::aces      ? ToneMapping::none
                                                                  : ToneMapping::pbr_neutral;
      u = {SettingChange::tone_mapping, "tone mapping: "};
      u.message += to_string(s.tone_mapping);
      return u;
    case SDLK_F11:
      s.fullscreen = !s.fullscreen;
      return {SettingChange::fullscreen, s.fullscreen ? "fullscreen" : "windowed"};
    default:
      return u;
  }
}

}  // namespace facet::cli
