// `facet bench`: renders benchmark scenes for N frames after a warm-up and reports ms/frame
// (median, min, max), throughput and the time per pipeline stage; optionally as JSON. With
// --backend gl the OpenGL twin draws the scenes it can (the built-in ones, not the glmark2
// equivalents), timed the same way, readback included.
#pragma once

#include <string>

#include "cli_fwd.hpp"
#include "render_command.hpp"

namespace facet::cli {

struct BenchOptions {
  std::string scene = "all";  // a name, names separated by commas, or all
  std::string backend = "facet";
  // The OpenGL twin's frames: "on", read back as `facet render` needs them; "off", timed as
  // glmark2 times llvmpipe's (GlRenderer::draw).
  std::string gl_readback = "on";
  std::string size = "1920x1080";
  int frames = 50;
  int warmup = 5;
  int threads = 0;
  std::string tile_size = "auto";
  int msaa = 1;                       // glmark2 runs without anti-aliasing
  std::string tone_mapping = "none";  // nor tone mapping
  PassOptions passes;                 // nor shadows, nor reflections
  std::string json;                   // empty: no JSON file
};

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench(const BenchOptions& options);

}  // namespace facet::cli
