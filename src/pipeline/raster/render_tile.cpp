// Stage: raster + shade + resolve of one tile (Renderer::Impl::render_tile, one task per tile:
// frame_run.cpp). Walks the tile's bin in submission order — skipping what occlusion shows
// hidden (occlusion.hpp) — hands each triangle to its draw's specialised raster routine
// (raster.hpp), each line to line.cpp and each point to point.cpp, fills the background where
// nothing covered, then resolves the tile into the framebuffer (output/).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/tick_count.hpp"
#include "pipeline/output/debug_view.hpp"
#include "pipeline/output/output.hpp"
#include "pipeline/raster/occlusion.hpp"
#include "pipeline/raster/raster.hpp"
#include "pipeline/renderer_impl.hpp"
#include "pipeline/shadow/shadow_reach.hpp"

namespace facet {

using pipeline::TileBuffers;

namespace {

// A bin's triangles lie far apart in the frame's arrays, each read for the first time since
// setup wrote it, so each would be a cache miss waited for: render_tile asks for the triangle
// kPrefetchAhead entries ahead, and for the varying planes of the one half as far ahead (whose
// triangle, asked for earlier, says where they are). Always inline: out of line, GCC takes the
// function for one without effects (a prefetch changes no value) and drops its calls.
constexpr std::ptrdiff_t kPrefetchAhead = 8;
[[gnu::always_inline]] inline void prefetch_ahead(const pipeline::Frame& frame,
                                                  const std::uint32_t* bin,
                                                  const std::uint32_t* bin_end) {
  if (bin_end - bin > kPrefetchAhead && pipeline::is_triangle_entry(bin[kPrefetchAhead])) {
    // Every cache line of the record: 104 bytes at multiples of 8 often span three.
    const auto* far = reinterpret_cast<const char*>(&frame.triangles[bin[kPrefetchAhead]]);
    static_assert(sizeof(pipeline::SetupTriangle) <= 128);
    __builtin_prefetch(far);
    __builtin_prefetch(far + 64);
    __builtin_prefetch(far + sizeof(pipeline::SetupTriangle) - 1);
  }
  if (bin_end - bin > kPrefetchAhead / 2 && pipeline::is_triangle_entry(bin[kPrefetchAhead / 2])) {
    const pipeline::SetupTriangle& near = frame.triangles[bin[kPrefetchAhead / 2]];
    __builtin_prefetch(frame.planes.data() + near.varying_planes);
  }
}

}  // namespace

void Renderer::Impl::render_tile(int index, int worker, Framebuffer& target) {
  const int ts = frame.tile_size;
  pipeline::TileContext tile;
  tile.frame = &frame;
  tile.kernels = frame.kernels->raster;
  tile.x0 = (index % frame.tiles_x) * ts;
  tile.y0 = (index / frame.tiles_x) * ts;
  tile.x1 = std::min(tile.x0 + ts, frame.width);
  tile.y1 = std::min(tile.y0 + ts, frame.height);
  tile.stride = ts;
  const std::uint32_t* bin = frame.bin_entries.data() + frame.bin_start[index];
  const std::uint32_t* bin_end = frame.bin_entries.data() + frame.bin_start[index + 1];
  const std::size_t bin_size = static_cast<std::size_t>(bin_end - bin);
  // A shadow map's tile that no lookup reads keeps what it held (shadow_reach.hpp).
  if (map_reach && pipeline::texels_outside_reach(*map_reach, tile.x0, tile.y0, tile.x1, tile.y1)) {
    tile_resolve_ticks[index] = 0, tile_pixels_shaded[index] = 0;
    return;
  }
  const DebugView debug = settings.debug_view;
  if (bin == bin_end && !background.environment && debug == DebugView::none) {
    // Lazy clear: nothing drawn here, write the clear values directly.
    const std::uint64_t resolve_start = tick_count();
    if (map_clear_tiles && map_clear_tiles->clear[index]) {
      // A tile that holds the clear values already.
    } else {
      if (background.depth_only) {
        pipeline::resolve_depth_tile(tile, true, target);
      } else {
        pipeline::resolve_cleared_tile(tile, settings.clear_color, resolve.scale, target);
      }
      if (map_clear_tiles) map_clear_tiles->clear[index] = 1;
    }
    tile_resolve_ticks[index] = ticks_since(resolve_start);
    return;
  }
  TileBuffers& buffers = tile_buffers[worker];  // sized in prepare_tiles
  tile.blocks_x = (ts + pipeline::kBlockSize - 1) / pipeline::kBlockSize;
  tile.color = buffers.color.data();
  // Display values whose codes the resolve would only copy: the tile holds the codes.
  if (resolve.display_referred && frame.samples == 1) tile.codes = buffers.codes.data();
  tile.depth = buffers.depth.data();
  tile.block_max_depth = buffers.block_max_depth.data();
  tile.samples = frame.samples;
  tile.sample_plane = static_cast<std::ptrdiff_t>(ts) * ts;
  tile.sample_colors = tile.color + tile.sample_plane;
  tile.split = buffers.split.data();
  tile.sample_mask = buffers.sample_mask.data();
  pipeline::WaitingPixels waiting;
  tile.waiting = &waiting;
  // Skip what the tile's last full, opaque, nearest triangle hides anyway (binning noted
  // whether there may be one); in bins of a few (large) triangles, also what such triangles
  // hide block by block.
  // Under MSAA the same, reasoning about every sample (occlusion.cpp).
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
  if (pipeline::looks_per_block(static_cast<std::size_t>(bin_end - bin),
                                (tile.x1 - tile.x0) * (tile.y1 - tile.y0)) &&
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
    if (!pipeline::is_triangle_entry(entry)) {
      // The overdraw heat map counts triangles; a line or point would overwrite the count.
      if (debug == DebugView::overdraw) continue;
      pipeline::flush_waiting(tile);
      if (background_pending)
        pipeline::fill_background(tile, background), background_pending = false;
      if (entry & pipeline::kLineBit) {
        pipeline::raster_line(tile, frame.lines[entry & ~pipeline::kLineBit]);
      } else {
        pipeline::raster_point(tile, frame.points[entry & ~pipeline::kPointBit]);
      }
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
  const std::uint64_t resolve_start = tick_count();
  if (map_clear_tiles) map_clear_tiles->clear[index] = 0;
  if (background.depth_only) {
    pipeline::resolve_depth_tile(tile, false, target);
  } else if (debug == DebugView::none) {
    pipeline::resolve_tile(tile, resolve, target);
  } else {
    pipeline::resolve_debug_tile(tile, debug, bin_size, resolve.scale, target);
  }
  tile_resolve_ticks[index] = ticks_since(resolve_start);
  tile_pixels_shaded[index] = tile.pixels_shaded;
}

}  // namespace facet
