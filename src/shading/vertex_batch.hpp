// The Gouraud model's vertex() for a run of vertices at once, with SIMD (vertex_batch.cpp,
// compiled for every target Highway supports): the vertex stage (pipeline/geometry/vertex.cpp)
// hands it the vertices of one vertex pass instead of calling vertex() for each. Its lighting (a
// world position, a view direction, a normalized half vector and a power per light) is most of the
// geometry stage's time in Gouraud-lit scenes. Same operations as GouraudShading::vertex()
// (lit_models.hpp) lane by lane, so the same bits, shadows of directional lights included
// (shadow_batch-inl.h); draws with point or spot lights keep vertex().
#pragma once

#include <glm/glm.hpp>

#include "core/simd_target.hpp"
#include "shading/uniforms.hpp"

namespace facet::shading {

inline constexpr int kVertexBatch = 64;

struct VertexBatchInput {
  int count = 0;                         // vertices, at most kVertexBatch
  const glm::vec3* positions = nullptr;  // object space, count of them
  // The unit world normal, one array per axis (the vertex pass's), kVertexBatch entries each.
  const float* normal[3] = {};
  const glm::vec2* texcoords = nullptr;  // count of them, or null: (0, 0)
  const glm::vec4* colors = nullptr;     // count of them, or null: white
};

// Whether gouraud_vertex_batch can light this draw: every light directional (shadowed or not).
bool gouraud_batches_vertices(const DrawUniforms& u);

// Where the Gouraud models (lit_models.hpp) keep their varyings: the diffuse light at slots
// diffuse..diffuse+2, the specular light at diffuse+3..diffuse+5, and, when with_surface, the
// texture coordinate and material_color() at kTexcoordSlot and kColorSlot (surface.hpp).
struct GouraudLayout {
  int diffuse;
  bool with_surface;
};

// out[k][n]: varying k of vertex n, as the Gouraud model of that layout's vertex() writes it.
using GouraudVertexBatchKernel = void (*)(const DrawUniforms& u, const VertexBatchInput& in,
                                          GouraudLayout layout, float (*out)[kVertexBatch]);
GouraudVertexBatchKernel gouraud_vertex_batch_kernel(SimdTarget target);

}  // namespace facet::shading
