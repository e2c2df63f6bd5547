// The frame, top to bottom (Renderer::finish): geometry — vertex transform, primitive assembly,
// clip and setup (geometry/, setup/) — then binning (bin/), then per tile in parallel: clear,
// raster + shade, resolve (raster/render_tile.cpp, output/).
#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>

#include "core/parallel.hpp"
#include "core/tick_count.hpp"
#include "pipeline/bin/bin.hpp"
#include "pipeline/geometry/geometry.hpp"
#include "pipeline/geometry/vertex.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/output/debug_view.hpp"
#include "pipeline/output/output.hpp"
#include "pipeline/raster/raster.hpp"
#include "pipeline/renderer_impl.hpp"
#include "shading/lighting.hpp"

namespace facet {

using pipeline::Clock;
using pipeline::is_blended;
using pipeline::ms_since;
using pipeline::TileBuffers;

// Whether every color this frame writes into its tiles is a display value (an 8-bit code, as
// the debug views and the glmark2 scenes' models write): without fog, environment, debug view,
// line or point meshes (their colors are linear), every draw's model writes display values
// unblended. Such a frame is not tone mapped. Known from the draws alone, before geometry (which
// bins by the tile size that depends on it: frame_tile_size).
bool Renderer::Impl::draws_only_display_values() const {
  if (lighting.environment.show_as_background || settings.debug_view != DebugView::none) {
    return false;
  }
  if (lighting.fog.mode != FogMode::none) return false;
  return std::all_of(frame.draws.begin(), frame.draws.end(), [](const pipeline::DrawRecord& d) {
    return d.pipeline.display_referred && d.mesh->topology != Topology::lines &&
           d.mesh->topology != Topology::points;
  });
}

// A frame of display values into an 8-bit sRGB target at exposure 0: the tiles hold code / 255,
// which resolve rounds to the code, instead of the code's decoded linear value, which resolve's
// sRGB encode turns back into the same code with far more work a pixel than the rounding; at one
// sample, where no samples are averaged, the codes themselves (TileContext::codes), which
// resolve copies. The bytes are the same either way.
bool Renderer::Impl::display_referred_frame(const Framebuffer& target) const {
  return target.format() == ColorFormat::rgba8_srgb && settings.exposure == 0.0f &&
         draws_only_display_values();
}

// The tile edge of this frame (RenderSettings::tile_size). Automatic: 128 for a frame whose
// tiles will hold 8-bit codes (a display-referred frame at one sample: TileContext::codes), a
// quarter of a float tile's bytes, so that four times the pixels fit the caches alike while a
// quarter as many tiles share the work paid per tile (a bin's walk, the clears and resolves) and
// fewer triangles straddle two tiles; 64 for the others, whose 128-pixel tiles (256 KB of float
// colors) lose in the caches what they save. Every size gives the same image.
int Renderer::Impl::frame_tile_size(const Framebuffer& target) const {
  if (settings.tile_size != RenderSettings::kAutoTileSize) return settings.tile_size;
  const bool codes =
      frame.samples == 1 && !linear_pass && !depth_only_pass && display_referred_frame(target);
  return codes ? 128 : 64;
}

// Transparency: opaque (and cut-out) draws first in submission order, then blended draws back
// to front, so each blends over what is behind it. Ties keep submission order.
void Renderer::Impl::order_draws() {
  frame.draw_order.clear();
  for (std::uint32_t d = 0; d < frame.draws.size(); ++d) {
    if (!is_blended(frame.draws[d].material.alpha_mode)) frame.draw_order.push_back(d);
  }
  std::size_t first_blended = frame.draw_order.size();
  for (std::uint32_t d = 0; d < frame.draws.size(); ++d) {
    if (is_blended(frame.draws[d].material.alpha_mode)) frame.draw_order.push_back(d);
  }
  std::stable_sort(frame.draw_order.begin() + first_blended, frame.draw_order.end(),
                   [&](std::uint32_t a, std::uint32_t b) {
                     return frame.draws[a].view_depth > frame.draws[b].view_depth;
                   });
}

// The depth view spans the view depths of what the frame draws, not near to far: most frames
// fill a small part of that, and would be one flat grey. The draws' bounds give the range
// without a pass over the pixels.
void Renderer::Impl::set_depth_view_range() {
  shading::FrameUniforms& uniforms = frame.uniforms;
  uniforms.depth_view_near = camera.near_plane;
  uniforms.depth_view_far = camera.far_plane;
  const bool depth_view = std::any_of(frame.draws.begin(), frame.draws.end(), [](const auto& d) {
    return d.material.shading == ShadingModel::depth;
  });
  if (!depth_view) return;
  float nearest = camera.far_plane, farthest = camera.near_plane;
  const glm::mat4 view = camera.view();
  for (const pipeline::DrawRecord& draw : frame.draws) {
    if (!draw.bounds) continue;
    const glm::mat4 model_view = view * draw.uniforms.model;
    for (int corner = 0; corner < 8; ++corner) {
      const float depth = -(model_view * draw.bounds->corner(corner)).z;
      nearest = std::min(nearest, depth), farthest = std::max(farthest, depth);
    }
  }
  uniforms.depth_view_near = std::clamp(nearest, camera.near_plane, camera.far_plane);
  uniforms.depth_view_far = std::clamp(farthest, camera.near_plane, camera.far_plane);
}

void Renderer::Impl::prepare_tiles(const Framebuffer& target) {
  frame.width = target.width();
  frame.height = target.height();
  // The debug views show what the pipeline did per pixel: one sample.
  frame.samples = settings.debug_view == DebugView::none ? settings.msaa : 1;
  frame.tile_size = frame_tile_size(target);
  frame.tiles_x = (frame.width + frame.tile_size - 1) / frame.tile_size;
  frame.tiles_y = (frame.height + frame.tile_size - 1) / frame.tile_size;
  std::size_t tiles = static_cast<std::size_t>(frame.tiles_x) * frame.tiles_y;
  tile_pixels_shaded.assign(tiles, 0);
  tile_ticks.assign(tiles, 0);
  tile_resolve_ticks.assign(tiles, 0);
  // Every worker's tile buffers are sized here, before the tasks: which worker renders which
  // tile changes from frame to frame, and a buffer first grown inside a task would allocate
  // in a steady-state frame.
  const std::size_t pixels = static_cast<std::size_t>(frame.tile_size) * frame.tile_size;
  const int blocks_x = (frame.tile_size + pipeline::kBlockSize - 1) / pipeline::kBlockSize;
  const std::size_t samples = static_cast<std::size_t>(frame.samples);
  for (TileBuffers& buffers : tile_buffers) {
    if (buffers.color.size() >= pixels * samples && buffers.split.size() >= pixels) continue;
    buffers.color.resize(pixels * samples);
    buffers.codes.resize(pixels);
    // find_box_pixels reads past rows
    buffers.depth.resize(pixels * samples + pipeline::kDepthSlack);
    buffers.block_max_depth.resize(static_cast<std::size_t>(blocks_x) * blocks_x);
    buffers.split.resize(pixels);
    buffers.sample_mask.resize(pixels);
  }
}

void Renderer::Impl::run(Framebuffer& target) {
  auto start = Clock::now();
  frame.stats = {};
  prepare_tiles(target);
  if (map_clear_tiles) {
    // Depth alone is cleared to the far plane whatever the clear color and exposure.
    const std::size_t tiles = static_cast<std::size_t>(frame.tiles_x) * frame.tiles_y;
    if (depth_only_pass) {
      map_clear_tiles->fit(frame.tile_size, tiles, glm::vec4(0.0f), 0.0f);
    } else {
      map_clear_tiles->fit(frame.tile_size, tiles, settings.clear_color, settings.exposure);
    }
  }
  // Per-draw pointers into frame-wide data, set now that the draw list no longer grows.
  frame.lights.clear();
  for (const Light& light : lighting.lights) frame.lights.push_back(shading::prepare_light(light));
  if (shadows_ready) {
    for (std::size_t i = 0; i < frame.lights.size() && i < shadows.size(); ++i) {
      if (shadows[i].maps.count > 0) frame.lights[i].shadow = &shadows[i].maps;
    }
  }
  // One SIMD target for the whole frame: every kernel is fetched for it here.
  kernels = pipeline::kernels_for(chosen_simd_target());
  frame.kernels = &kernels;
  shading::FrameUniforms& uniforms = frame.uniforms;
  uniforms.eye = camera.shading_eye();
  uniforms.ambient = lighting.ambient;
  uniforms.lights = frame.lights.data();
  uniforms.light_count = static_cast<int>(frame.lights.size());
  uniforms.lighting = &lighting;
  uniforms.environment_light = nullptr;
  if (lighting.environment.image_based_lighting) {
    environment_light = shading::project_environment(lighting.environment);
    uniforms.environment_light = &environment_light;
  }
  uniforms.near_plane = camera.near_plane;
  uniforms.far_plane = camera.far_plane;
  uniforms.view = camera.view();
  uniforms.projection = camera.projection();
  uniforms.width = frame.width;
  uniforms.height = frame.height;
  uniforms.orthographic = camera.projection_kind == Projection::orthographic;
  uniforms.view_depth = {};  // perspective: clip w
  if (camera.projection_kind == Projection::orthographic) {
    uniforms.view_depth = {0.0f, camera.far_plane - camera.near_plane, camera.near_plane};
  }
  uniforms.display_referred = false;  // decided after geometry (display_referred_frame)
  uniforms.display_exact = false;
  set_depth_view_range();
  uniforms.kernels = &kernels.shading;
  const pipeline::ClipBounds guard = pipeline::guard_band_bounds(frame);
  for (pipeline::DrawRecord& draw : frame.draws) {
    draw.uniforms.material = &draw.material;
    draw.uniforms.frame = &uniforms;
    // Which maps the batch form samples depends on the material: decided here once, not for
    // every triangle.
    shading::maps_to_sample(draw.pipeline.maps_read, draw.material, draw.maps);
    draw.clip_vertices = pipeline::keeps_clip_vertices(draw, guard, frame.max_clip_vertex_bytes);
  }
  order_draws();
  background.clear_color = settings.clear_color;
  background.environment =
      lighting.environment.show_as_background ? &lighting.environment : nullptr;
  background.inverse_view_projection = glm::inverse(frame.view_projection);
  background.eye = camera.shading_eye();
  background.depth_only = depth_only_pass;
  background.width = frame.width;
  background.height = frame.height;
  pipeline::prepare_debug_frame(settings.debug_view, lighting, background);

  // Geometry: transform, assemble, clip, cull, set up — merged in submission order.
  pipeline::run_geometry(frame, workers);
  frame.stats.triangles_in += primitives_outside;  // draws dropped whole when recorded
  frame.stats.culled += primitives_outside;
  frame.stats.ms_geometry = ms_since(start);
  frame.stats.tile_size = frame.tile_size;
  const bool referred = !linear_pass && display_referred_frame(target);
  background.display_referred = frame.stats.display_referred = referred;
  resolve.scale = std::exp2(settings.exposure);
  resolve.display_referred = referred;
  resolve.tone_mapping = draws_only_display_values() ? ToneMapping::none : settings.tone_mapping;
  resolve.maps_background = background.environment != nullptr;
  // Fog fades toward what the curve shows as the fog color, as a clear color of that value
  // shows unmapped.
  if (lighting.fog.mode != FogMode::none) {
    lighting.fog.color = fog_color_under(resolve.tone_mapping, lighting.fog.color, resolve.scale);
  }
  // A float target keeps display values as code / 255 whatever else the frame draws (no sRGB
  // encode follows to undo a decode), and the debug views' values unrounded.
  uniforms.display_exact = !linear_pass && target.format() == ColorFormat::rgba32f;
  uniforms.display_referred = referred || uniforms.display_exact;
  if (referred) {
    background.clear_color = pipeline::display_value_of(kernels, settings.clear_color);
    background.clear_codes = pipeline::display_codes(kernels, background.clear_color);
  }
  resolve.background.reset();
  if (!referred && !background.environment && target.format() == ColorFormat::rgba8_srgb) {
    resolve.background = pipeline::background_codes(kernels, resolve, background.clear_color);
  }

  auto bin_start = Clock::now();
  pipeline::bin_primitives(frame, workers);
  frame.stats.ms_binning = ms_since(bin_start);

  // Raster + shade + resolve: one tile per task, so any thread count gives the same image.
  auto raster_start = Clock::now();
  int tiles = frame.tiles_x * frame.tiles_y;
  parallel_tasks(tiles, workers, [&](int tile, int worker) {
    const std::uint64_t tile_start = tick_count();
    render_tile(tile, worker, target);
    tile_ticks[tile] = ticks_since(tile_start);
  });
  for (std::uint64_t n : tile_pixels_shaded) frame.stats.pixels_shaded += n;
  frame.stats.ms_raster = ms_since(raster_start);
  double busy = 0.0, resolving = 0.0;
  for (std::size_t i = 0; i < tile_ticks.size(); ++i) {
    busy += static_cast<double>(tile_ticks[i]);
    resolving += static_cast<double>(std::min(tile_resolve_ticks[i], tile_ticks[i]));
  }
  frame.stats.ms_resolve = busy > 0.0 ? frame.stats.ms_raster * (resolving / busy) : 0.0;
  frame.stats.ms_total = ms_since(start);
}

}  // namespace facet
