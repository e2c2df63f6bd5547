// `facet view`: an interactive window on a model or a built-in scene (the islands world is
// animated by time and has sound), with first-person and orbit controls, function keys and an
// overlay; also scripted (--frames, --screenshot, --camera-path).
#pragma once

#include <optional>
#include <string>

#include "cli_fwd.hpp"
#include "render_backend.hpp"
#include "render_command.hpp"
#include "scene_options.hpp"

namespace facet::cli {

struct ViewOptions {
  SceneOptions scene;
  std::string size = "1280x720";  // render resolution, independent of the window
  int threads = 0;
  int msaa = 4;                  // F10 cycles it
  int frames = 0;                // 0: run until the window is closed
  std::string screenshot;        // empty: none
  std::optional<double> time;    // fixed animation time in seconds; unset: the real clock
  std::string camera_path;       // empty: the camera follows input
  std::string overlay = "auto";  // auto: on unless scripted (--frames)
  bool fullscreen = false;
  std::string backend = "facet";             // or gl (render_backend.hpp); B switches at run time
  std::string tone_mapping = "pbr-neutral";  // T cycles it
  PassOptions passes;                        // off by default: they cost most of a frame
};

// Adds the `view` subcommand and its flags to app; options are filled on parse.
CLI::App* add_view_command(CLI::App& app, ViewOptions& options);

// The flags' values, checked: throws facet::Error naming the first bad flag. run_view checks them
// before it loads the view module and hands them to it.
struct ViewArguments {
  ImageSize size;
  ToneMapping tone_mapping = ToneMapping::pbr_neutral;
  RenderSettings passes;  // --shadows, its map size and cascades, --reflections
  Backend backend = Backend::facet;
  glm::vec3 background{0.0f};  // the clear color and the fog's, as parse_color reads them
};
ViewArguments view_arguments(const ViewOptions& options);

// Opens the window and runs the loop (the view module's, modules.hpp); throws facet::Error on
// bad values, with no display, or when the module is not installed. Returns the exit code.
int run_view(const ViewOptions& options);

}  // namespace facet::cli
