// Stage: primitive assembly, culling several triangles a vector. primitive.cpp culls a draw's
// triangles (strips listed as triangles) a run of up to kCullBatch at a time: the kernel
// (cull_batch.cpp, compiled for every target Highway supports) reads each triangle's three
// projected vertices and drops it for non-finite positions, all three vertices outside one
// frustum plane, zero orientation in homogeneous coordinates (homogeneous_orientation's double
// operations in its order, so every target drops the same triangles), the facing the draw
// culls, or (CullInput::drops_empty_boxes) a pixel box holding no pixel. The survivors are kept
// in order.
#pragma once

#include <cstdint>

#include "core/simd_target.hpp"
#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Triangles culled in one go before the survivors are assembled.
inline constexpr int kCullBatch = 128;

struct CullInput {
  const std::uint32_t* indices;  // three per triangle, in the draw's winding
  int count;                     // triangles, at most kCullBatch
  const ProjectedVertex* projected;
  bool culls_front, culls_back;
  bool positions = false;  // also list where each survivor was in the run (CullSurvivors)
  // Also drops the triangles setup would drop for an empty pixel box (setup_batch.cpp), among
  // those that need no clipping (planes_to_clip): in a frame of this size, whose samples reach
  // this far from a pixel's centre (fixed point: kSampleReach under MSAA, else 0). Setup works
  // a vector of triangles at a time, dropped or not: in scenes of tiny triangles (shadow maps'
  // distant casters above all), most of the vectors it would have spent on them are saved. Only
  // where every survivor that needs no clipping goes to the setup kernel as it is
  // (primitive.cpp's by_runs: no per-triangle hooks, which run for every triangle culling keeps,
  // and no wireframe edges, which are drawn whatever the fill).
  bool drops_empty_boxes = false;
  int width = 0, height = 0;
  std::int32_t reach = 0;
};

// The triangles that survive, in order, structure of arrays. Room for a vector past the last.
struct CullSurvivors {
  static constexpr int kRoom = kCullBatch + 16;
  int count = 0;
  alignas(64) std::uint32_t i0[kRoom], i1[kRoom], i2[kRoom];
  alignas(64) std::uint32_t codes[kRoom];         // the three vertices' codes, or-ed
  alignas(64) std::uint32_t front_facing[kRoom];  // 1 or 0
  alignas(64) std::uint32_t position[kRoom];      // in the run, when CullInput::positions
};

using CullKernel = void (*)(const CullInput& in, CullSurvivors& out);

// The kernel for `target` (core/simd_target.hpp).
CullKernel cull_kernel(SimdTarget target);

}  // namespace facet::pipeline
