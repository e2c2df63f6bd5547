// `facet render` (see render_command.hpp).
#include "render_command.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "animated_scene.hpp"
#include "arguments.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "output_files.hpp"
#include "process_memory.hpp"
#include "render_backend.hpp"
#include "render_compare.hpp"
#include "render_frames.hpp"

namespace facet::cli {
namespace {
const std::string kDefaultBackground = "0.53,0.66,0.82";  // sRGB sky blue

DebugView parse_debug_view(const std::string& text) {
  if (text == "none") return DebugView::none;
  if (text == "overdraw") return DebugView::overdraw;
  if (text == "tile_bins") return DebugView::tile_bins;
  throw Error("--debug-view: expected overdraw, tile_bins or none, got '" + text + "'");
}

}  // namespace

void add_pass_options(CLI::App& cmd, PassOptions& o) {
  cmd.add_option("--shadows", o.shadows,
                 "Shadows of the scene's directional and spot lights (each that casts them: a "
                 "model's own, or the key of the default three lights), through shadow maps: on "
                 "or off")
      ->capture_default_str();
  cmd.add_option("--shadow-map-size", o.map_size,
                 "Shadow map edge in texels, " + std::to_string(RenderSettings::kMinShadowMapSize) +
                     " .. " + std::to_string(Framebuffer::kMaxSize) +
                     ", or auto: the power of two at least the image's longer edge, 256 .. 2048 "
                     "(shadows look alike at every image size)")
      ->capture_default_str();
  cmd.add_option("--shadow-cascades", o.cascades,
                 "Shadow maps per directional light, 1 .. " +
                     std::to_string(RenderSettings::kMaxShadowCascades) +
                     ", each fitted to a slice of the view's depths and blended into the next "
                     "where they meet: more keep shadows sharp near the camera over a large world "
                     "(the islands), at a depth pass each; or auto: chosen each frame from the "
                     "view, 1 for a model seen whole, more as the depths seen span more")
      ->capture_default_str();
  cmd.add_option("--reflections", o.reflections,
                 "Planar reflections: flat mirror materials (the islands' sea) show the scene "
                 "mirrored in them, through a pass at half the image's size, or only the "
                 "environment: on or off (the default is --shadows')")
      ->capture_default_str();
}

void apply_pass_options(const PassOptions& o, bool default_on, ImageSize image,
                        RenderSettings& settings) {
  settings.shadows = o.shadows ? parse_on_off("--shadows", *o.shadows) : default_on;
  settings.reflections = o.reflections ? parse_on_off("--reflections", *o.reflections) : default_on;
  settings.shadow_map_size = parse_shadow_map_size(o.map_size, image);
  settings.shadow_cascades = parse_shadow_cascades(o.cascades);
}

CLI::App* add_render_command(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand("render",
                                     "Render a model or a built-in scene to image files, one frame "
                                     "or a sequence");
  add_scene_options(*cmd, o.scene, &o.batch.models);
  cmd->add_option("-o,--output", o.output,
                  "Output file: .png, .ppm (binary P6), .exr, .npy or .npz; with --frames, %04d "
                  "in the name is the frame number; a folder (FOLDER/) for several models")
      ->required();
  cmd->add_option("--size", o.size, "Image size WIDTHxHEIGHT, 1x1 .. 8192x8192")
      ->capture_default_str();
  cmd->add_option("--background", o.background,
                  "Background color r,g,b in [0, 1], sRGB, or none: transparent (a PNG with alpha "
                  "0 where nothing was drawn) (default: " +
                      kDefaultBackground + ")");
  cmd->add_option("--debug-view", o.debug_view,
                  "Draw what the pipeline did instead of the shaded image: overdraw (how many "
                  "triangles covered each pixel: black 0, blue 1 .. white 16+) or tile_bins (each "
                  "tile tinted by how many primitives were binned into it)");
  cmd->add_option("--exposure", o.exposure, "Exposure in stops: colors scaled by 2^EXPOSURE")
      ->capture_default_str();
  cmd->add_option("--tone-mapping", o.tone_mapping, tone_mapping_help(ToneMapping::pbr_neutral));
  cmd->add_option("--threads", o.threads, "Worker threads, 0 = all cores, at most 256")
      ->capture_default_str();
  cmd->add_option("--tile-size", o.tile_size, kTileSizeHelp)->capture_default_str();
  cmd->add_option("--backend", o.backend,
                  "Renderer: facet (the software rasterizer) or gl (its OpenGL twin, headless "
                  "through EGL: docs/gl_twin.md)")
      ->capture_default_str();
  cmd->add_option("--msaa", o.msaa, msaa_help(4));
  add_pass_options(*cmd, o.passes);
  cmd->add_option("--compare", o.compare,
                  "Draw the view once per variant and write them side by side, labelled: shading "
                  "models (every material shaded so), backends and tone mappings, separated by "
                  "commas, e.g. flat,gouraud,phong or facet,gl or none,pbr-neutral,aces; each "
                  "panel is --size");
  cmd->add_flag("--orthographic,--ortho", o.orthographic,
                "Parallel projection, fitted to the whole scene, seen along the camera's line of "
                "sight (the automatic three-quarter view, --eye/--target or --camera)");
  add_frame_options(*cmd, o.frames);
  add_batch_options(*cmd, o.batch);
  return cmd;
}

int run_render(const RenderOptions& o) {
  using Clock = std::chrono::steady_clock;
  // Every value is checked before any work, and the output path before rendering, so a bad
  // command fails fast and leaves nothing behind.
  ImageSize size = parse_size("--size", o.size);
  check_threads(o.threads);
  check_msaa(o.msaa);
  const int tile_size = parse_tile_size(o.tile_size);
  RenderSettings pass_settings;
  apply_pass_options(o.passes, true, size, pass_settings);
  if (!std::isfinite(o.exposure) || std::abs(o.exposure) > 20.0f) {
    throw Error("--exposure: must be within -20 .. 20 stops");
  }
  const ToneMapping tone_mapping = parse_tone_mapping(o.tone_mapping);
  const bool transparent = o.background == "none";
  glm::vec3 background =
      transparent ? glm::vec3(0.0f)
                  : parse_color("--background", o.background.value_or(kDefaultBackground));
  const DebugView debug_view = parse_debug_view(o.debug_view.value_or("none"));
  const Backend backend = parse_backend("--backend", o.backend);
  if (backend == Backend::gl && debug_view != DebugView::none) {
    throw Error("--debug-view: shows facet's own pipeline, not with --backend gl");
  }
  if (o.orthographic && (o.scene.fov || o.scene.near_plane || o.scene.far_plane)) {
    throw Error(std::string(o.scene.fov          ? "--fov"
                            : o.scene.near_plane ? "--near"
                                                 : "--far") +
                ": not with --orthographic, whose view and clip planes are fitted to the scene");
  }
  FrameJob job = plan_frames(o.frames, o.output);
  if (transparent && job.outputs.container == Container::ppm) {
    throw Error("--background none: " + o.output + " is a PPM, which has no alpha; use .png");
  }
  std::vector<CompareVariant> variants;
  if (o.compare) {
    variants = parse_compare(*o.compare, backend);
    const bool color_image =
        job.outputs.outputs == std::vector<Output>{Output::color} &&
        (job.outputs.container == Container::png || job.outputs.container == Container::ppm);
    if (job.sequence) throw Error("--compare: makes one picture, not a sequence of frames");
    if (!color_image) throw Error("--compare: writes one color image, a .png or a .ppm");
    if (transparent) throw Error("--compare: the panels are drawn on an opaque background");
    if (debug_view != DebugView::none) throw Error("--compare: not with --debug-view");
  }
  auto start = Clock::now();
  // A model is posed when a time is asked for (its animation sampled; at rest otherwise).
  const bool posed = o.frames.time || o.frames.frames || o.scene.animation;
  AnimatedScene animated(
      o.scene,
      posed ? std::optional(job.frames.empty() ? 0.0 : job.frames[0].seconds) : std::nullopt);
  Scene& scene = animated.scene();
  if (!o.scene.fog_color && !transparent) scene.lighting.fog.color = background;
  const float aspect = static_cast<float>(size.width) / size.height;
  Camera camera = build_camera(o.scene, scene, aspect);
  if (o.orthographic) camera = fit_orthographic(scene, camera, aspect);
  release_import_leftovers();
  double load_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();

  RenderSettings settings;
  settings.threads = o.threads;
  settings.tile_size = tile_size;
  settings.msaa = o.msaa;
  settings.shadows = pass_settings.shadows;
  settings.shadow_map_size = pass_settings.shadow_map_size;
  settings.shadow_cascades = pass_settings.shadow_cascades;
  settings.reflections = pass_settings.reflections;
  // Transparent: the framebuffer holds premultiplied color (blending over alpha 0), written
  // out with straight alpha (FrameRenderer).
  settings.clear_color = glm::vec4(background, transparent ? 0.0f : 1.0f);
  settings.debug_view = debug_view;
  settings.exposure = o.exposure;
  settings.tone_mapping = tone_mapping;
  if (o.compare) {
    const Framebuffer picture =
        render_comparison(variants, animated.scene(), camera, size, settings);
    write_outputs(picture, job.outputs, o.output);
    if (!job.quiet) {
      std::printf("%s: %d panels of %dx%d side by side (%s)\n", o.output.c_str(),
                  static_cast<int>(variants.size()), size.width, size.height, o.compare->c_str());
    }
    return 0;
  }
  Renderer renderer(settings);
  std::unique_ptr<GlBackend> gl;
  if (backend == Backend::gl) gl = make_gl_backend(settings);
  FrameRenderer frames(renderer, animated, camera, job, size, gl.get());
  if (job.sequence) return render_sequence(job, frames, size);

  const Framebuffer& framebuffer = frames.render(job.frames[0].seconds);
  auto rendered = Clock::now();
  write_outputs(framebuffer, job.outputs, o.output);
  double write_ms = std::chrono::duration<double, std::milli>(Clock::now() - rendered).count();
  if (job.quiet) return 0;
  if (gl) {
    std::printf("%s: %dx%d, drawn by OpenGL (%s); load %.1f ms, total %.1f ms; write %.1f ms\n",
                o.output.c_str(), size.width, size.height, gl->description().c_str(), load_ms,
                gl->last_frame_ms(), write_ms);
    return 0;
  }

  const FrameStats& s = renderer.stats();
  // Wireframes and line meshes draw segments: say how many, so their frames do not read as empty.
  std::string lines =
      s.lines_drawn > 0 ? ", " + std::to_string(s.lines_drawn) + " lines drawn" : "";
  if (s.points_drawn > 0) lines += ", " + std::to_string(s.points_drawn) + " points drawn";
  // FrameStats::triangles_in counts every primitive submitted.
  const char* submitted = lines.empty() ? "triangles" : "primitives";
  // Outputs beside the color image (or instead of it): say which files they went to.
  std::vector<std::string> files = job.outputs.files(o.output);
  const std::string written = files == std::vector<std::string>{o.output} ? "" : joined(files);
  std::printf(
      "%s: %dx%d, %llu %s in (%llu culled, %llu clipped, %llu drawn)%s, %llu pixels "
      "shaded; load %.1f ms, geometry %.1f ms, binning %.1f ms, raster %.1f ms, total %.1f ms; "
      "write %.1f ms%s%s\n",
      o.output.c_str(), size.width, size.height, static_cast<unsigned long long>(s.triangles_in),
      submitted, static_cast<unsigned long long>(s.culled),
      static_cast<unsigned long long>(s.clipped), static_cast<unsigned long long>(s.drawn),
      lines.c_str(), static_cast<unsigned long long>(s.pixels_shaded), load_ms, s.ms_geometry,
      s.ms_binning, s.ms_raster, s.ms_total, write_ms, written.empty() ? "" : "; wrote ",
      written.c_str());
  return 0;
}

}  // namespace facet::cli
