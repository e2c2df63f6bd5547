// The geometry stage (see geometry.hpp).
#include "pipeline/geometry.hpp"

#include "pipeline/parallel.hpp"
#include "pipeline/primitive.hpp"
#include "pipeline/vertex.hpp"

namespace facet::pipeline {
namespace {

// Primitives per task: large enough that a chunk's set-up dwarfs scheduling, small enough
// that a 70k-triangle model splits into dozens of tasks for the cores to share.
constexpr std::size_t kChunkPrimitives = 2048;

// Sizes a chunk's buffers for every primitive visible and unclipped, so that steady-state
// frames never grow them (a clipped fan can still add a few; vectors then grow once).
void reserve(GeometryChunk& chunk, const DrawRecord& draw) {
  std::size_t n = chunk.end - chunk.begin;
  bool lines = draw.pipeline.draws_edges || draw.mesh->topology == Topology::lines;
  chunk.out.triangles.reserve(n);
  chunk.out.planes.reserve(n * draw.pipeline.varyings);
  chunk.out.sequence.reserve(lines ? 4 * n : n);
  if (lines) chunk.out.lines.reserve(3 * n);
}

// Splits every draw into chunks, in draw order; returns how many.
std::size_t plan_chunks(Frame& frame) {
  std::size_t count = 0;
  for (std::uint32_t d : frame.draw_order) {
    std::size_t n = frame.draws[d].mesh->primitive_count();
    for (std::size_t begin = 0; begin < n; begin += kChunkPrimitives) {
      if (frame.chunks.size() <= count) frame.chunks.emplace_back();
      GeometryChunk& chunk = frame.chunks[count++];
      chunk.draw = d;
      chunk.begin = begin;
      chunk.end = std::min(n, begin + kChunkPrimitives);
      reserve(chunk, frame.draws[d]);
    }
  }
  return count;
}

// Concatenates the chunks' primitives into the frame, fixing up indices.
void merge_chunks(Frame& frame, std::size_t count, int workers) {
  GeometryChunk::Offsets total;
  for (std::size_t k = 0; k < count; ++k) {
    const PrimitiveBuffer& out = frame.chunks[k].out;
    frame.chunks[k].at = total;
    total.triangles += out.triangles.size();
    total.lines += out.lines.size();
    total.planes += out.planes.size();
    total.sequence += out.sequence.size();
    frame.stats.culled += frame.chunks[k].counts.culled;
    frame.stats.clipped += frame.chunks[k].counts.clipped;
  }
  // Grow by half again when a frame needs more than any before, so animated scenes settle.
  auto resize = [](auto& v, std::size_t n) {
    if (v.capacity() < n) v.reserve(n + n / 2);
    v.resize(n);
  };
  resize(frame.triangles, total.triangles);
  resize(frame.lines, total.lines);
  resize(frame.planes, total.planes);
  resize(frame.sequence, total.sequence);
  parallel_tasks(static_cast<int>(count), workers, [&](int k, int) {
    const PrimitiveBuffer& out = frame.chunks[k].out;
    const GeometryChunk::Offsets& at = frame.chunks[k].at;
    for (std::size_t i = 0; i < out.triangles.size(); ++i) {
      SetupTriangle t = out.triangles[i];
      t.varying_planes += static_cast<std::uint32_t>(at.planes);
      frame.triangles[at.triangles + i] = t;
    }
    std::copy(out.lines.begin(), out.lines.end(), frame.lines.begin() + at.lines);
    std::copy(out.planes.begin(), out.planes.end(), frame.planes.begin() + at.planes);
    for (std::size_t i = 0; i < out.sequence.size(); ++i) {
      std::uint32_t e = out.sequence[i];
      frame.sequence[at.sequence + i] =
          (e & kLineBit) ? ((e & ~kLineBit) + static_cast<std::uint32_t>(at.lines)) | kLineBit
                         : e + static_cast<std::uint32_t>(at.triangles);
    }
  });
}

}  // namespace

void run_geometry(Frame& frame, int workers) {
  frame.PrimitiveBuffer::clear();
  if (frame.vertices.size() < frame.draws.size()) frame.vertices.resize(frame.draws.size());
  for (std::uint32_t d : frame.draw_order) {
    frame.stats.triangles_in += frame.draws[d].mesh->primitive_count();
    transform_vertices(frame.draws[d], frame.width, frame.height, workers, frame.vertices[d]);
  }
  std::size_t count = plan_chunks(frame);
  parallel_tasks(static_cast<int>(count), workers, [&](int k, int) {
    GeometryChunk& chunk = frame.chunks[k];
    chunk.out.clear();
    chunk.counts = {};
    assemble_primitives(frame, chunk.draw, chunk.begin, chunk.end, chunk.out, chunk.counts);
  });
  merge_chunks(frame, count, workers);
  frame.stats.drawn = frame.triangles.size();
}

}  // namespace facet::pipeline
