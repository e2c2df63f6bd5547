// The geometry stage (see geometry.hpp).
#include "pipeline/geometry/geometry.hpp"

#include <unistd.h>

#include <algorithm>

#include "core/parallel.hpp"
#include "facet/error.hpp"
#include "pipeline/geometry/primitive.hpp"
#include "pipeline/geometry/primitive_sink.hpp"
#include "pipeline/geometry/vertex.hpp"

namespace facet::pipeline {
namespace {

// Primitives per task: large enough that a chunk's set-up dwarfs scheduling, small enough
// that a 70k-triangle model splits into dozens of tasks for the cores to share.
constexpr std::size_t kChunkPrimitives = 2048;

// Makes v hold at least n elements. It never shrinks, so a frame that needs fewer primitives
// than the last initializes nothing, and it grows by half again when a frame needs more than
// any before, so animated scenes settle and then allocate nothing.
template <class T, class Allocator>
void ensure_size(std::vector<T, Allocator>& v, std::size_t n) {
  if (v.size() >= n) return;
  if (v.capacity() < n) v.reserve(n + n / 2);
  v.resize(n);
}

// ensure_size for an array whose elements the caller rewrites before reading (a frame's, at its
// start): one too small is freed before the bigger one is allocated, rather than copied into
// it, which would touch (make resident) as many bytes of the new array as the old one held.
template <class T, class Allocator>
void ensure_size_discarding(std::vector<T, Allocator>& v, std::size_t n) {
  if (v.capacity() < n) std::vector<T, Allocator>().swap(v);
  ensure_size(v, n);
}

}  // namespace

std::size_t triangle_region_budget() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return std::size_t{1} << 30;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size) / 4;
}

