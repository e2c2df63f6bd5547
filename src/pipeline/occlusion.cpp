// Stage: raster, occlusion of whole bins (see occlusion.hpp).
#include "pipeline/occlusion.hpp"

#include <algorithm>
#include <limits>

#include "pipeline/bin.hpp"
#include "pipeline/setup.hpp"

namespace facet::pipeline {
namespace {

// Whether entry could hide the tile: an occluding draw's triangle whose bounding box holds the
// tile (a cheap look before the exact tests).
bool may_hide(const Frame& frame, std::uint32_t entry, int x0, int y0, int x1, int y1) {
  if (entry & kLineBit) return false;
  const SetupTriangle& t = frame.triangles[entry];
  return t.min_x <= x0 && t.min_y <= y0 && t.max_x >= x1 - 1 && t.max_y >= y1 - 1 &&
         frame.draws[t.draw].pipeline.occludes;
}

}  // namespace

std::size_t first_visible_entry(const Frame& frame, const std::uint32_t* bin, std::size_t count,
                                int x0, int y0, int x1, int y1) {
  // Most tiles of detailed models hold no candidate at all: settle that first, cheaply.
  std::size_t last_candidate = 0;
  for (std::size_t i = count; i-- > 1;) {
    if (may_hide(frame, bin[i], x0, y0, x1, y1)) {
      last_candidate = i;
      break;
    }
  }
  if (last_candidate == 0) return 0;
  std::size_t first = 0;
  // The nearest depth any entry so far can write in the tile.
  float nearest_so_far = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i <= last_candidate; ++i) {
    if (bin[i] & kLineBit) break;  // lines are not hidden (nor do they hide)
    const SetupTriangle& t = frame.triangles[bin[i]];
    const DrawPipeline& pipeline = frame.draws[t.draw].pipeline;
    if (!pipeline.depth_tested) break;  // it would show through whatever is drawn later
    const DepthRange range = depth_range_over(t, std::max(t.min_x, x0), std::max(t.min_y, y0),
                                              std::min(t.max_x, x1 - 1), std::min(t.max_y, y1 - 1));
    if (!(range.nearest == range.nearest)) break;  // NaN: no bound
    if (pipeline.occludes && i > first && range.farthest < nearest_so_far &&
        triangle_covers(t, x0, y0, x1, y1)) {
      // In a covered tile the bounding box clipped to it is the tile, so range is over it.
      first = i;
    }
    nearest_so_far = std::min(nearest_so_far, range.nearest);
  }
  return first;
}

}  // namespace facet::pipeline
