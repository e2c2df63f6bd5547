// The frame, top to bottom: Renderer records draws, then finish() runs the stages in order —
// vertex transform (vertex.cpp), primitive assembly + clip + setup (primitive.cpp, clip.cpp,
// setup.cpp), binning (bin.cpp), then per tile in parallel: clear, raster + shade
// (raster.hpp, line.cpp), resolve (output.cpp).
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <optional>
#include <string>
#include <unordered_map>

#include "facet/error.hpp"
#include "pipeline/bin/bin.hpp"
#include "pipeline/geometry/geometry.hpp"
#include "pipeline/geometry/vertex.hpp"
#include "pipeline/output/debug_view.hpp"
#include "pipeline/output/output.hpp"
#include "pipeline/parallel.hpp"
#include "pipeline/raster/occlusion.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/draw_culling.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/lighting.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

bool is_blended(AlphaMode mode) { return mode == AlphaMode::blend || mode == AlphaMode::additive; }

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A worker's tile buffers, reused for every tile it renders.
struct TileBuffers {
  std::vector<glm::vec4> color;
  std::vector<float> depth;
  std::vector<float> block_max_depth;  // one per 8x8 block (raster.hpp)
};

}  // namespace

struct Renderer::Impl {
  RenderSettings settings;
  int workers;
  // oneTBB caps workers at the core count unless told otherwise; more threads than cores is
  // a legitimate request (the determinism tests make it), so raise the cap while we live.
  std::optional<tbb::global_control> allow_workers;
  tbb::task_arena arena;
  std::vector<TileBuffers> tile_buffers;  // one per worker
  pipeline::Frame frame;
  std::vector<std::uint64_t> tile_pixels_shaded;
  std::vector<double> tile_ms, tile_resolve_ms;  // per tile: its task, and its resolve
  pipeline::Background background;
  Camera camera;
  Lighting lighting;
  bool recording = false;
  std::uint64_t primitives_outside = 0;  // of draws outside the frustum, never recorded
  // Meshes drawn through shared pointers, checked once (Renderer::draw): at the islands' 750
  // draws a frame, checking every mesh again took 4 % of a 720p frame on 2 threads, all of it
  // on the recording thread. An entry holds its mesh, so no other mesh can take its address
  // while it is remembered; it is forgotten a frame after the last that drew it.
  struct CheckedMesh {
    std::shared_ptr<const Mesh> mesh;
    std::optional<pipeline::MeshBox> box;
    std::uint64_t last_frame = 0;
  };
  std::unordered_map<const Mesh*, CheckedMesh> checked_meshes;
  std::uint64_t frame_number = 0;

  explicit Impl(const RenderSettings& s)
      : settings(s),
        workers(s.threads == 0 ? tbb::info::default_concurrency() : s.threads),
        allow_workers(workers > tbb::info::default_concurrency()
                          ? std::make_optional<tbb::global_control>(
                                tbb::global_control::max_allowed_parallelism, workers)
                          : std::nullopt),
        arena(workers),
        tile_buffers(workers) {}

  // Records a draw of a mesh that Mesh::validate() accepts, whose bounds are `box`.
  void record(const Mesh& mesh, const std::optional<pipeline::MeshBox>& box,
              const Material& material, const glm::mat4& transform,
              const pipeline::DrawPipeline& pipe);
  // The bounds of a mesh drawn through a shared pointer, checked the first time (draw()).
  const std::optional<pipeline::MeshBox>& checked_bounds(const std::shared_ptr<const Mesh>& mesh);
  // Records a draw of any mesh: checks it first.
  void check_and_record(const Mesh& mesh, const Material& material, const glm::mat4& transform,
                        const pipeline::DrawPipeline& pipe);
  void prepare_tiles(const Framebuffer& target);
  void render_tile(int index, int worker, Framebuffer& target);
  void run(Framebuffer& target);
  void order_draws();
  bool display_referred_frame(const Framebuffer& target) const;
};

