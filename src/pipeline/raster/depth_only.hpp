// Stage: raster, for draws that write depth alone: the shadow passes' casters
// (shading::DepthOnlyShading), whose color nothing reads. raster_triangle hands their triangles
// here in one-sample tiles. No varyings, no shading and no color: a small triangle's box, and
// each block of a larger one's, is searched in SIMD rows that write the depths they find at once
// (write_box_depths). The depths are those the shaded paths write (the same arithmetic), in the
// same order, so a depth map is the same bit for bit.
#pragma once

#include "pipeline/frame.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {

// Rasterizes triangle t into the one-sample tile's depth buffer: the covered pixels in front of
// it take t's depth. They count as the tile's pixels shaded (FrameStats::pixels_shaded: the
// pixels a pass wrote).
void raster_depth_only(TileContext& tile, const SetupTriangle& t);

}  // namespace facet::pipeline
