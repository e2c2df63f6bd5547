// Stage: raster + shade under multisampling (RenderSettings::msaa > 1). raster_triangle
// (raster.hpp) hands a triangle here when the tile holds several samples a pixel
// (TileContext::samples). Coverage and depth are per sample, with the same fixed-point edge
// functions and top-left rule as one sample a pixel, evaluated at the standard sample positions
// (setup/sample_positions.hpp); the pixel is shaded once, at its centre (its varyings
// extrapolated there when the centre itself is outside), and that color goes to the samples it
// covers that pass the depth test (PixelWriter::store_samples). output.cpp averages the samples.
//
// Cost: blocks whose every sample the triangle covers, in front of every sample drawn there
// (block_samples_in_front), take the one-sample whole-block path (cover_block, shade_full_block)
// and write one color a pixel; only their depths are per sample. Every other block, and the whole
// box of a small triangle, is searched for covered samples (SIMD across box rows,
// find_box_samples): that is the work along edges. Small triangles of draws whose pixels may wait
// join the tile's waiting pixels with their samples, whose depths the search writes at once
// (small_triangles.hpp), and are shaded a batch of several triangles at a time, as at one sample;
// writing them is then writing their colors (RasterKernels::write_sample_colors).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/pixel_writer.hpp"
#include "pipeline/raster/sample_steps.hpp"
#include "pipeline/raster/small_triangles.hpp"
#include "pipeline/setup/sample_positions.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {

// How a block lies against a triangle's edges: outside some edge (nothing covered), inside all
// three (everything covered) or crossing one (raster.hpp's classify_edges, classify_samples).
enum class EdgeCover { outside, crossed, inside };

// Which samples of the pixels of [x0, x1] x [y0, y1] (frame pixels, inclusive) triangle t may
// cover: outside (none), inside (all, at every pixel) or crossed. Exact: each edge is linear, so
// its extremes over the samples are at the rectangle's corners plus the steps' extremes.
inline EdgeCover classify_samples(const SetupTriangle& t, const SampleSteps& steps, int x0, int y0,
                                  int x1, int y1) {
  EdgeCover cover = EdgeCover::inside;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t c[4] = {edge_at_centre(t, i, x0, y0), edge_at_centre(t, i, x1, y0),
                               edge_at_centre(t, i, x0, y1), edge_at_centre(t, i, x1, y1)};
    const std::int64_t lowest = *std::min_element(c, c + 4) + steps.edge_min[i];
    const std::int64_t highest = *std::max_element(c, c + 4) + steps.edge_max[i];
    if (highest < 0) return EdgeCover::outside;
    if (lowest < 0) cover = EdgeCover::crossed;
  }
  return cover;
}

// The pixels of [left, right] x [top, bottom] (frame pixels, at most PackedPixels::kCapacity):
// the samples each covers that pass the depth test go to tile.sample_mask, and the pixels with
// any are shaded and written. The search runs with SIMD across box rows, in 32 bits for
// triangles whose edge coefficients allow it (find_box_samples), in doubles for the others
// (find_box_samples_wide).
template <class Shading, AlphaMode kAlpha>
void shade_covered_samples(TileContext& tile, const SetupTriangle& t, const SampleSteps& steps,
                           PixelWriter<Shading, kAlpha>& out, PackedPixels& pixels, int left,
                           int top, int right, int bottom) {
  constexpr bool kDepthTest = depth_tested<Shading>();
  const SampleBoxSearch search =
      sample_box_search<kDepthTest>(tile, t, steps, tile.sample_z, left, top, right, bottom);
  std::uint16_t masks[PackedPixels::kCapacity + kBoxSearchSlack];
  const auto find =
      steps.fits_32_bits ? tile.kernels.find_box_samples : tile.kernels.find_box_samples_wide;
  pixels.count = find(search, pixels.x, pixels.y, masks);
  for (int n = 0; n < pixels.count; ++n) {
    tile.sample_mask[static_cast<std::ptrdiff_t>(pixels.y[n] - tile.y0) * tile.stride +
                     (pixels.x[n] - tile.x0)] = masks[n];
  }
  if (pixels.count == 0) return;
  pixels.pad(0);  // interpolate_pixels reads whole vectors of positions
  tile.kernels.interpolate_pixels(t, out.fragment.planes, Shading::kVaryings, 0, pixels.count,
                                  pixels.x, pixels.y, pixels.z, pixels.w, pixels.v);
  out.shade(pixels);
}

