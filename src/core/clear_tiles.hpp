// ClearTiles: which tiles of a target still hold the clear values alone, cleared by an earlier
// frame and not drawn since. A frame leaves such a tile as it is where nothing is drawn again
// (pipeline/raster/render_tile.cpp), and keeps the record current. Shadow maps keep one per map;
// a RenderTexture one per buffer, traded with them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

namespace facet {

struct ClearTiles {
  int tile_size = 0;
  // What the cleared tiles' color was made of: the clear color, at this exposure.
  glm::vec4 color{0.0f};
  float exposure = 0.0f;
  std::vector<std::uint8_t> clear;  // per tile, in the frame's order

  // For a frame of `count` tiles of `size` pixels a side, clearing to `clear_color` at
  // `clear_exposure`: a record of other tiles or other clear values is forgotten.
  void fit(int size, std::size_t count, const glm::vec4& clear_color, float clear_exposure) {
    if (size == tile_size && count == clear.size() && clear_color == color &&
        clear_exposure == exposure) {
      return;
    }
    tile_size = size, color = clear_color, exposure = clear_exposure;
    clear.assign(count, 0);
  }
  // After the target was written by other means, or made again.
  void forget() { clear.assign(clear.size(), 0); }
};

}  // namespace facet
