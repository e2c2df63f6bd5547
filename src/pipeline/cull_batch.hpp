// Stage: primitive assembly, culling several triangles a vector. primitive.cpp culls a draw's
// triangle lists a run of up to kCullBatch triangles at a time: the kernel (cull_batch.cpp,
// compiled for every target Highway supports) reads each triangle's three projected vertices
// and drops it as Assembler::accept (primitive.cpp) would, in the same double operations: for
// non-finite positions, all three vertices outside one frustum plane, zero orientation in
// homogeneous coordinates, or the facing the draw culls. The survivors are kept in order.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Triangles culled in one go before the survivors are assembled.
inline constexpr int kCullBatch = 128;

// Where the kernel gathers (targets narrower than AVX2), it addresses a vertex by a 32-bit
// element offset (index x 8 floats): draws with more vertices are culled one triangle at a time.
inline constexpr std::size_t kMaxCullBatchVertices = std::size_t{1} << 28;

struct CullInput {
  const std::uint32_t* indices;  // three per triangle, in the draw's winding
  int count;                     // triangles, at most kCullBatch
  const ProjectedVertex* projected;
  bool culls_front, culls_back;
};

// The triangles that survive, in order, structure of arrays. Room for a vector past the last.
struct CullSurvivors {
  static constexpr int kRoom = kCullBatch + 16;
  int count = 0;
  alignas(64) std::uint32_t i0[kRoom], i1[kRoom], i2[kRoom];
  alignas(64) std::uint32_t codes[kRoom];         // the three vertices' codes, or-ed
  alignas(64) std::uint32_t front_facing[kRoom];  // 1 or 0
};

using CullKernel = void (*)(const CullInput& in, CullSurvivors& out);

// The kernel of the SIMD target Highway has chosen (choosing one if none is yet).
CullKernel cull_kernel();

}  // namespace facet::pipeline