// Rasterizes one triangle into a multisampled tile, 8x8 blocks at a time as raster_triangle;
// a triangle whose box holds at most a block's worth of pixels in one go. Small triangles of
// draws whose pixels may wait join the tile's waiting pixels, as at one sample
// (small_triangles.hpp), with their samples.
template <class Shading, AlphaMode kAlpha>
void raster_triangle_msaa(TileContext& tile, const SetupTriangle& t) {
  const int x0 = std::max(t.min_x, tile.x0), x1 = std::min(t.max_x, tile.x1 - 1);
  const int y0 = std::max(t.min_y, tile.y0), y1 = std::min(t.max_y, tile.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  using Writer = PixelWriter<Shading, kAlpha>;
  const int samples = tile.samples;
  const std::ptrdiff_t plane = tile.sample_plane;
  float sample_z[kMaxSamples];
  const SampleSteps steps(t, samples, sample_z);
  if constexpr (Writer::kWaits) {
    if (steps.fits_32_bits && box_may_wait(x1 - x0 + 1, y1 - y0 + 1)) {
      add_waiting<Shading, kAlpha>(tile, t, x0, y0, x1, y1, &steps, sample_z);
      return;
    }
  }
  flush_waiting(tile);  // this triangle is drawn after them
  std::copy_n(sample_z, samples, tile.sample_z);
  Writer out(tile, t);
  PackedPixels pixels;
  if ((x1 - x0 + 1) * (y1 - y0 + 1) <= PackedPixels::kCapacity) {
    // Small: no block is whole, and one walk of the box costs less than classifying blocks.
    shade_covered_samples(tile, t, steps, out, pixels, x0, y0, x1, y1);
    tile.pixels_shaded += out.shaded;
    return;
  }
  constexpr bool kDepthTest = depth_tested<Shading>();
  constexpr bool kTightensBound = Writer::kDepthWrite && kAlpha == AlphaMode::opaque;
  // Whole blocks: every edge inside, nothing to test (cover_block interpolates for them).
  BlockInput whole;
  std::fill_n(whole.e, 3, 0), std::fill_n(whole.a, 3, 0), std::fill_n(whole.b, 3, 0);
  whole.x_begin = whole.y_begin = 0;
  whole.x_end = whole.y_end = kBlockSize;
  whole.covers_block = true;
  whole.triangle = &t;
  whole.varying_planes = out.fragment.planes;
  whole.varyings = Shading::kVaryings;
  whole.depth_test = false;
  whole.depth = tile.depth;
  whole.depth_stride = tile.stride;
  whole.interpolate = true;
  alignas(64) BlockFragments block;
  const int bx0 = (x0 - tile.x0) / kBlockSize, bx1 = (x1 - tile.x0) / kBlockSize;
  const int by0 = (y0 - tile.y0) / kBlockSize, by1 = (y1 - tile.y0) / kBlockSize;
  for (int by = by0; by <= by1; ++by) {
    const int block_y = tile.y0 + by * kBlockSize;
    const int top = std::max(y0, block_y), bottom = std::min(y1, block_y + kBlockSize - 1);
    for (int bx = bx0; bx <= bx1; ++bx) {
      const int block_x = tile.x0 + bx * kBlockSize;
      if (tile.block_starts != nullptr && tile.entry < tile.block_starts[by * tile.blocks_x + bx])
        continue;  // a later triangle hides this one here (occlusion.hpp)
      const int left = std::max(x0, block_x), right = std::min(x1, block_x + kBlockSize - 1);
      const EdgeCover edges = classify_samples(t, steps, left, top, right, bottom);
      if (edges == EdgeCover::outside) continue;
      float& max_depth = tile.block_max_depth[by * tile.blocks_x + bx];
      float farthest = 0.0f;
      if constexpr (kDepthTest) {
        const DepthRange range = depth_range_over(t, left, top, right, bottom);
        if (range.nearest + steps.depth.min >= max_depth) continue;  // NaN goes on (and fails)
        farthest = range.farthest + steps.depth.max;
      }
      const bool whole_block = edges == EdgeCover::inside && left == block_x && top == block_y &&
                               right - left + 1 == kBlockSize && bottom - top + 1 == kBlockSize;
      const std::ptrdiff_t first =
          static_cast<std::ptrdiff_t>(block_y - tile.y0) * tile.stride + (block_x - tile.x0);
      // Whole blocks in front of the block's depth bound are likely in front of every sample.
      // The bound limits the block's depths from above only (pixels drawn since it was lowered
      // may be nearer), so each sample is still compared.
      if (whole_block && out.full_blocks() && (!kDepthTest || farthest < max_depth)) {
        whole.px0 = static_cast<float>(block_x) + 0.5f;
        whole.py0 = static_cast<float>(block_y) + 0.5f;
        tile.kernels.cover_block(whole, block);
        if (kDepthTest &&
            !tile.kernels.block_samples_in_front(block.z, tile.sample_z, samples,
                                                 tile.depth + first, tile.stride, plane)) {
          shade_covered_samples(tile, t, steps, out, pixels, left, top, right, bottom);
          continue;
        }
        out.shade_full_block(block, block_x, block_y);
        tile.kernels.write_block_sample_depths(block.z, tile.sample_z, samples, tile.depth + first,
                                               tile.stride, plane);
        for (int row = 0; row < kBlockSize; ++row) {
          std::memset(tile.split + first + static_cast<std::ptrdiff_t>(row) * tile.stride, 0,
                      kBlockSize);
        }
        if constexpr (kTightensBound) max_depth = std::min(max_depth, farthest);
        continue;
      }
      shade_covered_samples(tile, t, steps, out, pixels, left, top, right, bottom);
    }
  }
  tile.pixels_shaded += out.shaded;
}

}  // namespace facet::pipeline
