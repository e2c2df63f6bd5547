// Stage: binning (see bin.hpp).
#include "pipeline/bin/bin.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>

#include "core/parallel.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "pipeline/setup/sample_positions.hpp"

namespace facet::pipeline {

namespace {

// The smallest (or, with largest, the largest) value of edge i over the pixel centres of
// [x0, x1) x [y0, y1): E is linear, so it is at the corner its gradient points away from
// (or to).
std::int64_t edge_extreme(const SetupTriangle& t, int i, int x0, int y0, int x1, int y1,
                          bool largest) {
  const std::int64_t left = pixel_centre(x0), right = pixel_centre(x1 - 1);
  const std::int64_t top = pixel_centre(y0), bottom = pixel_centre(y1 - 1);
  const std::int64_t x = (t.a[i] >= 0) == largest ? right : left;
  const std::int64_t y = (t.b[i] >= 0) == largest ? bottom : top;
  return std::int64_t{t.a[i]} * x + std::int64_t{t.b[i]} * y + t.c[i];
}

}  // namespace

bool triangle_may_touch(const SetupTriangle& t, int x0, int y0, int x1, int y1,
                        std::int32_t reach) {
  for (int i = 0; i < 3; ++i) {
    // A point within `reach` of a centre along each axis adds at most (|a| + |b|) * reach.
    const std::int64_t slack =
        (std::abs(std::int64_t{t.a[i]}) + std::abs(std::int64_t{t.b[i]})) * std::int64_t{reach};
    if (edge_extreme(t, i, x0, y0, x1, y1, true) + slack < 0) return false;
  }
  return true;
}

bool triangle_covers(const SetupTriangle& t, int x0, int y0, int x1, int y1, std::int32_t reach) {
  if (t.min_x > x0 || t.min_y > y0 || t.max_x < x1 - 1 || t.max_y < y1 - 1) return false;
  for (int i = 0; i < 3; ++i) {
    // As in triangle_may_touch: a point within `reach` of a centre takes at most this off.
    const std::int64_t slack =
        (std::abs(std::int64_t{t.a[i]}) + std::abs(std::int64_t{t.b[i]})) * std::int64_t{reach};
    if (edge_extreme(t, i, x0, y0, x1, y1, false) - slack < 0) return false;
  }
  return true;
}

namespace {

// Calls visit(entry) for entries [begin, end) of the chunks' sequences, concatenated in
// chunk order (submission order).
template <class Visit>
void for_each_entry(const Frame& frame, std::size_t begin, std::size_t end, Visit&& visit) {
  const GeometryChunk* chunks = frame.chunks.data();
  // The last chunk starting at or before `begin` (empty chunks share a start; any will do).
  std::size_t k =
      std::partition_point(chunks, chunks + frame.chunk_count,
                           [&](const GeometryChunk& c) { return c.sequence_at <= begin; }) -
      chunks - 1;
  for (std::size_t i = begin; i < end; ++k) {
    // The chunk's entries [j, stop): in its region of the frame's sequence, then past it.
    const GeometryChunk& chunk = chunks[k];
    const SequenceEntry* region = frame.sequence.data() + chunk.entries.begin;
    const std::size_t in_region = chunk.entries.used;
    const std::size_t stop = std::min(end - chunk.sequence_at, chunk.entry_count());
    std::size_t j = i - chunk.sequence_at;
    for (; j < std::min(stop, in_region); ++j) visit(region[j]);
    for (; j < stop; ++j) visit(chunk.more_entries[j - in_region]);
    i = chunk.sequence_at + j;
  }
}

// True if triangle t may cover a pixel of tile (tx, ty).
bool may_touch_tile(const Frame& frame, const SetupTriangle& t, int tx, int ty) {
  const int ts = frame.tile_size;
  return triangle_may_touch(t, tx * ts, ty * ts, std::min((tx + 1) * ts, frame.width),
                            std::min((ty + 1) * ts, frame.height), sample_reach(frame.samples));
}

// Calls visit(tile, entry, hides) for every tile each primitive of entries [begin, end) may
// cover, in submission order; hides: the entry may hide the whole tile (Frame::bin_may_hide).
template <class Visit>
void for_each_binning(const Frame& frame, std::size_t begin, std::size_t end, Visit&& visit) {
  for_each_entry(frame, begin, end, [&](const SequenceEntry& e) {
    const std::uint32_t entry = e.index;
    const int tx0 = e.tile_x0, tx1 = e.tile_x1, ty0 = e.tile_y0, ty1 = e.tile_y1;
    if (e.tiles != 0) {  // setup said which tiles
      // Walked row by row, the bit index counting along: no division per entry.
      std::uint32_t bit = 1;
      for (int ty = ty0; ty <= ty1; ++ty) {
        for (int tx = tx0; tx <= tx1; ++tx, bit <<= 1) {
          if (e.tiles & bit) visit(static_cast<std::size_t>(ty) * frame.tiles_x + tx, entry, false);
        }
      }
      return;
    }
    // Large triangles skip the tiles their bounding box touches but their edges exclude.
    const SetupTriangle* tri = is_triangle_entry(entry) ? &frame.triangles[entry] : nullptr;
    const bool occludes = tri && frame.draws[tri->draw].pipeline.occludes;
    const int ts = frame.tile_size;
    for (int ty = ty0; ty <= ty1; ++ty) {
      for (int tx = tx0; tx <= tx1; ++tx) {
        if (tri && !may_touch_tile(frame, *tri, tx, ty)) continue;
        const bool hides = occludes && tri->min_x <= tx * ts && tri->min_y <= ty * ts &&
                           tri->max_x >= std::min((tx + 1) * ts, frame.width) - 1 &&
                           tri->max_y >= std::min((ty + 1) * ts, frame.height) - 1;
        visit(static_cast<std::size_t>(ty) * frame.tiles_x + tx, entry, hides);
      }
    }
  });
}

}  // namespace

std::uint32_t binning_tile_mask(const Frame& frame, const SetupTriangle* triangle,
                                const SequenceEntry& e) {
  const int span_x = e.tile_x1 - e.tile_x0 + 1, span_y = e.tile_y1 - e.tile_y0 + 1;
  if (span_x * span_y > kMaskedTiles) return 0;  // binning tests these tiles itself
  std::uint32_t tiles = 0;
  for (int bit = 0; bit < span_x * span_y; ++bit) {
    const int tx = e.tile_x0 + bit % span_x, ty = e.tile_y0 + bit / span_x;
    if (!triangle || may_touch_tile(frame, *triangle, tx, ty)) tiles |= 1u << bit;
  }
  return tiles;
}

void bin_primitives(Frame& frame, int workers) {
  // The sequence is cut into runs binned in parallel, in two passes over one arena: count
  // (per run and tile), then fill. Within a tile the runs' entries follow each other in run
  // order, so every bin keeps submission order whatever the schedule. The arena only grows
  // when a frame needs more entries than any before (by half again, so an animated scene
  // settles after a few frames and then allocates nothing).
  const std::size_t tiles = static_cast<std::size_t>(frame.tiles_x) * frame.tiles_y;
  const std::size_t primitives = frame.primitives;
  const std::size_t runs =
      std::clamp<std::size_t>(primitives / kPrimitivesPerBinningRun, 1, kMaxBinningRuns);
  auto run_begin = [&](std::size_t run) { return primitives * run / runs; };
  frame.bin_cursors.assign(runs * tiles, 0);  // capacity kept across frames
  frame.bin_hiders.assign(runs * tiles, 0);
  parallel_tasks(static_cast<int>(runs), workers, [&](int run, int) {
    std::uint32_t* counts = frame.bin_cursors.data() + run * tiles;
    std::uint8_t* hiders = frame.bin_hiders.data() + run * tiles;
    for_each_binning(frame, run_begin(run), run_begin(run + 1),
                     [&](std::size_t tile, std::uint32_t, bool hides) {
                       ++counts[tile];
                       hiders[tile] |= hides;
                     });
  });
  // Bin starts, and each run's first slot in each bin (the cursors the fill advances).
  frame.bin_start.assign(tiles + 1, 0);
  frame.bin_may_hide.assign(tiles, 0);
  std::uint32_t total = 0;
  for (std::size_t tile = 0; tile < tiles; ++tile) {
    frame.bin_start[tile] = total;
    for (std::size_t run = 0; run < runs; ++run) {
      std::uint32_t& cursor = frame.bin_cursors[run * tiles + tile];
      const std::uint32_t count = cursor;
      cursor = total;
      total += count;
      frame.bin_may_hide[tile] |= frame.bin_hiders[run * tiles + tile];
    }
  }
  frame.bin_start[tiles] = total;
  if (frame.bin_entries.capacity() < total) frame.bin_entries.reserve(total + total / 2);
  frame.bin_entries.resize(total);
  parallel_tasks(static_cast<int>(runs), workers, [&](int run, int) {
    std::uint32_t* cursors = frame.bin_cursors.data() + run * tiles;
    for_each_binning(frame, run_begin(run), run_begin(run + 1),
                     [&](std::size_t tile, std::uint32_t entry, bool) {
                       frame.bin_entries[cursors[tile]++] = entry;
                     });
  });
}

}  // namespace facet::pipeline
