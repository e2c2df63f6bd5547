// The islands world's textures, painted procedurally at start-up from deterministic noise (no
// image files): terrain, water, building materials, runway paint, metal and foliage.
#pragma once

#include <memory>

#include "facet/texture.hpp"

namespace facet::islands {

using TexturePtr = std::shared_ptr<const Texture>;

struct IslandTextures {
  TexturePtr grass, sand, rock;        // terrain, seen from above
  TexturePtr water, falls;             // calm water; falling water streaked along v
  TexturePtr wood, bark, brick, roof;  // planks along u; bark fibres along v
  TexturePtr runway, threshold;        // asphalt with markings, u across, v along the runway
  TexturePtr concrete, metal, foliage;
};

// Every texture is sRGB, mipmapped, and tiles seamlessly under Wrap::repeat.
IslandTextures make_island_textures();

}  // namespace facet::islands
