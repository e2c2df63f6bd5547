// `facet bench` (see bench_command.hpp).
#include "bench_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <memory>
#include <vector>

#include "arguments.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/renderer.hpp"
#include "render_backend.hpp"
#include "render_command.hpp"
#include "scenes/bench_scenes.hpp"

namespace facet::cli {
namespace {

struct SceneResult {
  std::string name;
  double median_ms = 0, min_ms = 0, max_ms = 0;
  double triangles_per_s = 0, pixels_per_s = 0;
  // Medians of the stages: raster is raster + shade, resolve the tiles' conversion to the
  // framebuffer (FrameStats::ms_resolve).
  double geometry_ms = 0, binning_ms = 0, raster_ms = 0, resolve_ms = 0;
  // The last frame's work: triangles submitted and drawn, pixels shaded.
  std::uint64_t triangles = 0, drawn = 0, pixels = 0;
  int tile_size = 0;  // the last frame's (FrameStats::tile_size: --tile-size auto chooses)
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

RenderSettings bench_settings(const BenchOptions& o, const bench::BenchScene& scene,
                              const ImageSize& size) {
  RenderSettings settings;
  settings.threads = o.threads;
  settings.tile_size = parse_tile_size(o.tile_size);
  settings.msaa = o.msaa;
  settings.tone_mapping = parse_tone_mapping(o.tone_mapping);
  apply_pass_options(o.passes, false, size, settings);
  settings.clear_color = scene.clear_color();
  return settings;
}

// Renders the warm-up and measured frames, each by draw_frame(t) (animations follow the clock,
// as in glmark2); returns the measured frames' wall times in ms, with after_frame called after
// each measured one.
std::vector<double> time_frames(const BenchOptions& o,
                                const std::function<void(double)>& draw_frame,
                                const std::function<void()>& after_frame) {
  using Clock = std::chrono::steady_clock;
  std::vector<double> total;
  auto t0 = Clock::now();
  for (int frame = 0; frame < o.warmup + o.frames; ++frame) {
    double t = std::chrono::duration<double>(Clock::now() - t0).count();
    auto start = Clock::now();
    draw_frame(t);
    double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (frame < o.warmup) continue;
    total.push_back(ms);
    after_frame();
  }
  return total;
}

void set_times(SceneResult& r, const std::vector<double>& total) {
  r.median_ms = median(total);
  r.min_ms = *std::min_element(total.begin(), total.end());
  r.max_ms = *std::max_element(total.begin(), total.end());
}

SceneResult run_scene(const std::string& name, bench::BenchScene& scene, const BenchOptions& o,
                      const ImageSize& size) {
  Renderer renderer(bench_settings(o, scene, size));
  // Color only, as glmark2's frames are: both depth-test, neither reads the depth back. Drawn
  // into frame after frame, as the viewer draws.
  Framebuffer framebuffer(size.width, size.height, ColorFormat::rgba8_srgb, DepthImage::none);
  framebuffer.keep_cleared_tiles(true);
  std::vector<double> geometry, binning, raster, resolve;
  std::vector<double> total = time_frames(
      o,
      [&](double t) {
        scene.record(renderer, t, size.width, size.height);
        renderer.finish(framebuffer);
      },
      [&] {
        const FrameStats& s = renderer.stats();
        geometry.push_back(s.ms_geometry);
        binning.push_back(s.ms_binning);
        raster.push_back(s.ms_raster - s.ms_resolve);
        resolve.push_back(s.ms_resolve);
      });
  SceneResult r;
  r.name = name;
  set_times(r, total);
  r.geometry_ms = median(geometry);
  r.binning_ms = median(binning);
  r.raster_ms = median(raster);
  r.resolve_ms = median(resolve);
  r.triangles = renderer.stats().triangles_in;
  r.drawn = renderer.stats().drawn;
  r.pixels = renderer.stats().pixels_shaded;
  r.tile_size = renderer.stats().tile_size;
  r.triangles_per_s = r.triangles / (r.median_ms / 1000.0);
  r.pixels_per_s = r.pixels / (r.median_ms / 1000.0);
  return r;
}

// The same frames drawn by the OpenGL twin: whole-frame times only (OpenGL reports no stages),
// the pixels read back into the framebuffer as facet's finish() writes them.
SceneResult run_scene_gl(const std::string& name, bench::BenchScene& scene, const BenchOptions& o,
                         const ImageSize& size) {
  const std::unique_ptr<GlBackend> gl = make_gl_backend(bench_settings(o, scene, size));  // untimed
  Framebuffer framebuffer(size.width, size.height, ColorFormat::rgba8_srgb, DepthImage::none);
  const float aspect = static_cast<float>(size.width) / size.height;
  Camera camera;
  const bool read_back = parse_on_off("--gl-readback", o.gl_readback);
  std::vector<double> total = time_frames(
      o,
      [&](double t) {
        const Scene& frame = *scene.scene_at(t, aspect, camera);
        if (read_back) {
          gl->render(frame, camera, framebuffer);
        } else {
          gl->draw(frame, camera, framebuffer);
        }
      },
      [] {});
  SceneResult r;
  r.name = name;
  set_times(r, total);
  return r;
}

void write_json(const std::string& path, const BenchOptions& o, const ImageSize& size,
                const std::vector<SceneResult>& results) {
  std::ofstream out(path);
  if (!out) throw Error(o.json + ": cannot write");
  // A number, or "auto" as a string.
  const int tile_size = parse_tile_size(o.tile_size);
  const std::string tile_size_json = tile_size == RenderSettings::kAutoTileSize
                                         ? "\"" + o.tile_size + "\""
                                         : std::to_string(tile_size);
  out << "{\n  \"size\": \"" << size.width << "x" << size.height
      << "\",\n  \"threads\": " << o.threads << ",\n  \"tile_size\": " << tile_size_json
      << ",\n  \"msaa\": " << o.msaa << ",\n  \"tone_mapping\": \"" << o.tone_mapping << "\""
      << ",\n  \"backend\": \"" << o.backend << "\""
      << ",\n  \"gl_readback\": \"" << o.gl_readback << "\""
      << ",\n  \"frames\": " << o.frames << ",\n  \"scenes\": [\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const SceneResult& r = results[i];
    out << "    {\"name\": \"" << r.name << "\", \"median_ms\": " << r.median_ms
        << ", \"min_ms\": " << r.min_ms << ", \"max_ms\": " << r.max_ms
        << ", \"triangles_per_s\": " << r.triangles_per_s
        << ", \"pixels_per_s\": " << r.pixels_per_s << ", \"geometry_ms\": " << r.geometry_ms
        << ", \"binning_ms\": " << r.binning_ms << ", \"raster_ms\": " << r.raster_ms
        << ", \"resolve_ms\": " << r.resolve_ms << ", \"triangles_in\": " << r.triangles
        << ", \"triangles_drawn\": " << r.drawn << ", \"pixels_shaded\": " << r.pixels;
    if (r.tile_size > 0) out << ", \"tile_size\": " << r.tile_size;  // none on the OpenGL twin
    out << "}" << (i + 1 < results.size() ? ",\n" : "\n");
  }
  out << "  ]\n}\n";
}

// The scenes named by --scene: one name, names separated by commas, or all.
std::vector<std::string> scene_list(const std::string& text) {
  if (text == "all") return bench::bench_scene_names();
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    names.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return names;
}

// llvmpipe, the OpenGL of a machine without a GPU, makes its own threads: --threads sets how
// many (Mesa's LP_NUM_THREADS) unless the environment already says.
void set_gl_threads(int threads) {
  if (threads > 0) setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 0);
}

}  // namespace