// Whether every color this frame writes into its tiles is a display value (an 8-bit code, as
// the debug views and the glmark2 scenes' models write): then the tiles hold code / 255, which
// resolve rounds back to the code, instead of the code's decoded linear value, which resolve's
// sRGB encode turns back into the same code at 30 instructions a pixel (a fifth of
// texture:linear's frame). The bytes are the same either way. Only for 8-bit sRGB targets at
// exposure 0, without fog, environment, debug view or lines, when every draw's model writes
// display values unblended.
bool Renderer::Impl::display_referred_frame(const Framebuffer& target) const {
  if (target.format() != ColorFormat::rgba8_srgb || settings.exposure != 0.0f) return false;
  if (background.environment != nullptr || settings.debug_view != DebugView::none) return false;
  if (lighting.fog.mode != FogMode::none || !frame.lines.empty()) return false;
  return std::all_of(frame.draws.begin(), frame.draws.end(),
                     [](const pipeline::DrawRecord& d) { return d.pipeline.display_referred; });
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

Renderer::Renderer(const RenderSettings& settings) {
  if (settings.threads < 0) {
    throw Error("renderer: threads must be 0 (all cores) or positive, got " +
                std::to_string(settings.threads));
  }
  int ts = settings.tile_size;
  if (ts != 16 && ts != 32 && ts != 64 && ts != 128) {
    throw Error("renderer: tile size must be 16, 32, 64 or 128, got " + std::to_string(ts));
  }
  impl_ = std::make_unique<Impl>(settings);
}

Renderer::~Renderer() = default;

const RenderSettings& Renderer::settings() const { return impl_->settings; }
const FrameStats& Renderer::stats() const { return impl_->frame.stats; }

void Renderer::begin_frame(const Camera& camera) {
  // A shared default, so a frame without lighting builds no Lighting (and allocates nothing).
  static const Lighting kDefaultLighting;
  begin_frame(camera, kDefaultLighting);
}

const Camera& Renderer::camera() const { return impl_->camera; }

void Renderer::begin_frame(const Camera& camera, const Lighting& lighting) {
  camera.validate();
  impl_->camera = camera;
  impl_->lighting = lighting;
  impl_->frame.draws.clear();
  impl_->primitives_outside = 0;
  const std::uint64_t frame_number = ++impl_->frame_number;
  std::erase_if(impl_->checked_meshes, [frame_number](const auto& entry) {
    return entry.second.last_frame + 1 < frame_number;  // not drawn in the last frame
  });
  impl_->frame.view_projection = camera.view_projection();
  impl_->recording = true;
}

void Renderer::draw(const Mesh& mesh, const Material& material, const glm::mat4& transform) {
  impl_->check_and_record(mesh, material, transform,
                          pipeline::pipeline_for(material, mesh, impl_->lighting));
}

void Renderer::draw(const std::shared_ptr<const Mesh>& mesh, const Material& material,
                    const glm::mat4& transform) {
  const std::optional<pipeline::MeshBox>& box = impl_->checked_bounds(mesh);
  impl_->record(*mesh, box, material, transform,
                pipeline::pipeline_for(material, *mesh, impl_->lighting));
}

const std::optional<pipeline::MeshBox>& Renderer::Impl::checked_bounds(
    const std::shared_ptr<const Mesh>& mesh) {
  if (!recording) throw Error("renderer: draw() called before begin_frame()");
  if (!mesh) throw Error("renderer: draw() of a null mesh pointer");
  auto [entry, added] = checked_meshes.try_emplace(mesh.get());
  if (added) {
    try {
      mesh->validate();
    } catch (...) {
      checked_meshes.erase(entry);
      throw;
    }
    entry->second.mesh = mesh;
    entry->second.box = pipeline::finite_bounds(*mesh);
  }
  entry->second.last_frame = frame_number;
  return entry->second.box;
}

void Renderer::Impl::check_and_record(const Mesh& mesh, const Material& material,
                                      const glm::mat4& transform,
                                      const pipeline::DrawPipeline& pipe) {
  if (!recording) throw Error("renderer: draw() called before begin_frame()");
  mesh.validate();
  record(mesh, pipeline::finite_bounds(mesh), material, transform, pipe);
}

void Renderer::Impl::record(const Mesh& mesh, const std::optional<pipeline::MeshBox>& box,
                            const Material& material, const glm::mat4& transform,
                            const pipeline::DrawPipeline& pipe) {
  const glm::mat4 model_view_projection = frame.view_projection * transform;
  if (box && pipeline::box_outside_frustum(*box, model_view_projection)) {
    primitives_outside += mesh.primitive_count();
    return;
  }
  pipeline::DrawRecord record;
  record.mesh = &mesh;
  record.bounds = box;
  record.material = material;
  record.pipeline = pipeline::debug_pipeline(settings.debug_view, pipe);
  if (is_blended(material.alpha_mode) && box) {
    glm::vec4 centre = camera.view() * transform * glm::vec4((box->low + box->high) * 0.5f, 1.0f);
    record.view_depth = -centre.z;
  }
  shading::DrawUniforms& u = record.uniforms;
  u.model = transform;
  u.model_view_projection = model_view_projection;
  u.normal_matrix = glm::inverseTranspose(glm::mat3(transform));
  u.base_color = material.base_color;
  u.wire_color = material.wire_color;
  u.use_vertex_colors = material.use_vertex_colors;
  u.ambient = lighting.ambient;
  u.eye = camera.eye;
  u.near_plane = camera.near_plane;
  u.far_plane = camera.far_plane;
  frame.draws.push_back(record);
}

void Renderer::finish(Framebuffer& target) {
  if (!impl_->recording) throw Error("renderer: finish() called before begin_frame()");
  impl_->arena.execute([&] { impl_->run(target); });
  impl_->recording = false;
}

void Renderer::Impl::prepare_tiles(const Framebuffer& target) {
  frame.width = target.width();
  frame.height = target.height();
  frame.tile_size = settings.tile_size;
  frame.tiles_x = (frame.width + frame.tile_size - 1) / frame.tile_size;
  frame.tiles_y = (frame.height + frame.tile_size - 1) / frame.tile_size;
  std::size_t tiles = static_cast<std::size_t>(frame.tiles_x) * frame.tiles_y;
  tile_pixels_shaded.assign(tiles, 0);
  tile_ms.assign(tiles, 0.0);
  tile_resolve_ms.assign(tiles, 0.0);
  // Every worker's tile buffers are sized here, before the tasks: which worker renders which
  // tile changes from frame to frame, and a buffer first grown inside a task would allocate
  // in a steady-state frame.
  const std::size_t pixels = static_cast<std::size_t>(frame.tile_size) * frame.tile_size;
  const int blocks_x = (frame.tile_size + pipeline::kBlockSize - 1) / pipeline::kBlockSize;
  for (TileBuffers& buffers : tile_buffers) {
    if (buffers.color.size() >= pixels) continue;
    buffers.color.resize(pixels);
    buffers.depth.resize(pixels + pipeline::kDepthSlack);  // find_box_pixels reads past rows
    buffers.block_max_depth.resize(static_cast<std::size_t>(blocks_x) * blocks_x);
  }
}

void Renderer::Impl::run(Framebuffer& target) {
  auto start = Clock::now();
  frame.stats = {};
  prepare_tiles(target);
  // Per-draw pointers into frame-wide data, set now that the draw list no longer grows.
  frame.lights.clear();
  for (const Light& light : lighting.lights) frame.lights.push_back(shading::prepare_light(light));
  const pipeline::ClipBounds guard = pipeline::guard_band_bounds(frame.width, frame.height);
  for (pipeline::DrawRecord& draw : frame.draws) {
    draw.uniforms.lights = frame.lights.data();
    draw.uniforms.light_count = static_cast<int>(frame.lights.size());
    draw.uniforms.material = &draw.material;
    draw.uniforms.lighting = &lighting;
    // Whether the batch form takes the draw depends on its lights and material: decided here
    // once, not for every triangle.
    draw.batch_shaded = draw.pipeline.batch_shades && draw.pipeline.batch_shades(draw.uniforms);
    draw.batch_vertices =
        draw.pipeline.batches_vertices && draw.pipeline.batches_vertices(draw.uniforms);
    draw.clip_vertices = pipeline::keeps_clip_vertices(draw, guard);
  }
  order_draws();
  background.clear_color = settings.clear_color;
  background.environment =
      lighting.environment.show_as_background ? &lighting.environment : nullptr;
  background.inverse_view_projection = glm::inverse(frame.view_projection);
  background.eye = camera.eye;
  background.width = frame.width;
  background.height = frame.height;
  pipeline::prepare_debug_frame(settings.debug_view, lighting, background);

  // Geometry: transform, assemble, clip, cull, set up — merged in submission order.
  pipeline::run_geometry(frame, workers);
  frame.stats.triangles_in += primitives_outside;  // draws dropped whole when recorded
  frame.stats.culled += primitives_outside;
  frame.stats.ms_geometry = ms_since(start);
  const bool referred = display_referred_frame(target);
  background.display_referred = frame.stats.display_referred = referred;
  for (pipeline::DrawRecord& draw : frame.draws) draw.uniforms.display_referred = referred;
  if (referred) background.clear_color = pipeline::display_value_of(settings.clear_color);

  auto bin_start = Clock::now();
  pipeline::bin_primitives(frame, workers);
  frame.stats.ms_binning = ms_since(bin_start);

  // Raster + shade + resolve: one tile per task, so any thread count gives the same image.
  auto raster_start = Clock::now();
  int tiles = frame.tiles_x * frame.tiles_y;
  pipeline::parallel_tasks(tiles, workers, [&](int tile, int worker) {
    auto tile_start = Clock::now();
    render_tile(tile, worker, target);
    tile_ms[tile] = ms_since(tile_start);
  });
  for (std::uint64_t n : tile_pixels_shaded) frame.stats.pixels_shaded += n;
  frame.stats.ms_raster = ms_since(raster_start);
  double busy = 0.0, resolving = 0.0;
  for (std::size_t i = 0; i < tile_ms.size(); ++i)
    busy += tile_ms[i], resolving += tile_resolve_ms[i];
  frame.stats.ms_resolve = busy > 0.0 ? frame.stats.ms_raster * (resolving / busy) : 0.0;
  frame.stats.ms_total = ms_since(start);
}

namespace {

// A bin's triangles lie far apart in the frame's arrays, each read for the first time since
// setup wrote it, and the wait for each was 6 % of bunny-close's frame: render_tile asks for
// the triangle kPrefetchAhead entries ahead, and for the varying planes of the one half as far
// ahead (whose triangle, asked for earlier, says where they are). Always inline: out of line,
// GCC took the function for one without effects (a prefetch changes no value) and dropped
// its calls.
constexpr std::ptrdiff_t kPrefetchAhead = 8;
[[gnu::always_inline]] inline void prefetch_ahead(const pipeline::Frame& frame,
                                                  const std::uint32_t* bin,
                                                  const std::uint32_t* bin_end) {
  if (bin_end - bin > kPrefetchAhead && !(bin[kPrefetchAhead] & pipeline::kLineBit)) {
    // Every cache line of the record: 104 bytes at multiples of 8 often span three.
    const auto* far = reinterpret_cast<const char*>(&frame.triangles[bin[kPrefetchAhead]]);
    static_assert(sizeof(pipeline::SetupTriangle) <= 128);
    __builtin_prefetch(far);
    __builtin_prefetch(far + 64);
    __builtin_prefetch(far + sizeof(pipeline::SetupTriangle) - 1);
  }
  if (bin_end - bin > kPrefetchAhead / 2 && !(bin[kPrefetchAhead / 2] & pipeline::kLineBit)) {
    const pipeline::SetupTriangle& near = frame.triangles[bin[kPrefetchAhead / 2]];
    __builtin_prefetch(frame.planes.data() + near.varying_planes);
  }
}

}  // namespace

void Renderer::Impl::render_tile(int index, int worker, Framebuffer& target) {
  const int ts = frame.tile_size;
  pipeline::TileContext tile;
  tile.frame = &frame;
  tile.x0 = (index % frame.tiles_x) * ts;
  tile.y0 = (index / frame.tiles_x) * ts;
  tile.x1 = std::min(tile.x0 + ts, frame.width);
  tile.y1 = std::min(tile.y0 + ts, frame.height);
  tile.stride = ts;
  const std::uint32_t* bin = frame.bin_entries.data() + frame.bin_start[index];
  const std::uint32_t* bin_end = frame.bin_entries.data() + frame.bin_start[index + 1];
  const std::size_t bin_size = static_cast<std::size_t>(bin_end - bin);
  const float scale = std::exp2(settings.exposure);
  const DebugView debug = settings.debug_view;
  if (bin == bin_end && !background.environment && debug == DebugView::none) {
    // Lazy clear: nothing drawn here, write the clear values directly.
    auto resolve_start = Clock::now();
    pipeline::resolve_cleared_tile(tile, settings.clear_color, scale, target);
    tile_resolve_ms[index] = ms_since(resolve_start);
    return;
  }
  TileBuffers& buffers = tile_buffers[worker];  // sized in prepare_tiles
  tile.blocks_x = (ts + pipeline::kBlockSize - 1) / pipeline::kBlockSize;
  tile.color = buffers.color.data();
  tile.depth = buffers.depth.data();
  tile.block_max_depth = buffers.block_max_depth.data();
  pipeline::WaitingPixels waiting;
  tile.waiting = &waiting;
  // Skip what the tile's last full, opaque, nearest triangle hides anyway (binning noted
  // whether there may be one); in bins of a few (large) triangles, also what such triangles
  // hide block by block.
  const bool may_hide = frame.bin_may_hide[index] != 0;
  if (may_hide) {
    bin += pipeline::first_visible_entry(frame, bin, bin_end - bin, tile.x0, tile.y0, tile.x1,
                                         tile.y1);
  }
  const std::uint32_t* const first_drawn = bin;
  // The views count or color what is drawn in their own ways: they always start cleared.
  const bool color_hidden = debug == DebugView::none && may_hide && bin != bin_end &&
                            pipeline::hides_clear(frame, *bin, tile.x0, tile.y0, tile.x1, tile.y1);
  pipeline::clear_tile(tile, background, color_hidden);
  std::uint32_t block_starts[pipeline::kMaxTileBlocks];
  if (bin_end - bin <= static_cast<std::ptrdiff_t>(pipeline::kMaxBlockOcclusionEntries) &&
      pipeline::first_visible_entries_per_block(frame, bin, bin_end - bin, tile.x0, tile.y0,
                                                tile.x1, tile.y1, tile.blocks_x, block_starts)) {
    tile.block_starts = block_starts;
  }
  // The environment is drawn late, into what no opaque triangle covered (fill_background):
  // before the first primitive that could write color without depth, or at the end.
  bool background_pending = background.environment != nullptr;
  for (; bin != bin_end; ++bin) {
    const std::uint32_t entry = *bin;
    tile.entry = static_cast<std::uint32_t>(bin - first_drawn);
    prefetch_ahead(frame, bin, bin_end);
    if (entry & pipeline::kLineBit) {
      // The overdraw heat map counts triangles; a line would overwrite the count.
      if (debug == DebugView::overdraw) continue;
      pipeline::flush_waiting(tile);
      if (background_pending)
        pipeline::fill_background(tile, background), background_pending = false;
      pipeline::raster_line(tile, frame.lines[entry & ~pipeline::kLineBit]);
    } else {
      const pipeline::SetupTriangle& t = frame.triangles[entry];
      const pipeline::DrawPipeline& draw_pipeline = frame.draws[t.draw].pipeline;
      if (background_pending && !draw_pipeline.occludes) {
        pipeline::flush_waiting(tile);
        pipeline::fill_background(tile, background), background_pending = false;
      }
      draw_pipeline.raster(tile, t);
    }
  }
  pipeline::flush_waiting(tile);
  if (background_pending) pipeline::fill_background(tile, background);
  auto resolve_start = Clock::now();
  if (debug == DebugView::none) {
    pipeline::resolve_tile(tile, scale, background.display_referred, target);
  } else {
    pipeline::resolve_debug_tile(tile, debug, bin_size, scale, target);
  }
  tile_resolve_ms[index] = ms_since(resolve_start);
  tile_pixels_shaded[index] = tile.pixels_shaded;
}

struct RendererAccess {
  static Renderer::Impl& impl(Renderer& renderer) { return *renderer.impl_; }
};

namespace pipeline {

void draw_with_pipeline(Renderer& renderer, const Mesh& mesh, const Material& material,
                        const glm::mat4& transform, const DrawPipeline& pipe) {
  RendererAccess::impl(renderer).check_and_record(mesh, material, transform, pipe);
}

void draw_with_pipeline(Renderer& renderer, const std::shared_ptr<const Mesh>& mesh,
                        const Material& material, const glm::mat4& transform,
                        const DrawPipeline& pipe) {
  auto& impl = RendererAccess::impl(renderer);  // Impl is private: not named here
  const std::optional<MeshBox>& box = impl.checked_bounds(mesh);
  impl.record(*mesh, box, material, transform, pipe);
}

}  // namespace pipeline
}  // namespace facet
