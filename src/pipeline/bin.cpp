// Stage: binning (see bin.hpp).
#include "pipeline/bin.hpp"

#include <algorithm>

#include "pipeline/fixed_point.hpp"

namespace facet::pipeline {

bool triangle_may_touch(const SetupTriangle& t, int x0, int y0, int x1, int y1) {
  std::int64_t left = pixel_centre(x0), right = pixel_centre(x1 - 1);
  std::int64_t top = pixel_centre(y0), bottom = pixel_centre(y1 - 1);
  for (int i = 0; i < 3; ++i) {
    // E is linear, so its maximum over the rectangle is at the corner its gradient points to.
    std::int64_t x = t.a[i] >= 0 ? right : left;
    std::int64_t y = t.b[i] >= 0 ? bottom : top;
    if (std::int64_t{t.a[i]} * x + std::int64_t{t.b[i]} * y + t.c[i] < 0) return false;
  }
  return true;
}

namespace {

// Calls visit(tile, entry) for every tile each primitive may cover, in submission order.
template <class Visit>
void for_each_binning(const Frame& frame, Visit&& visit) {
  const int ts = frame.tile_size;
  for (std::uint32_t entry : frame.sequence) {
    int min_x, min_y, max_x, max_y;
    const SetupTriangle* tri = nullptr;
    if (entry & kLineBit) {
      const SetupLine& l = frame.lines[entry & ~kLineBit];
      min_x = l.min_x, min_y = l.min_y, max_x = l.max_x, max_y = l.max_y;
    } else {
      tri = &frame.triangles[entry];
      min_x = tri->min_x, min_y = tri->min_y, max_x = tri->max_x, max_y = tri->max_y;
    }
    int tx0 = min_x / ts, tx1 = max_x / ts, ty0 = min_y / ts, ty1 = max_y / ts;
    bool single_tile = tx0 == tx1 && ty0 == ty1;
    for (int ty = ty0; ty <= ty1; ++ty) {
      for (int tx = tx0; tx <= tx1; ++tx) {
        // Large triangles skip the tiles their bounding box touches but their edges exclude.
        if (tri && !single_tile &&
            !triangle_may_touch(*tri, tx * ts, ty * ts, std::min((tx + 1) * ts, frame.width),
                                std::min((ty + 1) * ts, frame.height))) {
          continue;
        }
        visit(static_cast<std::size_t>(ty) * frame.tiles_x + tx, entry);
      }
    }
  }
}

}  // namespace

void bin_primitives(Frame& frame) {
  // Two passes over one arena instead of a growing vector per tile: count, then fill. The
  // arena only grows when a frame needs more entries than any before (by half again, so an
  // animated scene settles after a few frames and then allocates nothing).
  std::size_t tiles = static_cast<std::size_t>(frame.tiles_x) * frame.tiles_y;
  frame.bin_start.assign(tiles + 1, 0);
  for_each_binning(frame, [&](std::size_t tile, std::uint32_t) { ++frame.bin_start[tile + 1]; });
  for (std::size_t i = 0; i < tiles; ++i) frame.bin_start[i + 1] += frame.bin_start[i];
  std::size_t total = frame.bin_start[tiles];
  if (frame.bin_entries.capacity() < total) frame.bin_entries.reserve(total + total / 2);
  frame.bin_entries.resize(total);
  // Fill, using bin_start as the write cursors, then shift them back to the starts.
  for_each_binning(frame, [&](std::size_t tile, std::uint32_t entry) {
    frame.bin_entries[frame.bin_start[tile]++] = entry;
  });
  for (std::size_t i = tiles; i > 0; --i) frame.bin_start[i] = frame.bin_start[i - 1];
  frame.bin_start[0] = 0;
}

}  // namespace facet::pipeline
