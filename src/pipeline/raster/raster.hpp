// Stage: raster + shade. Reads one tile's bin (bin.cpp) and, for each triangle in submission
// order, finds the covered pixel centres with the fixed-point edge functions set up in
// setup.cpp, tests depth early, shades with the draw's shading model and writes the tile's
// own color and depth buffers; output.cpp then resolves the tile to the framebuffer.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

#include "pipeline/frame.hpp"
#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/depth_only.hpp"
#include "pipeline/raster/msaa.hpp"
#include "pipeline/raster/pixel_writer.hpp"
#include "pipeline/raster/small_triangles.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {

// Classifies the three edges at the four corners of the block rectangle in.[xy]_begin/end
// (exact, in 64 bits) and fills the 32-bit edge values cover_block steps with (block_raster.hpp
// says why 32 bits hold them). An edge inside at all four corners is inside at every pixel
// between them. Returns whether the rectangle lies outside some edge (no pixel covered),
// inside all three (every pixel covered), or crosses an edge.
inline EdgeCover classify_edges(const SetupTriangle& t, int block_x, int block_y, BlockInput& in) {
  EdgeCover cover = EdgeCover::inside;
  for (int i = 0; i < 3; ++i) {
    // floor(E / 256): an arithmetic shift.
    const std::int64_t e = edge_at_centre(t, i, block_x, block_y) >> kSubpixelBits;
    const std::int64_t ax0 = std::int64_t{t.a[i]} * in.x_begin,
                       ax1 = std::int64_t{t.a[i]} * (in.x_end - 1);
    const std::int64_t by0 = std::int64_t{t.b[i]} * in.y_begin,
                       by1 = std::int64_t{t.b[i]} * (in.y_end - 1);
    const std::int64_t c00 = e + ax0 + by0, c10 = e + ax1 + by0, c01 = e + ax0 + by1,
                       c11 = e + ax1 + by1;
    if ((c00 | c10 | c01 | c11) >= 0) {  // inside at every corner: no test needed
      in.e[i] = in.a[i] = in.b[i] = 0;
      continue;
    }
    if ((c00 & c10 & c01 & c11) < 0) return EdgeCover::outside;  // outside at every corner
    in.e[i] = static_cast<std::int32_t>(e);
    in.a[i] = t.a[i];
    in.b[i] = t.b[i];
    cover = EdgeCover::crossed;
  }
  return cover;
}

// The triangle's depths over the box [x0, x1] x [y0, y1] of the tile (depth_range_over), or none
// when it lies behind everything drawn there (the blocks' depth bounds, tile.block_max_depth): a
// far layer drawn after a near one is done without a block's edge tests. NaN goes on.
inline std::optional<DepthRange> depths_in_front(const TileContext& tile, const SetupTriangle& t,
                                                 int x0, int y0, int x1, int y1) {
  float farthest_drawn = 0.0f;
  for (int by = (y0 - tile.y0) / kBlockSize; by <= (y1 - tile.y0) / kBlockSize; ++by) {
    for (int bx = (x0 - tile.x0) / kBlockSize; bx <= (x1 - tile.x0) / kBlockSize; ++bx) {
      farthest_drawn = std::max(farthest_drawn, tile.block_max_depth[by * tile.blocks_x + bx]);
    }
  }
  const DepthRange box_depth = depth_range_over(t, x0, y0, x1, y1);
  if (box_depth.nearest >= farthest_drawn) return std::nullopt;
  return box_depth;
}

// The 8x8 blocks of the box [x0, x1] x [y0, y1] (frame pixels, inclusive) that triangle t may
// change: not hidden by a later triangle (tile.block_starts), not outside an edge, and, with
// kDepthTest, not wholly behind the block's depth bound. For each, `in` holds the block's
// pixel ranges, edge values (classify_edges), first pixel centre and depths, and
// visit(block_x, block_y, edges, max_depth) runs, max_depth being the block's bound.
// box_depth: t's depths over the box (depths_in_front; NaN farthest: each block is tested).
template <bool kDepthTest, class Visit>
void for_each_block(TileContext& tile, const SetupTriangle& t, int x0, int y0, int x1, int y1,
                    const DepthRange& box_depth, BlockInput& in, Visit&& visit) {
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
      const EdgeCover edges = classify_edges(t, block_x, block_y, in);
      if (edges == EdgeCover::outside) continue;
      in.px0 = static_cast<float>(block_x) + 0.5f;
      in.py0 = static_cast<float>(block_y) + 0.5f;
      float& max_depth = tile.block_max_depth[by * tile.blocks_x + bx];
      // A block's depths lie within the box's (exact bounds, depth_range_over), so where the
      // triangle's farthest is in front of the block's bound, the test below cannot reject the
      // block and is not computed: every block of a first layer.
      if (kDepthTest && !(box_depth.farthest < max_depth)) {
        const float nearest = depth_range_over(t, block_x + in.x_begin, block_y + in.y_begin,
                                               block_x + in.x_end - 1, block_y + in.y_end - 1)
                                  .nearest;
        if (nearest >= max_depth) continue;  // every pixel fails "less"; NaN goes on
      }
      in.depth = tile.depth + static_cast<std::ptrdiff_t>(block_y - tile.y0) * tile.stride +
                 (block_x - tile.x0);
      visit(block_x, block_y, edges, max_depth);
    }
  }
}

