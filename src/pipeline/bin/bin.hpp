// Stage: binning. Reads the set-up primitives in submission order (the geometry chunks'
// sequences) and appends each to the bin of every tile it may cover; raster/ (render_tile.cpp,
// line.cpp, point.cpp) read the bins.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Enough primitives per parallel run that counting them outweighs a run's per-tile counters;
// at most this many runs (their counters are runs x tiles).
inline constexpr std::size_t kPrimitivesPerBinningRun = 16384;
inline constexpr std::size_t kMaxBinningRuns = 16;

void bin_primitives(Frame& frame, int workers);

// SequenceEntry::tiles for a box of several tiles (binning_entry: 0 for triangles whose box
// holds a whole tile, and boxes of more than kMaskedTiles, whose tiles binning tests itself): for a
// triangle (not null: its edge functions must be final), which tiles it may touch; a line may touch
// every tile of its box, and a point does.
std::uint32_t binning_tile_mask(const Frame& frame, const SetupTriangle* triangle,
                                const SequenceEntry& e);

// Whether the pixel box [min_x, max_x] x [min_y, max_y] (inside the frame) holds a whole tile
// (a partial one at the frame's right or bottom edge too). Tile sizes are powers of two.
inline bool box_holds_a_tile(const Frame& frame, int min_x, int min_y, int max_x, int max_y) {
  const int ts = frame.tile_size;
  // Along one axis: the first tile starting in the box ends in it.
  auto holds = [ts](int lo, int hi, int size) {
    const int start = (lo + ts - 1) & ~(ts - 1);
    return start < size && std::min(start + ts, size) - 1 <= hi;
  };
  return holds(min_x, max_x, frame.width) && holds(min_y, max_y, frame.height);
}

// The sequence entry of primitive `index` with the given pixel bounding box (inclusive, inside
// the frame). Inline: most triangles lie in one tile, and setup calls this for each.
inline SequenceEntry binning_entry(const Frame& frame, std::uint32_t index,
                                   const SetupTriangle* triangle, int min_x, int min_y, int max_x,
                                   int max_y) {
  // Tile sizes are powers of two (Renderer checks) and boxes are non-negative: shift, not divide.
  const int shift = std::countr_zero(static_cast<unsigned>(frame.tile_size));
  SequenceEntry e;
  e.index = index;
  e.tile_x0 = static_cast<std::uint16_t>(min_x >> shift);
  e.tile_y0 = static_cast<std::uint16_t>(min_y >> shift);
  e.tile_x1 = static_cast<std::uint16_t>(max_x >> shift);
  e.tile_y1 = static_cast<std::uint16_t>(max_y >> shift);
  const bool one_tile = e.tile_x0 == e.tile_x1 && e.tile_y0 == e.tile_y1;
  if (triangle != nullptr && box_holds_a_tile(frame, min_x, min_y, max_x, max_y)) {
    e.tiles = 0;  // binning tests its tiles, and notes those it may hide
  } else {
    e.tiles = one_tile ? 1u : binning_tile_mask(frame, triangle, e);
  }
  return e;
}

// True if the triangle may cover a pixel centre of the rectangle [x0, x1) x [y0, y1):
// the edge functions' maxima over the rectangle's centres are all non-negative. With reach
// (fixed point), a point up to that far from a centre along each axis (MSAA samples:
// kSampleReach).
bool triangle_may_touch(const SetupTriangle& t, int x0, int y0, int x1, int y1,
                        std::int32_t reach = 0);

// True if the triangle covers every pixel centre of [x0, x1) x [y0, y1): the edge functions'
// minima over the rectangle's centres are all non-negative (and so is its bounding box). With
// reach, every point up to that far from a centre along each axis (MSAA samples: kSampleReach).
bool triangle_covers(const SetupTriangle& t, int x0, int y0, int x1, int y1,
                     std::int32_t reach = 0);

}  // namespace facet::pipeline