namespace {

// Frame-wide totals of the chunks' regions (and then of what overflowed them).
struct Totals {
  std::size_t triangles = 0, planes = 0, lines = 0, points = 0, entries = 0;
};

// Whether `draw` fills triangles (sets up a triangle per triangle of its mesh).
bool fills_triangles(const DrawRecord& draw) {
  const Topology topology = draw.mesh->topology;
  return topology != Topology::lines && topology != Topology::points &&
         draw.pipeline.fills_triangles;
}

// Gives a chunk of n primitives of `draw` its regions: room for everything it sets up unless
// clipping splits triangles (one triangle per triangle, three edges per wireframe triangle,
// one segment per line, one point per point), so only a fan's extra pieces can overflow; no
// room for triangles unless `triangle_regions` (Frame::max_triangle_region_bytes).
void plan_regions(GeometryChunk& chunk, const DrawRecord& draw, bool triangle_regions,
                  Totals& totals) {
  const auto n = static_cast<std::uint32_t>(chunk.end - chunk.begin);
  const Topology topology = draw.mesh->topology;
  const bool line_mesh = topology == Topology::lines, point_mesh = topology == Topology::points;
  const bool triangle_mesh = !line_mesh && !point_mesh;
  const std::uint32_t triangles = triangle_regions && fills_triangles(draw) ? n : 0;
  const std::uint32_t lines = line_mesh                                    ? n
                              : triangle_mesh && draw.pipeline.draws_edges ? 3 * n
                                                                           : 0;
  const std::uint32_t points = point_mesh ? n : 0;
  chunk.triangles = {static_cast<std::uint32_t>(totals.triangles), triangles, 0};
  chunk.planes_begin = static_cast<std::uint32_t>(totals.planes);
  chunk.lines = {static_cast<std::uint32_t>(totals.lines), lines, 0};
  chunk.points = {static_cast<std::uint32_t>(totals.points), points, 0};
  totals.triangles += triangles;
  totals.planes += std::size_t{triangles} * draw.pipeline.varyings;
  totals.lines += lines;
  totals.points += points;
  chunk.entries = {static_cast<std::uint32_t>(totals.entries), triangles + lines + points, 0};
  totals.entries += triangles + lines + points;
  chunk.overflow.clear();
  chunk.more_entries.clear();
  chunk.counts = {};
}

// Splits every draw into chunks, in draw order, each with its regions of the frame's arrays.
Totals plan_chunks(Frame& frame) {
  std::size_t region_bytes = 0;
  for (std::uint32_t d : frame.draw_order) {
    const DrawRecord& draw = frame.draws[d];
    if (!fills_triangles(draw)) continue;
    region_bytes += draw.mesh->primitive_count() *
                    (sizeof(SetupTriangle) + sizeof(Plane) * draw.pipeline.varyings);
  }
  // Past the limit, each chunk's triangles go to its overflow buffer, appended to the frame's
  // arrays once set up: only the triangles that survive culling (a few per pixel at most, once
  // they are smaller than pixels) take memory, where reserving regions for 100 million
  // triangles, tens of gigabytes, fails. Below it the regions are reserved (their culled part
  // is never touched, so costs no memory) and the appending copy is skipped.
  const bool triangle_regions = region_bytes <= frame.max_triangle_region_bytes;
  Totals totals;
  std::size_t count = 0;
  for (std::uint32_t d : frame.draw_order) {
    std::size_t n = frame.draws[d].mesh->primitive_count();
    for (std::size_t begin = 0; begin < n; begin += kChunkPrimitives) {
      if (frame.chunks.size() <= count) frame.chunks.emplace_back();
      GeometryChunk& chunk = frame.chunks[count++];
      chunk.draw = d;
      chunk.begin = begin;
      chunk.end = std::min(n, begin + kChunkPrimitives);
      plan_regions(chunk, frame.draws[d], triangle_regions, totals);
    }
  }
  // Indices must stay clear of the sequence's flag bits (primitive_sink.hpp).
  if (totals.triangles >= kMaxPrimitiveIndex || totals.lines >= kMaxPrimitiveIndex ||
      totals.points >= kMaxPrimitiveIndex || totals.planes > UINT32_MAX ||
      totals.entries > UINT32_MAX) {
    throw Error("renderer: too many primitives in one frame");
  }
  frame.chunk_count = count;
  ensure_size_discarding(frame.triangles, totals.triangles);
  ensure_size_discarding(frame.planes, totals.planes);
  ensure_size_discarding(frame.lines, totals.lines);
  ensure_size_discarding(frame.points, totals.points);
  ensure_size_discarding(frame.sequence, totals.entries);
  return totals;
}

// Appends what overflowed the chunks' regions after all the regions, in chunk order, and
// rewrites the sequence entries that pointed into the overflow buffers. Also sums the counts.
void finish_chunks(Frame& frame, Totals end) {
  // The arrays grow once, to hold every chunk's overflow (a frame without regions puts all its
  // triangles there).
  Totals all = end;
  for (std::size_t k = 0; k < frame.chunk_count; ++k) {
    const PrimitiveBuffer& o = frame.chunks[k].overflow;
    all.triangles += o.triangles.size();
    all.planes += o.planes.size();
    all.lines += o.lines.size();
  }
  if (all.triangles >= kMaxPrimitiveIndex || all.lines >= kMaxPrimitiveIndex ||
      all.planes > UINT32_MAX) {
    throw Error("renderer: too many primitives in one frame");
  }
  ensure_size(frame.triangles, all.triangles);
  ensure_size(frame.planes, all.planes);
  ensure_size(frame.lines, all.lines);
  std::size_t sequence_at = 0;
  for (std::size_t k = 0; k < frame.chunk_count; ++k) {
    GeometryChunk& chunk = frame.chunks[k];
    chunk.sequence_at = sequence_at;
    sequence_at += chunk.entry_count();
    frame.stats.culled += chunk.counts.culled;
    frame.stats.clipped += chunk.counts.clipped;
    frame.stats.drawn += chunk.triangles.used + chunk.overflow.triangles.size();
    frame.stats.lines_drawn += chunk.lines.used + chunk.overflow.lines.size();
    frame.stats.points_drawn += chunk.points.used;
    const PrimitiveBuffer& o = chunk.overflow;
    if (o.triangles.empty() && o.lines.empty()) continue;
    for (std::size_t i = 0; i < o.triangles.size(); ++i) {
      SetupTriangle t = o.triangles[i];
      t.varying_planes += static_cast<std::uint32_t>(end.planes);
      frame.triangles[end.triangles + i] = t;
    }
    std::copy(o.planes.begin(), o.planes.end(), frame.planes.begin() + end.planes);
    std::copy(o.lines.begin(), o.lines.end(), frame.lines.begin() + end.lines);
    const auto rewrite = [&](SequenceEntry& entry) {
      std::uint32_t& e = entry.index;
      if (!(e & kOverflowBit)) return;
      const std::uint32_t local = e & ~(kOverflowBit | kLineBit);
      e = (e & kLineBit) ? static_cast<std::uint32_t>(end.lines + local) | kLineBit
                         : static_cast<std::uint32_t>(end.triangles + local);
    };
    for (std::uint32_t i = 0; i < chunk.entries.used; ++i) {
      rewrite(frame.sequence[chunk.entries.begin + i]);
    }
    for (SequenceEntry& entry : chunk.more_entries) rewrite(entry);
    end.triangles += o.triangles.size();
    end.planes += o.planes.size();
    end.lines += o.lines.size();
  }
  frame.primitives = sequence_at;
}

}  // namespace

