// `facet bench`: renders benchmark scenes for N frames after a warm-up and reports ms/frame
// (median, min, max), throughput and the time per pipeline stage; optionally as JSON.
#pragma once

#include <string>

#include "cli_fwd.hpp"

namespace facet::cli {

struct BenchOptions {
  std::string scene = "all";
  std::string size = "1920x1080";
  int frames = 50;
  int warmup = 5;
  int threads = 0;
  int tile_size = 64;
  int msaa = 1;      // glmark2 runs without anti-aliasing
  std::string json;  // empty: no JSON file
};

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench(const BenchOptions& options);

}  // namespace facet::cli