// After a triangle wrote `written` distinct pixels of the block: where that is every pixel of
// the block (in the tile), their largest depth bounds the block. That is the triangle's farthest
// over the block's corners (depth_range_over: the same arithmetic as cover_block's depths,
// monotonic in x and y), four evaluations instead of a search of all 64.
inline void lower_block_bound(const TileContext& tile, const SetupTriangle& t, int block_x,
                              int block_y, int written, float& max_depth) {
  const int width = std::min(kBlockSize, tile.x1 - block_x);
  const int height = std::min(kBlockSize, tile.y1 - block_y);
  if (written == width * height) {
    const float farthest =
        depth_range_over(t, block_x, block_y, block_x + width - 1, block_y + height - 1).farthest;
    max_depth = std::min(max_depth, farthest);
  }
}

// Rasterizes one triangle into the tile; a template over the shading model and the alpha
// mode so that the per-pixel loop is specialised once per draw state (record/pipeline_table.cpp
// builds the table). Depth-only draws in one-sample tiles take raster_depth_only
// (depth_only.hpp). Small triangles of draws whose pixels may wait join the tile's waiting pixels
// (small_triangles.hpp); other small triangles, after what waits is written, take
// raster_small_triangle; the others, likewise after it, are walked in 8x8 blocks:
//   1. blocks every edge keeps out are skipped, and edges that cover a block are not tested;
//   2. blocks whose nearest triangle depth is behind everything drawn there are skipped
//      (tile.block_max_depth, a per-block bound on the depth buffer: hierarchical depth);
//   3. cover_block finds the covered pixels that pass the depth test, with their depth and
//      varyings, SIMD across a block row;
//   4. those pixels join the triangle's others waiting to be shaded, up to a batch, then are
//      shaded and written (PixelWriter::shade): the material's maps sampled and models with a
//      batch form (fragment_batch) evaluated for all of them at once with SIMD, other models
//      one pixel at a time; whole covered blocks of opaque batch-shaded draws go straight into
//      the tile (shade_full_block).
template <class Shading, AlphaMode kAlpha = AlphaMode::opaque>
void raster_triangle(TileContext& tile, const SetupTriangle& t) {
  if constexpr (depth_only<Shading>()) {
    static_assert(kAlpha == AlphaMode::opaque && depth_tested<Shading>(),
                  "depth alone is written by opaque, depth-tested draws");
    if (tile.samples == 1) {
      raster_depth_only(tile, t);
      return;
    }
  }
  if (tile.samples > 1) {  // multisampled tiles (msaa.hpp; their small triangles wait too)
    raster_triangle_msaa<Shading, kAlpha>(tile, t);
    return;
  }
  const int x0 = std::max(t.min_x, tile.x0), x1 = std::min(t.max_x, tile.x1 - 1);
  const int y0 = std::max(t.min_y, tile.y0), y1 = std::min(t.max_y, tile.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  const int box = (x1 - x0 + 1) * (y1 - y0 + 1);
  if constexpr (PixelWriter<Shading, kAlpha>::kWaits) {
    if (box_may_wait(x1 - x0 + 1, y1 - y0 + 1)) {
      add_waiting<Shading, kAlpha>(tile, t, x0, y0, x1, y1);
      return;
    }
  }
  flush_waiting(tile);  // this triangle is drawn after them
  PixelWriter<Shading, kAlpha> out(tile, t);
  if (box <= kSmallTrianglePixels) {
    raster_small_triangle(tile, t, x0, y0, x1, y1, out);
    tile.pixels_shaded += out.shaded;
    return;
  }
  constexpr bool kDepthTest = depth_tested<Shading>();
  // The triangle's depths over its whole box (NaN: unknown, each block is tested).
  DepthRange box_depth{0.0f, std::numeric_limits<float>::quiet_NaN()};
  if constexpr (kDepthTest) {
    const std::optional<DepthRange> in_front = depths_in_front(tile, t, x0, y0, x1, y1);
    if (!in_front) return;
    box_depth = *in_front;
  }
  // Writes that leave every pixel of a block at a depth we know: the block's bound can drop.
  constexpr bool kTightensBound =
      PixelWriter<Shading, kAlpha>::kDepthWrite && kAlpha == AlphaMode::opaque;
  BlockInput in;
  in.triangle = &t;
  in.varying_planes = out.fragment.planes;
  in.varyings = Shading::kVaryings;
  in.depth_test = kDepthTest;
  in.depth_stride = tile.stride;
  alignas(64) BlockFragments block;
  PackedPixels pixels;
  // A block's pixels join those waiting in `pixels` for the next shade() while they end at most
  // here, so that interpolating them after the others, in whole vectors of up to 8, stays
  // within the arrays; else those are shaded first and the block's start the next batch.
  constexpr int kPendingPixels = PackedPixels::kCapacity - 7;
  static_assert(PackedPixels::kCapacity + kBlockPixels <= std::size(PackedPixels{}.x),
                "a block's positions are packed after a whole batch before they move up");
  const auto draw_block = [&](int block_x, int block_y, EdgeCover edges, float& max_depth) {
    // Batches take a block's pixels packed, and interpolate_pixels gives the packed ones their w
    // and varyings (the same values), cheaper than copying those one by one from cover_block's
    // rows. cover_block interpolates only where the block is likely whole, for shade_full_block:
    // every edge inside, and the triangle in front of the block's depth bound (exactly whole then
    // in a first layer).
    const bool all_inside = edges == EdgeCover::inside && in.x_begin == 0 &&
                            in.x_end == kBlockSize && in.y_begin == 0 && in.y_end == kBlockSize;
    const bool likely_whole = all_inside && (!kDepthTest || box_depth.farthest < max_depth);
    in.interpolate = !out.batches() || (likely_whole && out.full_blocks());
    in.covers_block = all_inside;
    tile.kernels.cover_block(in, block);
    if (block.mask == 0) return;
    int written = 0;
    if (block.mask == ~std::uint64_t{0} && out.full_blocks() && in.interpolate) {
      out.shade_full_block(block, block_x, block_y);
      float* depth = tile.depth + tile_index(tile, block_x, block_y);
      for (int row = 0; row < kBlockSize; ++row) {
        std::memcpy(depth + static_cast<std::ptrdiff_t>(row) * tile.stride,
                    block.z + row * kBlockSize, sizeof(float) * kBlockSize);
      }
      written = kBlockPixels;
    } else if (out.batches()) {
      // The block's pixels join those of the triangle's earlier blocks, shaded together when
      // the next block's might not fit (or at the end): one batch of many pixels instead of a
      // batch per block, a few pixels each along the edges. The triangle covers each pixel
      // once, so the order of its writes does not matter.
      int first = pixels.count, end = first;
      for (std::uint64_t m = block.mask; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        pixels.x[end] = static_cast<std::int16_t>(block_x + i % kBlockSize);
        pixels.y[end] = static_cast<std::int16_t>(block_y + i / kBlockSize);
        ++end;
      }
      const int covered = end - first;
      if (end > kPendingPixels && first > 0) {  // shade those before, then move these up
        std::int16_t x[kBlockPixels], y[kBlockPixels];
        std::copy_n(pixels.x + first, covered, x);
        std::copy_n(pixels.y + first, covered, y);
        out.shade(pixels);
        std::copy_n(x, covered, pixels.x);
        std::copy_n(y, covered, pixels.y);
        first = 0;
      }
      pixels.count = first + covered;
      pixels.pad_positions();  // interpolate_pixels reads whole vectors of positions
      tile.kernels.interpolate_pixels(t, out.fragment.planes, Shading::kVaryings, first, covered,
                                      pixels.x, pixels.y, pixels.z, pixels.w, pixels.v);
      // Opaque draws (the only ones whose bound tightens) write every pixel they shade.
      written = covered;
    } else if constexpr (!batch_shaded<Shading>()) {  // batch models always batch
      for (std::uint64_t m = block.mask; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        out.fragment.w = block.w[i];
        for (int k = 0; k < Shading::kVaryings; ++k) out.fragment.v[k] = block.v[k][i];
        written += out.write(block_x + i % kBlockSize, block_y + i / kBlockSize, block.z[i]);
      }
    }
    if constexpr (kTightensBound) {
      lower_block_bound(tile, t, block_x, block_y, written, max_depth);
    }
  };
  for_each_block<kDepthTest>(tile, t, x0, y0, x1, y1, box_depth, in, draw_block);
  if (pixels.count > 0) out.shade(pixels);
  tile.pixels_shaded += out.shaded;
}

// Rasterizes one segment into the tile (line.cpp).
void raster_line(TileContext& tile, const SetupLine& line);

// Rasterizes one point into the tile (point.cpp).
void raster_point(TileContext& tile, const SetupPoint& point);

}  // namespace facet::pipeline