CLI::App* add_bench_command(CLI::App& app, BenchOptions& o) {
  CLI::App* cmd = app.add_subcommand("bench", "Measure ms/frame on the benchmark scenes");
  cmd->add_option(
         "--scene", o.scene,
         "Scenes to run, separated by commas: " + joined(bench::bench_scene_names()) + "; or all")
      ->capture_default_str();
  cmd->add_option("--backend", o.backend,
                  "Renderer: facet, or gl (its OpenGL twin: the scenes it can draw, timed the same "
                  "way with the pixels read back; --threads sets llvmpipe's LP_NUM_THREADS)")
      ->capture_default_str();
  cmd->add_option("--gl-readback", o.gl_readback,
                  "With --backend gl: on, or off to time its frames as glmark2 times llvmpipe's "
                  "(an 8-bit sRGB target, clear, draw, glFinish; no readback, no tone mapping)")
      ->capture_default_str();
  cmd->add_option("--size", o.size, "Frame size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--frames", o.frames, "Frames measured per scene (after the warm-up)")
      ->capture_default_str();
  cmd->add_option("--warmup", o.warmup, "Frames rendered before measuring")->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads, 0 = all cores, at most 256")
      ->capture_default_str();
  cmd->add_option("--tile-size", o.tile_size, kTileSizeHelp)->capture_default_str();
  cmd->add_option("--msaa", o.msaa, msaa_help(1));
  cmd->add_option("--tone-mapping", o.tone_mapping, tone_mapping_help(ToneMapping::none));
  add_pass_options(*cmd, o.passes);
  cmd->add_option("--json", o.json, "Also write the results to this JSON file");
  return cmd;
}

