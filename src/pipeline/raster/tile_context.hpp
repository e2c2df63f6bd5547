// Stage: raster + shade, the tile being rendered (TileContext): its own color and depth buffers,
// written by raster.hpp's loops and resolved by output.cpp, and how a pixel's samples are
// stored under MSAA.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>

#include "pipeline/frame.hpp"
#include "pipeline/raster/block_raster.hpp"
#include "pipeline/setup/sample_positions.hpp"

namespace facet::pipeline {

// Largest tile edge the renderer accepts (RenderSettings::tile_size).
inline constexpr int kMaxTileSize = 128;
inline constexpr int kMaxTileBlocks = (kMaxTileSize / kBlockSize) * (kMaxTileSize / kBlockSize);

struct WaitingPixels;

// One tile being rendered: owned by one task for the whole frame, so nothing here is shared.
struct TileContext {
  const Frame* frame = nullptr;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixel rectangle [x0, x1) x [y0, y1)
  int stride = 0;                      // pixels per row of the tile buffers
  glm::vec4* color = nullptr;          // linear RGBA
  // Or, in display-referred frames of one sample into an 8-bit target (frame_run.cpp's
  // display_referred_frame), whose colors the resolve would only round, each pixel's codes: its
  // four bytes RGBA as the target stores them, which the resolve copies; then `color` is not
  // used. Null otherwise.
  std::uint32_t* codes = nullptr;
  float* depth = nullptr;  // kDepthSlack more floats readable after the last row's
  // Per 8x8 block (row-major, blocks_x per row): no depth in the block is larger. Starts at the
  // clear depth; lowered when a triangle writes a whole block (raster_triangle).
  float* block_max_depth = nullptr;
  int blocks_x = 0;
  // Per block, the index of the first triangle that can change it, counted from the first
  // bin entry drawn (occlusion.hpp's first_visible_entries_per_block), or null: every one can.
  // `entry` is the index of the triangle being drawn, counted the same way.
  const std::uint32_t* block_starts = nullptr;
  std::uint32_t entry = 0;
  std::uint64_t pixels_shaded = 0;
  // Pixels of small triangles waiting to be shaded together (WaitingPixels): the tile task's
  // own (render_tile.cpp sets it before the first triangle).
  WaitingPixels* waiting = nullptr;
  RasterKernels kernels{};  // the frame's (pipeline/kernels.hpp), set with the tile
  // MSAA (raster/msaa.hpp): sample s of pixel i has depth[s * sample_plane + i] (planes: the
  // searches test a box row of one sample at a time) and color sample_color(tile, i, s): sample
  // 0's is color[i], the one the one-sample paths use, and the others' follow one another, those
  // of pixel i from sample_colors[i * (samples - 1)] (a split pixel's samples are written and
  // averaged together). While split[i] is 0, every sample of pixel i has color[i]'s color (the
  // others' are stale): a write that covers all samples costs one color, and only edge pixels
  // hold several.
  int samples = 1;
  std::ptrdiff_t sample_plane = 0;
  glm::vec4* sample_colors = nullptr;
  std::uint8_t* split = nullptr;
  // Per pixel, the samples the triangle being drawn covers there that pass the depth test
  // (msaa.hpp sets it before shading the pixel); and that triangle's depth at each sample
  // minus its depth at the pixel centre.
  std::uint16_t* sample_mask = nullptr;
  float sample_z[kMaxSamples] = {};
};

// A display value's codes as a tile of codes holds them (TileContext::codes): the frame's
// 8-bit rounding kernel's (round_unorm8_row), as the models' batch forms round them.
std::uint32_t display_codes(const Kernels& kernels, const glm::vec4& value);

// Where frame pixel (x, y) is in the tile's buffers (plane 0).
inline std::ptrdiff_t tile_index(const TileContext& tile, int x, int y) {
  return static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride + (x - tile.x0);
}

// MSAA: the color of sample s of tile pixel i (TileContext::sample_colors).
inline glm::vec4& sample_color(const TileContext& tile, std::ptrdiff_t i, int s) {
  return s == 0 ? tile.color[i] : tile.sample_colors[i * (tile.samples - 1) + (s - 1)];
}

// Alpha to coverage for cut-out (alpha-mask) draws under MSAA: the samples a pixel of this alpha
// keeps. Alpha is mapped so that the cutoff keeps half of them, 1 all and 0 none (linearly on
// each side: the cut-out's edge is where a one-sample render puts it, softened across the
// samples), and that many samples are kept, the first ones of the pattern. A fixed subset, not a
// dither: the image stays the same for every tile and thread.
inline unsigned alpha_to_coverage(float alpha, float cutoff, int samples) {
  float kept;
  if (!(alpha == alpha)) return 0u;  // NaN: discarded, as the one-sample test does
  if (alpha >= cutoff) {
    kept = cutoff >= 1.0f ? 1.0f : 0.5f + 0.5f * (alpha - cutoff) / (1.0f - cutoff);
  } else {
    kept = cutoff <= 0.0f ? 0.0f : 0.5f * alpha / cutoff;
  }
  const float count = std::clamp(kept, 0.0f, 1.0f) * static_cast<float>(samples) + 0.5f;
  const int n = static_cast<int>(count);  // round half up, 0 .. samples
  return n >= 32 ? ~0u : (1u << n) - 1u;
}

// MSAA: gives each sample of pixel i its own copy of the pixel's color, before a write that
// leaves the samples different.
inline void split_pixel(TileContext& tile, std::ptrdiff_t i) {
  if (tile.split[i]) return;
  for (int s = 1; s < tile.samples; ++s) sample_color(tile, i, s) = tile.color[i];
  tile.split[i] = 1;
}

}  // namespace facet::pipeline
