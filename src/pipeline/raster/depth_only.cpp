// Stage: raster, depth alone (see depth_only.hpp).
#include "pipeline/raster/depth_only.hpp"

#include <algorithm>
#include <optional>

#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/raster.hpp"
#include "pipeline/raster/small_triangles.hpp"

namespace facet::pipeline {
namespace {

// The blocks of the box [x0, x1] x [y0, y1] (frame pixels, inclusive) the triangle may change
// (for_each_block): the part of each within the box is searched as a small box is, its covered
// pixels in front taking their depths at once (write_box_depths). Returns how many.
int write_block_depths(TileContext& tile, const SetupTriangle& t, int x0, int y0, int x1, int y1,
                       const DepthRange& box_depth) {
  BlockInput in;
  in.triangle = &t;
  int written = 0;
  for_each_block<true>(tile, t, x0, y0, x1, y1, box_depth, in,
                       [&](int block_x, int block_y, EdgeCover, float& max_depth) {
                         const int left = block_x + in.x_begin, top = block_y + in.y_begin;
                         const int width = in.x_end - in.x_begin, height = in.y_end - in.y_begin;
                         const int count = tile.kernels.write_box_depths(
                             t, left, top, width, height, tile.depth + tile_index(tile, left, top),
                             tile.stride);
                         written += count;
                         lower_block_bound(tile, t, block_x, block_y, count, max_depth);
                       });
  return written;
}

}  // namespace

void raster_depth_only(TileContext& tile, const SetupTriangle& t) {
  const int x0 = std::max(t.min_x, tile.x0), x1 = std::min(t.max_x, tile.x1 - 1);
  const int y0 = std::max(t.min_y, tile.y0), y1 = std::min(t.max_y, tile.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  flush_waiting(tile);  // this triangle is drawn after them
  const int width = x1 - x0 + 1;
  if (box_may_wait(width, y1 - y0 + 1)) {
    // Small: the box searched a band of rows at a time, as the waiting pixels' search takes it
    // (add_waiting), which keeps its edge values within 32 bits.
    const int rows = kMaxWaitingBox / width;
    for (int y = y0; y <= y1; y += rows) {
      float* depth = tile.depth + tile_index(tile, x0, y);
      tile.pixels_shaded += tile.kernels.write_box_depths(
          t, x0, y, width, std::min(rows, y1 - y + 1), depth, tile.stride);
    }
    return;
  }
  const std::optional<DepthRange> box_depth = depths_in_front(tile, t, x0, y0, x1, y1);
  if (box_depth) tile.pixels_shaded += write_block_depths(tile, t, x0, y0, x1, y1, *box_depth);
}

}  // namespace facet::pipeline
