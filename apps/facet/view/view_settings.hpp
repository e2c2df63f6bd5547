// The viewer's adjustable settings and the keys that change them (F1-F11, B, T): render mode,
// shading model, field of view, render resolution, threads, overlay, anti-aliasing, help,
// fullscreen, backend, tone mapping.
// Each change comes back with a one-line description for the overlay's change panel.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "arguments.hpp"
#include "facet/material.hpp"
#include "facet/renderer.hpp"

namespace facet::cli {

// F2 cycles these, in this order.
enum class RenderMode { shaded, wireframe, wire_overlay, depth, normals, overdraw, tile_bins };
std::string_view to_string(RenderMode mode);

// B cycles these: which renderer draws the frame (facet's own or its OpenGL twin), or the
// difference of the two, amplified (view_difference.hpp).
enum class ViewBackend { facet, gl, difference };
std::string_view to_string(ViewBackend backend);

struct ViewSettings {
  RenderMode mode = RenderMode::shaded;
  std::optional<ShadingModel> shading;  // F7: forced on every material; empty: each its own
  float fov_degrees = 60.0f;
  ImageSize size;
  int threads = 0;  // 0 = all cores
  int msaa = 4;     // samples per pixel (RenderSettings::msaa); F10 cycles 1, 2, 4, 8, 16
  bool overlay = true;
  bool help = false;
  bool fullscreen = false;
  ViewBackend backend = ViewBackend::facet;
  ToneMapping tone_mapping = ToneMapping::pbr_neutral;  // T cycles pbr-neutral, aces, none

  // The material shading model the mode and F7 ask for; empty: the material's own.
  std::optional<ShadingModel> forced_shading() const;
  DebugView debug_view() const;
  std::string shading_name() const;  // "material" when not forced
};

enum class SettingChange {
  none,
  mode,
  shading,
  fov,
  size,
  threads,
  msaa,
  overlay,
  help,
  fullscreen,
  backend,
  tone_mapping
};

struct SettingUpdate {
  SettingChange change = SettingChange::none;
  std::string message;  // e.g. "render mode: wireframe"
};

// Applies a setting key (an SDL_Keycode): F1-F11, B for the backend, T for the tone mapping;
// others change nothing.
SettingUpdate apply_setting_key(int keycode, ViewSettings& settings);

// Render resolutions that F5/F6 step through.
inline constexpr ImageSize kViewResolutions[] = {{320, 180},   {640, 360},  {960, 540},
                                                 {1280, 720},  {1600, 900}, {1920, 1080},
                                                 {2560, 1440}, {3840, 2160}};

}  // namespace facet::cli
