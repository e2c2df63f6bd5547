// Stage: setup of triangles. Primitive assembly (primitive.cpp) hands the triangles culling kept
// that need no clipping, a run at a time, and each clipped polygon's fan to a SIMD kernel
// (setup_batch.cpp, compiled for every target Highway supports), which sets them up: winding,
// pixel box, edge functions, depth and 1 / w planes with one triangle per lane, then each kept
// triangle's varying planes with one plane per lane. One at a time, a triangle's setup waits
// on its own double-precision division and products; across lanes they overlap.
#pragma once

#include <cstdint>

#include "core/simd_target.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/geometry/primitive_sink.hpp"

namespace facet::pipeline {

// Triangles to set up, a lane each, by their vertices' indices into the draw's projected
// vertices and varyings (primitive assembly passes a run of the cull kernel's survivors, which
// need no clipping, in place): the kernel reads the indices a vector at a time, so each array
// must be readable kSetupBatchSlack entries past `count` (what is there is not used).
inline constexpr int kSetupBatchSlack = 16;
struct SetupBatch {
  int count = 0;
  const std::uint32_t* vertex[3] = {};     // in the draw's winding
  const std::uint32_t* front_facing = {};  // 1 or 0, as culling decided
};

// What the kernel needs besides the batch.
struct SetupBatchTarget {
  PrimitiveSink& out;
  int width, height;  // the frame's
  std::uint32_t draw;
  const ProjectedVertex* projected;  // the draw's, screen parts meaningful (no clipping)
  const float* over_w;               // `varyings` floats a vertex, kOverWSlack past the last
  int varyings;
  // The first of three varyings (a normal) whose planes a triangle seen from the side its
  // normals turn away from gets reversed, or -1 (DrawPipeline::lights_back_faces); and the
  // first of three holding the vertex's world position, which tells that side.
  int back_face_normal = -1;
  int back_face_position = -1;
};

// Sets up the batch's triangles into target.out, in lane order; returns how many it dropped
// (degenerate or flipped by snapping, or covering no pixel centre).
using SetupBatchKernel = int (*)(const SetupBatch& batch, const SetupBatchTarget& target);

// The kernel for `target` (core/simd_target.hpp), fetched once per frame (pipeline/kernels.hpp).
SetupBatchKernel setup_batch_kernel(SimdTarget target);

}  // namespace facet::pipeline
