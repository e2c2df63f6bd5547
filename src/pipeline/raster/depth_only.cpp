// Stage: raster, depth alone (see depth_only.hpp).
#include "pipeline/raster/depth_only.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>

#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/pixel_writer.hpp"
#include "pipeline/raster/raster.hpp"
#include "pipeline/raster/small_triangles.hpp"

namespace facet::pipeline {
namespace {

// The block's covered pixels (block.mask) take their depths (block.z), into the tile's depth
// from the block's first pixel `depth` on.
void write_depths(const TileContext& tile, const BlockFragments& block, float* depth) {
  if (block.mask == ~std::uint64_t{0}) {
    for (int row = 0; row < kBlockSize; ++row) {
      std::memcpy(depth + static_cast<std::ptrdiff_t>(row) * tile.stride,
                  block.z + row * kBlockSize, sizeof(float) * kBlockSize);
    }
    return;
  }
  for (std::uint64_t m = block.mask; m != 0; m &= m - 1) {
    const int i = std::countr_zero(m);
    depth[static_cast<std::ptrdiff_t>(i / kBlockSize) * tile.stride + i % kBlockSize] = block.z[i];
  }
}

// The blocks of the box [x0, x1] x [y0, y1] (frame pixels, inclusive) the triangle may change
// (for_each_block): their covered pixels take cover_block's depths. Returns how many.
int write_block_depths(TileContext& tile, const SetupTriangle& t, int x0, int y0, int x1, int y1,
                       const DepthRange& box_depth) {
  BlockInput in;
  in.triangle = &t;
  in.varying_planes = nullptr;
  in.varyings = 0;
  in.depth_test = true;
  in.depth_stride = tile.stride;
  in.interpolate = false;
  alignas(64) BlockFragments block;
  int written = 0;
  for_each_block<true>(tile, t, x0, y0, x1, y1, box_depth, in,
                       [&](int block_x, int block_y, EdgeCover, float& max_depth) {
                         tile.kernels.cover_block(in, block);
                         if (block.mask == 0) return;
                         write_depths(tile, block, tile.depth + tile_index(tile, block_x, block_y));
                         const int count = std::popcount(block.mask);
                         written += count;
                         lower_block_bound(tile, t, block_x, block_y, block.mask, count, max_depth);
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
