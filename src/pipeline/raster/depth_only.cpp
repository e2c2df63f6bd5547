// Stage: raster, depth alone (see depth_only.hpp).
#include "pipeline/raster/depth_only.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/pixel_writer.hpp"
#include "pipeline/raster/raster.hpp"
#include "pipeline/raster/small_triangles.hpp"

namespace facet::pipeline {
namespace {

// The blocks of the box [x0, x1] x [y0, y1] (frame pixels, inclusive), as raster_triangle walks
// them: each block the triangle may cover in front of what is drawn there goes through
// cover_block, and its covered pixels take their depths.
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
  const int bx0 = (x0 - tile.x0) / kBlockSize, bx1 = (x1 - tile.x0) / kBlockSize;
  const int by0 = (y0 - tile.y0) / kBlockSize, by1 = (y1 - tile.y0) / kBlockSize;
  for (int by = by0; by <= by1; ++by) {
    const int block_y = tile.y0 + by * kBlockSize;
    in.y_begin = std::max(y0, block_y) - block_y;
    in.y_end = std::min(y1, block_y + kBlockSize - 1) - block_y + 1;
    for (int bx = bx0; bx <= bx1; ++bx) {
      const int block_x = tile.x0 + bx * kBlockSize;
      if (tile.block_starts != nullptr && tile.entry < tile.block_starts[by * tile.blocks_x + bx])
        continue;  // a later triangle hides this one here
      in.x_begin = std::max(x0, block_x) - block_x;
      in.x_end = std::min(x1, block_x + kBlockSize - 1) - block_x + 1;
      if (classify_edges(t, block_x, block_y, in) == EdgeCover::outside) continue;
      in.px0 = static_cast<float>(block_x) + 0.5f;
      in.py0 = static_cast<float>(block_y) + 0.5f;
      float& max_depth = tile.block_max_depth[by * tile.blocks_x + bx];
      if (!(box_depth.farthest < max_depth)) {
        const float nearest = depth_range_over(t, block_x + in.x_begin, block_y + in.y_begin,
                                               block_x + in.x_end - 1, block_y + in.y_end - 1)
                                  .nearest;
        if (nearest >= max_depth) continue;  // every pixel fails "less"; NaN goes on
      }
      float* depth = tile.depth + static_cast<std::ptrdiff_t>(block_y - tile.y0) * tile.stride +
                     (block_x - tile.x0);
      in.depth = depth;
      tile.kernels.cover_block(in, block);
      if (block.mask == 0) continue;
      if (block.mask == ~std::uint64_t{0}) {
        for (int row = 0; row < kBlockSize; ++row) {
          std::memcpy(depth + static_cast<std::ptrdiff_t>(row) * tile.stride,
                      block.z + row * kBlockSize, sizeof(float) * kBlockSize);
        }
      } else {
        for (std::uint64_t m = block.mask; m != 0; m &= m - 1) {
          const int i = std::countr_zero(m);
          depth[static_cast<std::ptrdiff_t>(i / kBlockSize) * tile.stride + i % kBlockSize] =
              block.z[i];
        }
      }
      written += std::popcount(block.mask);
      // Every pixel of the block written: the triangle's farthest over it bounds the block.
      const int width = std::min(kBlockSize, tile.x1 - block_x);
      const int height = std::min(kBlockSize, tile.y1 - block_y);
      if (block.mask == block_pixels_mask(width, height)) {
        const float farthest =
            depth_range_over(t, block_x, block_y, block_x + width - 1, block_y + height - 1)
                .farthest;
        max_depth = std::min(max_depth, farthest);
      }
    }
  }
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
  // A triangle behind everything drawn over its box is done without an edge test.
  float farthest_drawn = 0.0f;
  for (int by = (y0 - tile.y0) / kBlockSize; by <= (y1 - tile.y0) / kBlockSize; ++by) {
    for (int bx = (x0 - tile.x0) / kBlockSize; bx <= (x1 - tile.x0) / kBlockSize; ++bx) {
      farthest_drawn = std::max(farthest_drawn, tile.block_max_depth[by * tile.blocks_x + bx]);
    }
  }
  const DepthRange box_depth = depth_range_over(t, x0, y0, x1, y1);
  if (box_depth.nearest >= farthest_drawn) return;  // NaN goes on
  tile.pixels_shaded += write_block_depths(tile, t, x0, y0, x1, y1, box_depth);
}

}  // namespace facet::pipeline
