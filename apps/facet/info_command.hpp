// `facet info MODEL`: imports a model and prints what it holds (meshes, triangles, materials,
// textures, bounds, lights, cameras, nodes), without rendering anything.
#pragma once

#include <string>

#include "cli_fwd.hpp"

namespace facet::cli {

struct InfoOptions {
  std::string model;
  bool allow_outside_paths = false;
  double import_timeout = 60.0;
};

// Adds the `info` subcommand and its arguments to app; options are filled on parse.
CLI::App* add_info_command(CLI::App& app, InfoOptions& options);

// Runs the command; throws facet::Error if the model cannot be imported. Returns exit code.
int run_info(const InfoOptions& options);

}  // namespace facet::cli
