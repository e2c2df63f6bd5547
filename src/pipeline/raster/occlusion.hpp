// Stage: raster, before a tile's first triangle. Reads the tile's bin (bin.cpp) and finds the
// last triangle that hides everything binned before it (in the tile, and in small bins in each
// 8x8 block), so raster.hpp never shades what would be overdrawn: a full-screen opaque surface
// drawn last costs one layer, not all of them.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Index into bin[0 .. count) of an entry before which no entry can change the tile's pixels
// (0 if it finds none; it may miss a hider to save reading every entry). Entry i hides all
// before it when
//   * its draw is opaque, depth-tested and depth-writing (DrawPipeline::occludes),
//   * it covers every pixel centre of the tile (its three edges are >= 0 at the four corners),
//   * its farthest depth in the tile is nearer than the nearest depth any earlier entry can
//     have there (exact bounds: depth_range_over),
// and every earlier entry is a depth-tested triangle. Then each tile pixel ends with entry i's
// color and depth whether the earlier entries were drawn or not: i passes "less" against the
// clear depth exactly where it passes against anything they wrote. Under MSAA the same holds
// sample by sample, with "every pixel centre" read as "every sample" and the depth bounds
// widened to the samples (occlusion.cpp).
std::size_t first_visible_entry(const Frame& frame, const std::uint32_t* bin, std::size_t count,
                                int x0, int y0, int x1, int y1);

// Whether entry writes every pixel of the freshly cleared tile [x0, x1) x [y0, y1): an
// occluding draw's triangle (as above) that covers every pixel centre, nearer than the clear
// depth (output.hpp's kClearDepth) everywhere there. Drawn first, it leaves nothing of the
// clear color to see, so render_tile does not clear the color.
bool hides_clear(const Frame& frame, std::uint32_t entry, int x0, int y0, int x1, int y1);

// Whether a bin of `entries` in a tile of `tile_pixels` also looks for hidden work per 8x8
// block: when it holds at most one entry per kPixelsPerBlockOcclusionEntry pixels of the tile (16
// in a 64 x 64 tile). The look costs a depth bound per entry and block the entry touches, which
// pays when a few large triangles overdraw each other (where no single one covers the tile:
// along the seam of a full-screen quad's two triangles), not in bins of triangles of a few
// blocks, which seldom hide one another block by block. Tiles of 16 pixels never look, tiles of
// 32 only in bins of at most 4 entries: small tiles are more often hidden whole
// (first_visible_entry).
inline constexpr std::size_t kPixelsPerBlockOcclusionEntry = 256;
inline bool looks_per_block(std::size_t entries, int tile_pixels) {
  return entries * kPixelsPerBlockOcclusionEntry <= static_cast<std::size_t>(tile_pixels);
}

// The same per 8x8 block of the tile [x0, x1) x [y0, y1) (blocks_x blocks per row, aligned to
// the tile's origin): starts[b] = index into bin[0 .. count) of the first entry that can change
// block b's pixels, by the conditions above over the block instead of the tile. raster.hpp
// skips block b of every triangle before starts[b]. False, with starts unset, when no block can
// start later than the first entry.
bool first_visible_entries_per_block(const Frame& frame, const std::uint32_t* bin,
                                     std::size_t count, int x0, int y0, int x1, int y1,
                                     int blocks_x, std::uint32_t* starts);

}  // namespace facet::pipeline
