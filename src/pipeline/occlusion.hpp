// Stage: raster, before a tile's first triangle. Reads the tile's bin (bin.cpp) and finds the
// last triangle that hides everything binned before it, so raster.hpp never shades what would
// be overdrawn: a full-screen opaque surface drawn last costs one layer, not all of them.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Index into bin[0 .. count) of the first entry that can change the tile's pixels. Entry i
// hides all before it when
//   * its draw is opaque, depth-tested and depth-writing (DrawPipeline::occludes),
//   * it covers every pixel centre of the tile (its three edges are >= 0 at the four corners),
//   * its farthest depth in the tile is nearer than the nearest depth any earlier entry can
//     have there (exact bounds: depth_range_over),
// and every earlier entry is a depth-tested triangle. Then each tile pixel ends with entry i's
// color and depth whether the earlier entries were drawn or not: i passes "less" against the
// clear depth exactly where it passes against anything they wrote.
std::size_t first_visible_entry(const Frame& frame, const std::uint32_t* bin, std::size_t count,
                                int x0, int y0, int x1, int y1);

}  // namespace facet::pipeline
