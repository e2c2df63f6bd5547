// Stage: raster, occlusion of whole bins (see occlusion.hpp).
#include "pipeline/raster/occlusion.hpp"

#include <algorithm>
#include <limits>

#include "pipeline/bin/bin.hpp"
#include "pipeline/output/output.hpp"
#include "pipeline/raster/pixel_writer.hpp"
#include "pipeline/raster/sample_steps.hpp"
#include "pipeline/setup/sample_positions.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {
namespace {

// An entry an occlusion scan may look past: a triangle of a depth-tested draw. Scans stop at
// anything else, a line or point (they are not hidden, nor do they hide) or a draw without the
// depth test (it would show through whatever is drawn later): then `triangle` is null.
struct ScanEntry {
  const SetupTriangle* triangle = nullptr;
  bool occludes = false;  // its draw writes depth and is opaque (DrawPipeline::occludes)
};
ScanEntry scan_entry(const Frame& frame, std::uint32_t entry) {
  if (!is_triangle_entry(entry)) return {};
  const SetupTriangle& t = frame.triangles[entry];
  const DrawPipeline& pipeline = frame.draws[t.draw].pipeline;
  if (!pipeline.depth_tested) return {};
  return {&t, pipeline.occludes};
}

// Under MSAA the tests reason about every sample instead of every pixel centre: a sample's depth
// is its pixel centre's plus the triangle's step for it, rounded once (SampleSteps), so the
// steps' extremes added to the centres' bounds bound the samples' depths (rounding is
// monotonic); and covering every point within half a pixel of each centre (kSampleReach) covers
// every sample. Then each sample, like each centre at one sample, ends with the hider's color and
// depth whether what it hides was drawn or not (and a pixel whose samples the hider all writes is
// left unsplit either way).

// t's depths over its pixel centres within `range` widened to its samples (none at one).
DepthRange over_samples(const Frame& frame, const SetupTriangle& t, DepthRange range) {
  if (frame.samples == 1) return range;
  float z[kMaxSamples];
  const DepthSteps steps = sample_depth_steps(t, frame.samples, z);
  return {range.nearest + steps.min, range.farthest + steps.max};  // NaN stays
}

// depth_range_over the part of t's bounding box in the rectangle [x0, x1) x [y0, y1), over its
// samples.
DepthRange depth_range_within(const Frame& frame, const SetupTriangle& t, int x0, int y0, int x1,
                              int y1) {
  return over_samples(frame, t,
                      depth_range_over(t, std::max(t.min_x, x0), std::max(t.min_y, y0),
                                       std::min(t.max_x, x1 - 1), std::min(t.max_y, y1 - 1)));
}

// triangle_covers for every sample of the rectangle's pixels.
bool covers_samples(const Frame& frame, const SetupTriangle& t, int x0, int y0, int x1, int y1) {
  return triangle_covers(t, x0, y0, x1, y1, sample_reach(frame.samples));
}

// Whether entry could hide the tile: an occluding draw's triangle whose bounding box holds the
// tile (a cheap look before the exact tests).
bool may_hide(const Frame& frame, std::uint32_t entry, int x0, int y0, int x1, int y1) {
  const ScanEntry e = scan_entry(frame, entry);
  if (!e.occludes) return false;
  const SetupTriangle& t = *e.triangle;
  return t.min_x <= x0 && t.min_y <= y0 && t.max_x >= x1 - 1 && t.max_y >= y1 - 1;
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
  // The scan reads every entry's triangle up to the last candidate, a cache miss each. Once an
  // entry lies nearer somewhere in the tile than the last candidate lies anywhere (a tree in
  // front of the ground drawn after it), the last candidate cannot hide what came before: the
  // scan stops there and keeps the best hider found so far, leaving any between to be drawn.
  const SetupTriangle& last = frame.triangles[bin[last_candidate]];
  const float last_farthest = covers_samples(frame, last, x0, y0, x1, y1)
                                  ? depth_range_within(frame, last, x0, y0, x1, y1).farthest
                                  : -std::numeric_limits<float>::infinity();  // no stop
  std::size_t first = 0;
  // The nearest depth any entry so far can write in the tile.
  float nearest_so_far = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i <= last_candidate; ++i) {
    const ScanEntry e = scan_entry(frame, bin[i]);
    if (!e.triangle) break;
    const SetupTriangle& t = *e.triangle;
    const DepthRange range = depth_range_within(frame, t, x0, y0, x1, y1);
    if (!(range.nearest == range.nearest)) break;  // NaN: no bound
    if (e.occludes && i > first && range.farthest < nearest_so_far &&
        covers_samples(frame, t, x0, y0, x1, y1)) {
      // In a covered tile the bounding box clipped to it is the tile, so range is over it.
      first = i;
    }
    nearest_so_far = std::min(nearest_so_far, range.nearest);
    if (nearest_so_far <= last_farthest) break;  // NaN farthest: never
  }
  return first;
}

