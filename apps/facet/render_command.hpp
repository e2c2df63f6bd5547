// `facet render`: renders a model file or a built-in scene to an image (PNG, PPM), its float and
// id outputs (OpenEXR, NumPy), one frame or a sequence (frame_options.hpp); several models or
// folders into a folder (render_batch.hpp).
#pragma once

#include <optional>
#include <string>

#include "arguments.hpp"
#include "cli_fwd.hpp"
#include "facet/renderer.hpp"
#include "frame_options.hpp"
#include "render_batch.hpp"
#include "scene_options.hpp"

namespace facet::cli {

// The options of the passes before the color pass (render, bench, view): --shadows,
// --shadow-map-size, --shadow-cascades and --reflections.
struct PassOptions {
  std::optional<std::string> shadows;      // "on" or "off"; unset: the command's default
  std::string map_size = "auto";           // texels or "auto" (parse_shadow_map_size)
  std::string cascades = "auto";           // 1 .. 4 or "auto" (parse_shadow_cascades)
  std::optional<std::string> reflections;  // "on" or "off"; unset: as shadows' default
};

struct RenderOptions {
  SceneOptions scene;
  FrameOptions frames;
  std::string output;
  std::string size = "1920x1080";
  std::optional<std::string> background;  // r,g,b or "none"
  std::optional<std::string> debug_view;
  float exposure = 0.0f;
  // Highlights kept rather than clipped in every thumbnail (RenderSettings::tone_mapping).
  std::string tone_mapping = "pbr-neutral";
  int threads = 0;
  std::string tile_size = "auto";
  int msaa = 4;        // anti-aliased images by default (RenderSettings::msaa)
  PassOptions passes;  // shadows and reflections on by default
  bool orthographic = false;
  std::string backend = "facet";       // or "gl": the OpenGL twin (render_backend.hpp)
  std::optional<std::string> compare;  // variants side by side (render_compare.hpp)
  BatchOptions batch;                  // the positional models; several, or a folder, make a batch
};

// Adds the pass options to a command (render, bench, view), filled on parse.
void add_pass_options(CLI::App& cmd, PassOptions& options);
// Checks them (throwing facet::Error naming the flag) and sets them in settings; shadows and
// reflections are `default_on` unless --shadows or --reflections says.
void apply_pass_options(const PassOptions& options, bool default_on, ImageSize image,
                        RenderSettings& settings);

// Adds the `render` subcommand and its flags to app; options are filled on parse.
CLI::App* add_render_command(CLI::App& app, RenderOptions& options);

// Runs the command; throws facet::Error on bad values or failed writes. Returns exit code.
int run_render(const RenderOptions& options);

}  // namespace facet::cli
