// Stage: vertex transform. Reads a recorded draw (mesh + uniforms) and writes, per mesh vertex,
// a ClipVertex (clip position + the shading model's varyings) and its projection (outcodes,
// screen position, varyings over w) for primitive assembly and setup.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pipeline/frame.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/vertex_pass.hpp"

namespace facet::pipeline {

// Vertices per task: big enough to amortise scheduling, small enough to balance 2-8 cores. A
// draw of at most this many is transformed by the calling thread alone.
inline constexpr std::size_t kVerticesPerTask = 4096;

// Whether the draw's vertex stage must write ClipVertex: the clipper, the per-triangle hooks,
// the edges and lines read them. A draw with none of those, whose bounds lie inside
// the guard band and between near and far, writes only its projected vertices and over_w: 80
// bytes a vertex less to write and read. A draw with hooks whose ClipVertex would take more than
// `max_clip_vertex_bytes` (Frame::max_clip_vertex_bytes) writes only its projected vertices:
// primitive assembly computes the corners of the triangles that survive culling
// (transform_corners), as the vertex stage would have. Decided once per frame
// (DrawRecord::clip_vertices), when the frame's size gives the guard band.
bool keeps_clip_vertices(const DrawRecord& draw, const ClipBounds& guard,
                         std::size_t max_clip_vertex_bytes);

// What the vertex pass reads of a draw, for a width x height framebuffer whose guard band (and
// plane) `guard` is.
VertexPassInput vertex_pass_input(const DrawRecord& draw, int width, int height,
                                  const ClipBounds& guard);

// The ClipVertex of the mesh vertices corner[0..2] of a draw, the same bits transform_vertices
// writes for them (every step of the vertex stage computes each vertex alone), for a draw that
// keeps none (keeps_clip_vertices).
void transform_corners(const DrawRecord& draw, const Kernels& kernels,
                       const VertexPassInput& pass_input, const std::uint32_t corner[3],
                       ClipVertex out[3]);

// Transforms every vertex of the draw into out (resized to the vertex count) and projects it
// onto a width x height framebuffer whose guard band (and plane) `guard` is. Large meshes are
// transformed in parallel batches; the result does not depend on how they are split.
void transform_vertices(const DrawRecord& draw, const Kernels& kernels, int width, int height,
                        const ClipBounds& guard, int workers, DrawVertices& out);

}  // namespace facet::pipeline
