// Stage: vertex transform, the SIMD part. vertex.cpp hands it a run of up to kVertexPass mesh
// vertices; vertex_pass.cpp (compiled for every SIMD target Highway supports, picked at run
// time) computes everything about them that needs no shading model, several vertices at a
// time: clip position, unit world normal, outcodes and screen position. vertex.cpp then calls
// the shading model per vertex and stores the results.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "core/simd_target.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/setup/fixed_point.hpp"

namespace facet::pipeline {

inline constexpr std::size_t kVertexPass = 64;

struct VertexPassInput {
  const glm::vec3* positions;  // the mesh's
  const glm::vec3* normals;    // the mesh's, or null: the normals are then zero
  glm::mat4 model_view_projection;
  glm::mat3 normal_matrix;
  int width, height;  // of the framebuffer, for to_screen
  ClipBounds frustum, guard;
};

// ProjectedVertex::codes bit set by the pass when the lane's screen position is outside the
// 32-bit integers: only vertices far beyond the guard band, whose screen position nothing reads
// (their triangles are clipped, and the clipped vertices projected anew), so it is left as the
// target computed it. Stored positions without the bit are to_screen's.
inline constexpr std::uint32_t kScalarScreen = 1u << 17;

// Results for vertices [first, first + count), structure of arrays indexed by vertex - first.
// Each value is computed with the same operations in the same order on every target (glm's for
// the matrices; outcode() and to_screen() for the rest, whose definitions are written out in
// pipeline/reference.hpp for the tests), so it is bit-identical on every target.
struct VertexPass {
  alignas(64) float x[kVertexPass], y[kVertexPass], z[kVertexPass], w[kVertexPass];  // clip
  alignas(64) float nx[kVertexPass], ny[kVertexPass], nz[kVertexPass];  // unit world normal
  alignas(64) std::int32_t sx[kVertexPass], sy[kVertexPass];            // ScreenVertex
  alignas(64) float depth[kVertexPass], inv_w[kVertexPass];
  alignas(64) std::uint32_t codes[kVertexPass];  // as ProjectedVertex::codes (+ kScalarScreen)
};

// Runs the pass over vertices [first, first + count) of in; the kernel for `target`.
using VertexPassKernel = void (*)(const VertexPassInput& in, std::size_t first, std::size_t count,
                                  VertexPass& out);
VertexPassKernel vertex_pass_kernel(SimdTarget target);

// out[i] = to_screen(clip[i], width, height) for i < count: what the pass computes for a mesh's
// vertices, for the vertices clipping makes and the ends of lines.
using ProjectToScreenKernel = void (*)(const glm::vec4* clip, int count, int width, int height,
                                       ScreenVertex* out);
ProjectToScreenKernel project_to_screen_kernel(SimdTarget target);

}  // namespace facet::pipeline
