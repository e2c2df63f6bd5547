// The Gouraud models' lighting, with SIMD, a run of vertices at once (vertex_batch.cpp, compiled
// for every target Highway supports): the vertex stage (pipeline/geometry/vertex.cpp) hands it the
// vertices of one vertex pass, and the models' vertex() and face_without_normals()
// (lit_models.hpp) hand it one vertex or one triangle's centre. Its lighting (a world position, a
// view direction, each light's incident light and shadow, a normalized half vector and a power)
// is most of the geometry stage's time in Gouraud-lit scenes. Directional, point and spot lights,
// shadowed or not (light_batch-inl.h, shadow_batch-inl.h); the same bits on every target,
// vertex_batch_test checks it.
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
  // Object space, w the handedness, count of them, or null: zero. A model that reads one turns
  // it to world space (world_tangent, surface.hpp).
  const glm::vec4* tangents = nullptr;
};

// Where the Gouraud models (lit_models.hpp) keep their varyings: the diffuse light at slots
// diffuse..diffuse+2, the specular light at diffuse+3..diffuse+5, and, when with_surface, the
// texture coordinate and material_color() at kTexcoordSlot and kColorSlot (surface.hpp). Under
// gray light (every light's color and the specular color gray: the three channels' light from the
// lights has the same bits), one slot each: the diffuse light at `diffuse`, without the ambient
// light (which need not be gray: the pixel adds it), and the specular light at the next.
struct GouraudLayout {
  int diffuse;
  bool with_surface;
  bool gray = false;
};

// out[k][n]: varying k of vertex n in that layout, n < count (the light is stored a vector at a
// time: some entries past count are written too).
using GouraudVertexBatchKernel = void (*)(const DrawUniforms& u, const VertexBatchInput& in,
                                          GouraudLayout layout, float (*out)[kVertexBatch]);
GouraudVertexBatchKernel gouraud_vertex_batch_kernel(SimdTarget target);

// Points already in world space, with their unit world normals: count of each, at most
// kVertexBatch; lit with the lights' shadows or without (flat shading's triangles), in the full
// layout or the gray light's (GouraudLayout).
struct WorldPoints {
  int count = 0;
  const glm::vec3* positions = nullptr;
  const glm::vec3* normals = nullptr;
  bool shadows = true;
  bool gray = false;
};

// out[k][n]: the diffuse light (k = 0..2) and the specular light (k = 3..5) at point n, as the
// vertex batch lights its vertices once it has their world positions; under gray light, the
// diffuse light without the ambient (k = 0) and the specular light (k = 1).
using GouraudLightBatchKernel = void (*)(const DrawUniforms& u, const WorldPoints& in,
                                         float (*out)[kVertexBatch]);
GouraudLightBatchKernel gouraud_light_batch_kernel(SimdTarget target);

}  // namespace facet::shading