int run_bench(const BenchOptions& o) {
  ImageSize size = parse_size("--size", o.size);
  if (o.frames < 1) throw Error("--frames: must be at least 1");
  if (o.warmup < 0) throw Error("--warmup: must be 0 or more");
  check_threads(o.threads);
  check_msaa(o.msaa);
  parse_tone_mapping(o.tone_mapping);
  RenderSettings checked;
  apply_pass_options(o.passes, false, size, checked);
  parse_tile_size(o.tile_size);
  const Backend backend = parse_backend("--backend", o.backend);
  if (!parse_on_off("--gl-readback", o.gl_readback) && backend != Backend::gl) {
    throw Error("--gl-readback off: only with --backend gl");
  }
  // Every name is checked before the first frame, so a typo does not end a long run half-way.
  const std::vector<std::string> known = bench::bench_scene_names();
  const std::vector<std::string> glmark2 = bench::glmark2_scene_names();
  auto listed = [](const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  std::vector<std::string> names;
  for (const std::string& name : scene_list(o.scene)) {
    if (!listed(known, name)) {
      throw Error("--scene: unknown benchmark scene '" + name + "' (" + joined(known) +
                  "; or all)");
    }
    if (backend == Backend::gl && listed(glmark2, name)) {
      if (o.scene == "all") continue;
      throw Error("--scene " + name +
                  ": a glmark2 scene, shaded as glmark2 does by facet only; "
                  "not with --backend gl");
    }
    names.push_back(name);
  }
  if (backend == Backend::gl) {
    set_gl_threads(o.threads);
    std::printf("OpenGL: %s\n", make_gl_backend(RenderSettings{})->description().c_str());
  }
  std::vector<SceneResult> results;
  std::printf("%-28s %9s %9s %9s %10s %10s %8s %8s %8s %8s\n", "scene", "median", "min", "max",
              "Mtri/s", "Mpix/s", "geom", "bin", "raster", "resolve");
  for (const std::string& name : names) {
    auto scene = bench::make_bench_scene(name);  // setup: not timed
    if (backend == Backend::gl) {
      SceneResult r = run_scene_gl(name, *scene, o, size);
      std::printf("%-28s %9.2f %9.2f %9.2f %10s %10s %8s %8s %8s %8s\n", r.name.c_str(),
                  r.median_ms, r.min_ms, r.max_ms, "-", "-", "-", "-", "-", "-");
      results.push_back(r);
    } else {
      SceneResult r = run_scene(name, *scene, o, size);
      std::printf("%-28s %9.2f %9.2f %9.2f %10.1f %10.1f %8.2f %8.2f %8.2f %8.2f\n", r.name.c_str(),
                  r.median_ms, r.min_ms, r.max_ms, r.triangles_per_s / 1e6, r.pixels_per_s / 1e6,
                  r.geometry_ms, r.binning_ms, r.raster_ms, r.resolve_ms);
      results.push_back(r);
    }
    std::fflush(stdout);
  }
  std::printf(
      "(ms/frame at %dx%d, %d frames after %d warm-up, backend %s; stage columns are medians in "
      "ms: raster is raster + shade)\n",
      size.width, size.height, o.frames, o.warmup, backend_name(backend));
  if (!o.json.empty()) write_json(o.json, o, size, results);
  return 0;
}

}  // namespace facet::cli
