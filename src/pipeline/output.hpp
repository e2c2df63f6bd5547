// Stage: output. Clears a tile's local buffers (lazily: the framebuffer is never read) and
// resolves the finished tile into the framebuffer once, converting to the target format.
#pragma once

#include <glm/vec4.hpp>

#include "facet/framebuffer.hpp"
#include "pipeline/raster.hpp"

namespace facet::pipeline {

void clear_tile(TileContext& tile, const glm::vec4& color);
void resolve_tile(const TileContext& tile, Framebuffer& target);
// A tile with an empty bin is written straight from the clear values.
void resolve_cleared_tile(const TileContext& tile, const glm::vec4& color, Framebuffer& target);

}  // namespace facet::pipeline
