// `facet view` (see view_command.hpp): its flags; the rest is the view module's
// (view/view_run.cpp: the window, the scene and the start camera; view/view_loop.cpp: the frames).
#include "view_command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>

#include "arguments.hpp"
#include "facet/error.hpp"
#include "facet/image_io.hpp"
#include "modules.hpp"
#include "view_bindings.hpp"

namespace facet::cli {
namespace {

const std::string kBackground = "0.53,0.66,0.82";  // sRGB sky blue, as `facet render`

std::string view_description() {
  std::string text =
      "Open a window on a model or a built-in scene and move through it. Models start in orbit "
      "mode, built-in scenes in first person. Keys:\n";
  text += view_bindings_text("  ");
  return text;
}

}  // namespace

CLI::App* add_view_command(CLI::App& app, ViewOptions& o) {
  CLI::App* cmd = app.add_subcommand("view", view_description());
  add_scene_options(*cmd, o.scene);
  cmd->add_option("--size", o.size,
                  "Render resolution WIDTHxHEIGHT; the window scales it with letterboxing")
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads, 0 = all cores, at most 256")
      ->capture_default_str();
  cmd->add_option("--msaa", o.msaa, msaa_help(4) + "; F10 cycles it");
  cmd->add_option("--tone-mapping", o.tone_mapping,
                  tone_mapping_help(ToneMapping::pbr_neutral) + "; T cycles it");
  add_pass_options(*cmd, o.passes);
  cmd->add_option("--frames", o.frames, "Render this many frames, then quit (0: until closed)")
      ->capture_default_str();
  cmd->add_option("--screenshot", o.screenshot, "Save the last frame to this PNG or PPM file");
  cmd->add_option("--time", o.time,
                  "Fixed animation time in seconds (default: the real clock from the start)");
  cmd->add_option("--camera-path", o.camera_path,
                  "Fly along the timed camera keys in FILE (lines of: t x y z yaw pitch)");
  cmd->add_option("--overlay", o.overlay,
                  "Statistics overlay at the start: on, off, or auto (on unless --frames)")
      ->check(CLI::IsMember({"auto", "on", "off"}))
      ->capture_default_str();
  cmd->add_flag("--fullscreen", o.fullscreen, "Start fullscreen (F11 toggles)");
  cmd->add_option("--backend", o.backend,
                  "Renderer at the start: facet or gl (its OpenGL twin); B switches between "
                  "them and their difference")
      ->capture_default_str();
  return cmd;
}

ViewArguments view_arguments(const ViewOptions& o) {
  ViewArguments a;
  a.size = parse_size("--size", o.size);
  check_threads(o.threads);
  check_msaa(o.msaa);
  a.tone_mapping = parse_tone_mapping(o.tone_mapping);
  // Off unless asked: shadows cost several times a frame of the islands, reflections another.
  apply_pass_options(o.passes, false, a.size, a.passes);
  if (o.frames < 0) throw Error("--frames: must be 0 (until closed) or more");
  if (o.time && !std::isfinite(*o.time)) throw Error("--time: must be a finite number of seconds");
  if (!o.screenshot.empty()) check_writable(o.screenshot);
  a.backend = parse_backend("--backend", o.backend);
  a.background = parse_color("--background", kBackground);
  if (auto axis = o.scene.up ? parse_up_axis(*o.scene.up) : std::nullopt;
      axis && *axis != glm::vec3(0.0f, 1.0f, 0.0f)) {
    // The first-person and orbit controls turn about +Y; a view turned to another axis would
    // flip back at the first move.
    throw Error("--up " + *o.scene.up +
                ": the viewer's controls keep +Y up; other model axes are for facet render");
  }
  return a;
}

int run_view(const ViewOptions& options) {
  // Bad flags are told before the module is looked for.
  return run_view_module(options, view_arguments(options));
}

}  // namespace facet::cli
