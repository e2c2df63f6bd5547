// Stage: vertex transform. Reads a recorded draw (mesh + uniforms) and writes, per mesh vertex,
// a ClipVertex (clip position + the shading model's varyings) and its projection (outcodes,
// screen position, varyings over w) for primitive assembly and setup.
#pragma once

#include <vector>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Vertices per task: big enough to amortise scheduling, small enough to balance 2-8 cores. A
// draw of at most this many is transformed by the calling thread alone.
inline constexpr std::size_t kVertexBatch = 4096;

// Transforms every vertex of the draw into out (resized to the vertex count) and projects it
// onto a width x height framebuffer. Large meshes are transformed in parallel batches; the
// result does not depend on how they are split.
void transform_vertices(const DrawRecord& draw, int width, int height, int workers,
                        DrawVertices& out);

}  // namespace facet::pipeline