bool hides_clear(const Frame& frame, std::uint32_t entry, int x0, int y0, int x1, int y1) {
  if (!may_hide(frame, entry, x0, y0, x1, y1)) return false;
  const SetupTriangle& t = frame.triangles[entry];
  return depth_range_within(frame, t, x0, y0, x1, y1).farthest < kClearDepth &&  // NaN: false
         covers_samples(frame, t, x0, y0, x1, y1);
}

namespace {

// Whether some entry of an occluding draw can be nearer somewhere in the tile than an earlier
// one: what hiding it in any block needs (its farthest depth in the block is at least its
// nearest in the tile, the earlier one's nearest in the block at most its farthest in the
// tile). Layers drawn nearest first never are: their blocks skip the look.
bool any_entry_nearer_than_one_before(const Frame& frame, const std::uint32_t* bin,
                                      std::size_t count, int x0, int y0, int x1, int y1) {
  float farthest_before = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    const ScanEntry e = scan_entry(frame, bin[i]);
    if (!e.triangle) return false;  // as below: nothing after it is looked at
    const DepthRange range = depth_range_within(frame, *e.triangle, x0, y0, x1, y1);
    if (!(range.nearest == range.nearest)) return false;  // NaN: no bound
    if (e.occludes && range.nearest < farthest_before) return true;
    farthest_before = std::max(farthest_before, range.farthest);
  }
  return false;
}

}  // namespace

bool first_visible_entries_per_block(const Frame& frame, const std::uint32_t* bin,
                                     std::size_t count, int x0, int y0, int x1, int y1,
                                     int blocks_x, std::uint32_t* starts) {
  if (!any_entry_nearer_than_one_before(frame, bin, count, x0, y0, x1, y1)) return false;
  const int blocks_y = (y1 - y0 + kBlockSize - 1) / kBlockSize;
  // Per block, the nearest depth any entry so far can write there.
  float nearest_so_far[kMaxTileBlocks];
  for (int b = 0; b < blocks_x * blocks_y; ++b) {
    starts[b] = 0;
    nearest_so_far[b] = std::numeric_limits<float>::infinity();
  }
  const std::int32_t reach = sample_reach(frame.samples);
  for (std::size_t i = 0; i < count; ++i) {
    const ScanEntry e = scan_entry(frame, bin[i]);
    if (!e.triangle) return true;
    const SetupTriangle& t = *e.triangle;
    // The triangle's box in the tile, and the blocks it overlaps.
    const int left = std::max(t.min_x, x0), right = std::min(t.max_x, x1 - 1);
    const int top = std::max(t.min_y, y0), bottom = std::min(t.max_y, y1 - 1);
    if (left > right || top > bottom) continue;
    for (int by = (top - y0) / kBlockSize; by <= (bottom - y0) / kBlockSize; ++by) {
      const int block_y0 = y0 + by * kBlockSize, block_y1 = std::min(block_y0 + kBlockSize, y1);
      for (int bx = (left - x0) / kBlockSize; bx <= (right - x0) / kBlockSize; ++bx) {
        const int block_x0 = x0 + bx * kBlockSize, block_x1 = std::min(block_x0 + kBlockSize, x1);
        // One that covers no pixel centre of the block changes nothing there. (Its box may:
        // a quad's two triangles share theirs, and each would bound the other's depth.)
        if (!triangle_may_touch(t, block_x0, block_y0, block_x1, block_y1, reach)) continue;
        const DepthRange range = over_samples(
            frame, t,
            depth_range_over(t, std::max(left, block_x0), std::max(top, block_y0),
                             std::min(right, block_x1 - 1), std::min(bottom, block_y1 - 1)));
        if (!(range.nearest == range.nearest)) return true;  // NaN: no bound
        const int b = by * blocks_x + bx;
        if (e.occludes && i > starts[b] && range.farthest < nearest_so_far[b] &&
            triangle_covers(t, block_x0, block_y0, block_x1, block_y1, reach)) {
          starts[b] = static_cast<std::uint32_t>(i);
        }
        nearest_so_far[b] = std::min(nearest_so_far[b], range.nearest);
      }
    }
  }
  return true;
}

}  // namespace facet::pipeline
