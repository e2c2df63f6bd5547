// `facet render`: renders a built-in scene to a PNG or PPM file.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace facet::cli {

struct RenderOptions {
  std::string scene = "shapes";
  std::string output;
  std::string size = "1920x1080";
  std::optional<std::string> eye, target, up, background, shading, cull;
  std::optional<float> fov, near_plane, far_plane;
  int threads = 0;
  int tile_size = 64;
};

// Adds the `render` subcommand and its flags to app; options are filled on parse.
CLI::App* add_render_command(CLI::App& app, RenderOptions& options);

// Runs the command; throws facet::Error on bad values or failed writes. Returns exit code.
int run_render(const RenderOptions& options);

}  // namespace facet::cli
