// A batch of models drawn by `facet render` (see render_batch.hpp).
#include "render_batch.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <set>

#include "arguments.hpp"
#include "facet/error.hpp"
#include "output_files.hpp"
#include "progress.hpp"
#include "render_command.hpp"
#include "stop_signals.hpp"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kFormats = {"png", "ppm", "exr", "npy", "npz"};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool has_model_extension(const fs::path& path) {
  const auto& known = model_extensions();
  return std::find(known.begin(), known.end(), lower(path.extension().string())) != known.end();
}

// The folder's model files, recursively, sorted by path so the order (and the -2, -3 names)
// is the same on every file system. Unreadable subfolders are passed over, not fatal: the
// batch draws what it can reach.
std::vector<fs::path> models_in(const fs::path& folder) {
  std::vector<fs::path> found;
  std::error_code ec;
  auto options = fs::directory_options::skip_permission_denied;
  for (fs::recursive_directory_iterator it(folder, options, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->is_regular_file(ec) && has_model_extension(it->path())) found.push_back(it->path());
  }
  if (ec) throw Error(folder.string() + ": cannot read the folder (" + ec.message() + ")");
  std::sort(found.begin(), found.end());
  return found;
}

// `taken` holds every name given so far; the first free one of NAME.EXT, NAME-2.EXT, ... is
// returned and added. Paths are compared normalized (thumbs/./a.png is thumbs/a.png).
std::string free_name(const fs::path& folder, const std::string& stem, const std::string& extension,
                      std::set<std::string>& taken) {
  for (int n = 1;; ++n) {
    std::string name = stem + (n == 1 ? "" : "-" + std::to_string(n)) + "." + extension;
    std::string path = (folder / name).lexically_normal().string();
    if (taken.insert(path).second) return path;
  }
}

std::string models(int count) {
  return std::to_string(count) + (count == 1 ? " model" : " models");
}

// The error as one line that names the model (the importer's messages mostly do already).
std::string naming(const std::string& model, const std::string& message) {
  return message.find(model) != std::string::npos ? message : model + ": " + message;
}

// Checks the options once before the first model, by drawing the built-in shapes scene at one
// pixel with them (about a millisecond) into a hidden file in the output folder, removed at
// once: a bad flag is then one usage error rather than one error per model, and every check
// run_render makes is made, whatever flags it learns.
void check_options(const RenderOptions& o, const std::string& folder) {
  parse_size("--size", o.size);  // the one value the probe does not use
  RenderOptions probe = o;
  probe.batch.models.clear();
  probe.scene.model.clear();
  probe.scene.camera_index.reset();  // the model's own cameras: checked per model
  probe.size = "1x1";
  probe.frames.quiet = true;
  probe.output =
      (fs::path(folder) / (".facet-check-" + std::to_string(::getpid()) + "." + o.batch.format))
          .string();
  OutputPlan plan = plan_outputs(o.frames.outputs, o.frames.normal_space, probe.output);
  struct Remove {
    std::vector<std::string> files;
    ~Remove() {
      for (const std::string& file : files) std::remove(file.c_str());
    }
  } remove{plan.files(probe.output)};
  run_render(probe);
}

// Creates the output folder if it does not exist yet; returns whether it did. A name with an
// image's extension is taken for a slip (one file for several models), not made a folder.
bool make_folder(const std::string& folder) {
  std::error_code ec;
  const bool exists = fs::exists(folder, ec);
  if ((exists && !fs::is_directory(folder, ec)) ||
      (!exists && folder.back() != '/' && fs::path(folder).has_extension())) {
    throw Error("--output: " + folder +
                " is not a folder; several models are written into a folder, one image each "
                "(-o FOLDER/)");
  }
  if (exists) return false;
  fs::create_directories(folder, ec);
  if (ec) throw Error("--output: cannot create the folder " + folder + " (" + ec.message() + ")");
  return true;
}

}  // namespace

void add_batch_options(CLI::App& cmd, BatchOptions& o) {
  cmd.add_option("--format", o.format,
                 "Image type of a batch (several models or a folder, -o FOLDER/): " +
                     std::string("png, ppm, exr, npy or npz"))
      ->capture_default_str();
}

const std::vector<std::string>& model_extensions() {
  // The formats facet reads (assimp's common ones and glTF). Not `.d`: compilers leave `.d`
  // dependency files in source trees; nor `.blend` and `.dxf`, whose recent or 2D files assimp
  // cannot draw. Any of them named on the command line is still tried.
  static const std::vector<std::string> extensions = {
      ".3ds", ".3mf", ".ac",      ".amf",  ".ase", ".b3d",     ".cob", ".dae",
      ".fbx", ".glb", ".gltf",    ".ifc",  ".iqm", ".irrmesh", ".lwo", ".lxo",
      ".md2", ".md3", ".md5mesh", ".ms3d", ".nff", ".obj",     ".off", ".ogex",
      ".ply", ".q3o", ".smd",     ".stl",  ".x",   ".x3d",     ".xgl", ".zgl"};
  return extensions;
}

