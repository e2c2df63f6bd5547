// `facet render` (see render_command.hpp).
#include "render_command.hpp"

#include <chrono>
#include <cstdio>

#include "arguments.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"

namespace facet::cli {
namespace {
const std::string kDefaultBackground = "0.53,0.66,0.82";  // sRGB sky blue
}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file (PNG or PPM)");
  cmd->add_option("--scene", o.scene, "Built-in scene to render")->capture_default_str();
  cmd->add_option("-o,--output", o.output, "Output file; .png or .ppm (binary P6)")->required();
  cmd->add_option("--size", o.size, "Image size WIDTHxHEIGHT, 1x1 .. 8192x8192")
      ->capture_default_str();
  cmd->add_option("--eye", o.eye, "Camera position x,y,z (default: the scene's camera)");
  cmd->add_option("--target", o.target, "Point the camera looks at x,y,z (default: the scene's)");
  cmd->add_option("--up", o.up, "Camera up direction x,y,z (default: 0,1,0)");
  cmd->add_option(
      "--fov", o.fov,
      "Vertical field of view in degrees, (0, 180) (default: the scene's; 50 for shapes)");
  cmd->add_option("--near", o.near_plane, "Near clip distance, > 0 (default: 0.1)");
  cmd->add_option("--far", o.far_plane, "Far clip distance, > near (default: 100)");
  cmd->add_option("--shading", o.shading,
                  "Shading model for every object: unlit, vertex_color, flat, lambert, depth, "
                  "normals, wireframe, wire_overlay (default: each object's own, lambert)");
  cmd->add_option("--cull", o.cull, "Face culling: back, front or none (default: back)");
  cmd->add_option("--background", o.background,
                  "Background color r,g,b in [0, 1], sRGB (default: " + kDefaultBackground + ")");
  cmd->add_option("--threads", o.threads, "Worker threads, 0 = all cores")->capture_default_str();
  cmd->add_option("--tile-size", o.tile_size, "Tile edge in pixels: 16, 32, 64 or 128")
      ->capture_default_str();
  return cmd;
}

namespace {

Camera camera_for(const RenderOptions& o, const Scene& scene, const ImageSize& size) {
  Camera camera = scene.camera;
  if (o.eye) camera.eye = parse_vec3("--eye", *o.eye);
  if (o.target) camera.target = parse_vec3("--target", *o.target);
  if (o.up) camera.up = parse_vec3("--up", *o.up);
  if (o.fov) camera.fov_y_degrees = *o.fov;
  if (o.near_plane) camera.near_plane = *o.near_plane;
  if (o.far_plane) camera.far_plane = *o.far_plane;
  camera.aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
  try {
    camera.validate();
  } catch (const Error& e) {
    // Name the flags, not the library's field names.
    throw Error(std::string(e.what()) + " (check --eye, --target, --up, --fov, --near, --far)");
  }
  return camera;
}

void apply_material_overrides(const RenderOptions& o, Scene& scene) {
  if (o.shading) {
    ShadingModel model;
    if (!parse_shading_model(*o.shading, model)) {
      throw Error("--shading: unknown model '" + *o.shading +
                  "' (unlit, vertex_color, flat, lambert, depth, normals, wireframe, "
                  "wire_overlay)");
    }
    for (auto& material : scene.materials) material.shading = model;
  }
  if (o.cull) {
    CullMode mode;
    if (!parse_cull_mode(*o.cull, mode)) {
      throw Error("--cull: unknown mode '" + *o.cull + "' (back, front, none)");
    }
    for (auto& material : scene.materials) material.cull = mode;
  }
}

}  // namespace

int run_render(const RenderOptions& o) {
  using Clock = std::chrono::steady_clock;
  // Every value is checked before any work, and the output path before rendering, so a bad
  // command fails fast and leaves nothing behind.
  ImageSize size = parse_size("--size", o.size);
  if (o.threads < 0)
    throw Error("--threads: must be 0 (all cores) or more, got " + std::to_string(o.threads));
  glm::vec3 background = parse_color("--background", o.background.value_or(kDefaultBackground));
  Scene scene = make_builtin_scene(o.scene);
  apply_material_overrides(o, scene);
  Camera camera = camera_for(o, scene, size);
  check_writable(o.output);

  RenderSettings settings;
  settings.threads = o.threads;
  settings.tile_size = o.tile_size;
  settings.clear_color = glm::vec4(background, 1.0f);
  Renderer renderer(settings);
  Framebuffer framebuffer(size.width, size.height);

  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(framebuffer);
  auto rendered = Clock::now();
  write_image(framebuffer, o.output);
  double write_ms = std::chrono::duration<double, std::milli>(Clock::now() - rendered).count();

  const FrameStats& s = renderer.stats();
  std::printf(
      "%s: %dx%d, %llu triangles in (%llu culled, %llu clipped, %llu drawn), %llu pixels shaded; "
      "geometry %.1f ms, binning %.1f ms, raster %.1f ms, total %.1f ms; write %.1f ms\n",
      o.output.c_str(), size.width, size.height, static_cast<unsigned long long>(s.triangles_in),
      static_cast<unsigned long long>(s.culled), static_cast<unsigned long long>(s.clipped),
      static_cast<unsigned long long>(s.drawn), static_cast<unsigned long long>(s.pixels_shaded),
      s.ms_geometry, s.ms_binning, s.ms_raster, s.ms_total, write_ms);
  return 0;
}

}  // namespace facet::cli
