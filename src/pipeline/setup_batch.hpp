// Stage: setup, batched. Primitive assembly (primitive.cpp) gathers the triangles that need no
// clipping into a SetupBatch, and a SIMD kernel (setup_batch.cpp, compiled for every target
// Highway supports) sets them up: winding, pixel box, edge functions, depth and 1 / w planes
// with one triangle per lane, then each kept triangle's varying planes with one plane per lane.
// It writes them, in order, as setup_projected_triangle (setup.hpp) would one at a time, bit for
// bit. One at a time, a triangle's setup waits on its own double-precision division and
// products; across lanes they overlap.
#pragma once

#include <cstdint>

#include "pipeline/frame.hpp"
#include "pipeline/primitive_sink.hpp"

namespace facet::pipeline {

// Triangles per batch: a multiple of every target's lane count.
inline constexpr int kSetupBatch = 32;

// Per triangle (lane): its vertices' screen positions (ScreenVertex) and varyings times 1 / w,
// in the draw's winding, and the facing culling decided.
struct SetupBatch {
  int count = 0;  // lanes [0, count) hold triangles
  alignas(64) std::int32_t x[3][kSetupBatch] = {};
  alignas(64) std::int32_t y[3][kSetupBatch] = {};
  alignas(64) float z[3][kSetupBatch] = {};
  alignas(64) float inv_w[3][kSetupBatch] = {};
  alignas(64) std::int32_t front_facing[kSetupBatch] = {};  // 1 or 0
  const float* over_w[3][kSetupBatch] = {};                 // `varyings` floats each
};

// What the kernel needs besides the batch.
struct SetupBatchTarget {
  PrimitiveSink& out;
  int width, height;  // the frame's
  std::uint32_t draw;
  int varyings;
};

// Sets up the batch's triangles into target.out, in lane order; returns how many it dropped
// (degenerate or flipped by snapping, or covering no pixel centre).
using SetupBatchKernel = int (*)(const SetupBatch& batch, const SetupBatchTarget& target);

// The kernel of the SIMD target Highway has chosen (choosing one if none is yet), to fetch once
// for many batches.
SetupBatchKernel setup_batch_kernel();

}  // namespace facet::pipeline
