// ClearTiles: which tiles of a depth-only target still hold the clear depth alone, cleared by an
// earlier frame and not drawn since. A frame leaves such a tile as it is where nothing is drawn
// again (pipeline/raster/render_tile.cpp), and keeps the record current. Shadow maps keep one
// per map; a depth-only RenderTexture one per buffer, traded with them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet {

struct ClearTiles {
  int tile_size = 0;
  std::vector<std::uint8_t> clear;  // per tile, in the frame's order

  // For a frame of `count` tiles of `size` pixels a side: a record of other tiles is forgotten.
  void fit(int size, std::size_t count) {
    if (size == tile_size && count == clear.size()) return;
    tile_size = size;
    clear.assign(count, 0);
  }
  // After the target was written by other means, or made again.
  void forget() { clear.assign(clear.size(), 0); }
};

}  // namespace facet
