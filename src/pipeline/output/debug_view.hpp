// Debug views (RenderSettings::debug_view): what the pipeline did instead of what it shaded.
// Hooked into the frame at three points in the renderer: the draw's pipeline when it is recorded,
// the lighting and background before the frame runs, and the resolve of each tile.
#pragma once

#include <cstddef>

#include "facet/framebuffer.hpp"
#include "facet/light.hpp"
#include "facet/renderer.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/output/output.hpp"
#include "pipeline/raster/raster.hpp"

namespace facet::pipeline {

// The pipeline a draw runs under the debug view: the overdraw counter for `overdraw`,
// otherwise the draw's own. (Under `overdraw`, line primitives are not drawn: the heat map
// counts triangles.)
const DrawPipeline& debug_pipeline(DebugView view, const DrawPipeline& own);

// The overdraw counter accumulates from zero: no fog, no environment, a black clear.
void prepare_debug_frame(DebugView view, Lighting& lighting, Background& background);

// Resolves a finished tile under a debug view (not `none`); bin_size is how many primitives
// were binned into it.
void resolve_debug_tile(const TileContext& tile, DebugView view, std::size_t bin_size, float scale,
                        Framebuffer& target);

}  // namespace facet::pipeline