void run_geometry(Frame& frame, int workers) {
  if (frame.vertices.size() < frame.draws.size()) frame.vertices.resize(frame.draws.size());
  if (frame.worker_vertices.size() < static_cast<std::size_t>(workers)) {
    frame.worker_vertices.resize(workers);
  }
  const Totals totals = plan_chunks(frame);
  const ClipBounds guard = guard_band_bounds(frame);
  // A small draw is one task, its vertex transform and then all its chunks, so that its
  // vertices (about 160 bytes each) are still in the core's cache when its triangles read
  // them; they go to the worker's own buffer, which the worker's next small draw overwrites
  // while it is still in cache, instead of to the draw's, which a frame of many draws has long
  // evicted. (Such a task never waits on nested parallel work, so its worker cannot start
  // another task meanwhile: transform_vertices runs a small draw on the calling thread.) A big
  // draw's vertices are transformed first, in parallel batches, into the draw's buffer, and
  // then its chunks are tasks of their own.
  frame.geometry_tasks.clear();                      // capacity kept across frames
  std::size_t small_vertices = 0, small_over_w = 0;  // the largest small draw's needs
  for (std::uint32_t k = 0; k < frame.chunk_count;) {
    const std::uint32_t d = frame.chunks[k].draw;
    std::uint32_t end = k + 1;
    while (end < frame.chunk_count && frame.chunks[end].draw == d) ++end;
    frame.stats.triangles_in += frame.draws[d].mesh->primitive_count();
    const std::size_t vertex_count = frame.draws[d].mesh->positions.size();
    if (vertex_count <= kVerticesPerTask) {
      frame.geometry_tasks.push_back({k, end, true});
      small_vertices = std::max(small_vertices, vertex_count);
      small_over_w = std::max(
          small_over_w,
          vertex_count * static_cast<std::size_t>(frame.draws[d].pipeline.varyings) + kOverWSlack);
    } else {
      transform_vertices(frame.draws[d], *frame.kernels, frame.width, frame.height, guard, workers,
                         frame.vertices[d]);
      for (; k < end; ++k) frame.geometry_tasks.push_back({k, k + 1, false});
    }
    k = end;
  }
  // Every worker's buffer can hold the largest small draw before the tasks start: which worker
  // takes which draw changes from frame to frame, and a buffer growing inside a task would
  // allocate in a steady-state frame.
  for (DrawVertices& buffer : frame.worker_vertices) {
    buffer.clip.reserve(small_vertices);
    buffer.projected.reserve(small_vertices);
    buffer.over_w.reserve(small_over_w);
  }
  parallel_tasks(static_cast<int>(frame.geometry_tasks.size()), workers, [&](int i, int worker) {
    const Frame::GeometryTask& task = frame.geometry_tasks[i];
    const std::uint32_t d = frame.chunks[task.first_chunk].draw;
    DrawVertices& vertices = task.transform ? frame.worker_vertices[worker] : frame.vertices[d];
    if (task.transform) {
      transform_vertices(frame.draws[d], *frame.kernels, frame.width, frame.height, guard, workers,
                         vertices);
    }
    for (std::uint32_t k = task.first_chunk; k < task.end_chunk; ++k) {
      GeometryChunk& chunk = frame.chunks[k];
      PrimitiveSink sink(frame, chunk, frame.draws[d].pipeline.varyings);
      assemble_primitives(frame, d, vertices, chunk.begin, chunk.end, sink, chunk.counts);
    }
  });
  finish_chunks(frame, totals);
}

}  // namespace facet::pipeline