bool is_batch(const BatchOptions& o, const std::string& output) {
  if (o.models.empty()) return false;  // a built-in scene: one image, whatever -o says
  if (o.models.size() > 1) return true;
  if (!output.empty() && output.back() == '/') return true;
  std::error_code ec;
  return o.models.size() == 1 && fs::is_directory(o.models[0], ec);
}

std::vector<BatchItem> plan_batch(const std::vector<std::string>& models,
                                  const std::string& output_folder, const std::string& extension) {
  std::vector<BatchItem> items;
  std::set<std::string> taken;
  for (const std::string& model : models) {
    std::error_code ec;
    if (!fs::is_directory(model, ec)) {
      // A missing or unreadable file is still an item: its error is reported when it is drawn.
      fs::path path(model);
      items.push_back({model, free_name(output_folder, path.stem().string(), extension, taken)});
      continue;
    }
    std::vector<fs::path> found = models_in(model);
    if (found.empty()) {
      throw Error(model + ": no model files in this folder (looked for " +
                  std::to_string(model_extensions().size()) +
                  " extensions: .obj, .gltf, .glb, "
                  ".stl, .ply, .3ds, .fbx, .dae, .off, ...)");
    }
    for (const fs::path& path : found) {
      fs::path folder = fs::path(output_folder) / path.parent_path().lexically_relative(model);
      items.push_back({path.string(), free_name(folder, path.stem().string(), extension, taken)});
    }
  }
  return items;
}

int run_batch(const RenderOptions& o) {
  if (o.backend != "facet") {
    throw Error("--backend " + o.backend + ": only facet's own renderer draws a batch of models");
  }
  using Clock = std::chrono::steady_clock;
  if (o.frames.frames) {
    throw Error(
        "--frames: a sequence is drawn from one model; not with several models or a "
        "folder");
  }
  if (o.scene.scene) throw Error("--scene: give model files or --scene, not both");
  if (std::find(kFormats.begin(), kFormats.end(), o.batch.format) == kFormats.end()) {
    throw Error("--format: expected png, ppm, exr, npy or npz, got '" + o.batch.format + "'");
  }
  if (o.output.empty()) throw Error("--output: give the folder the images go to");
  std::string folder = o.output;
  std::vector<BatchItem> items = plan_batch(o.batch.models, folder, o.batch.format);
  const bool made = make_folder(folder);
  try {
    check_options(o, folder);
  } catch (...) {
    std::error_code ec;
    if (made) fs::remove(folder, ec);  // a usage error leaves nothing behind
    throw;
  }

  const bool quiet = o.frames.quiet;
  const int total = static_cast<int>(items.size());
  // On a terminal one bar redrawn in place; otherwise run_render's own line per model.
  std::optional<Progress> bar;
  if (Progress::style_for(stdout, quiet) == Progress::Style::bar) {
    bar.emplace(Progress::Style::bar, total, stdout, "models");
    bar->start(models(total) + " into " + folder);
  }
  StopSignals stop;
  auto start = Clock::now();
  int failed = 0;
  for (const BatchItem& item : items) {
    RenderOptions one = o;
    one.batch.models.clear();
    one.scene.model = item.model;
    one.output = item.output;
    one.frames.quiet = quiet || bar.has_value();
    std::string error;
    try {
      std::error_code ec;
      fs::create_directories(fs::path(item.output).parent_path(), ec);
      run_render(one);
    } catch (const Error& e) {
      error = e.what();
    } catch (const std::exception& e) {
      error = std::string("unexpected: ") + e.what();
    }
    if (!error.empty()) {
      ++failed;
      if (bar) bar->end_line();
      std::fprintf(stderr, "facet: error: %s\n", naming(item.model, error).c_str());
      std::fflush(stderr);
    }
    if (bar && error.empty()) bar->rendered(0, {}, 0.0, 0.0);
    if (bar && !error.empty()) bar->failed();
    const int done = static_cast<int>(&item - items.data()) + 1;
    if (int signal = stop.received(); signal != 0 && done < total) {
      if (bar) bar->end_line();
      std::fprintf(stderr, "facet: stopped by %s after %d of %d models, each written whole\n",
                   signal == SIGINT ? "Ctrl-C (SIGINT)" : "SIGTERM", done, total);
      return 128 + signal;
    }
  }
  if (bar) bar->end_line();
  if (!quiet) {
    double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::printf("%s in %.1f s: %d rendered, %d failed\n", models(total).c_str(), seconds,
                total - failed, failed);
  }
  return failed > 0 ? 1 : 0;
}

int run_render_command(const RenderOptions& options) {
  if (is_batch(options.batch, options.output)) {
    if (options.compare) throw Error("--compare: makes one picture of one model, not a batch");
    return run_batch(options);
  }
  RenderOptions one = options;
  if (!one.batch.models.empty()) one.scene.model = one.batch.models.front();
  return run_render(one);
}

}  // namespace facet::cli
