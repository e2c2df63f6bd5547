// Stage: vertex transform, its results stored per vertex. The vertex pass (vertex_pass.hpp) and
// the shading models' batch forms compute a run of vertices as structure of arrays; culling and
// setup read them per vertex (ProjectedVertex, and each vertex's varyings over w in a row).
// vertex_rows.cpp (compiled for every SIMD target Highway supports) turns eight vertices'
// values into their rows with a transpose in registers, where element by element each vertex
// would cost a store per value and a loop per vertex.
#pragma once

#include <cstddef>

#include "pipeline/frame.hpp"
#include "pipeline/geometry/vertex_pass.hpp"

namespace facet::pipeline {

// out[j] for j < count: clip x, y and w, the codes without kScalarScreen, and the screen
// position from the pass. Vertices whose codes have kScalarScreen get the pass's values too:
// the caller recomputes their screen position (to_screen).
using StoreProjectedKernel = void (*)(const VertexPass& pass, std::size_t count,
                                      ProjectedVertex* out);
StoreProjectedKernel store_projected_kernel(SimdTarget target);

// out[j * varyings + k] = values[k][j] * inv_w[j] for j < count, k < varyings (at most
// kMaxVaryings): each vertex's varyings over w, as setup's planes take them. Writes nothing
// else.
using StoreOverWKernel = void (*)(const float (*values)[kVertexPass], const float* inv_w,
                                  std::size_t count, int varyings, float* out);
StoreOverWKernel store_over_w_kernel(SimdTarget target);

}  // namespace facet::pipeline
