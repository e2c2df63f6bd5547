// The varying layout shared by the lit shading models, what their vertices write into it, and
// texture map sampling at a fragment (for the models with fragment()).
//
//   slot  0-1  texture coordinate   6-8  world normal
//         2-5  color (material x    9-11  world position
//              vertex color)       12-15  world tangent, w = handedness
// Ordered by how many models need them, so a model that needs fewer interpolates a prefix:
// unlit uses slots 0-5 only.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "shading/fragment.hpp"
#include "shading/uniforms.hpp"
#include "shading/vertex_batch.hpp"

namespace facet::shading {

inline constexpr int kTexcoordSlot = 0;
inline constexpr int kColorSlot = 2;
inline constexpr int kNormalSlot = 6;
inline constexpr int kPositionSlot = 9;
inline constexpr int kTangentSlot = 12;
inline constexpr int kUnlitVaryings = 6;  // texture coordinate and color
// Also without the position: what a surface lit by directional lights only, from one side,
// reads (no light's direction depends on where the pixel is, and no back face is turned).
inline constexpr int kUnpositionedSurfaceVaryings = 9;
inline constexpr int kSurfaceVaryings = 12;             // without tangent
inline constexpr int kSurfaceVaryingsWithTangent = 16;  // for normal maps

inline void store(float* out, glm::vec4 v) {
  out[0] = v.r, out[1] = v.g, out[2] = v.b, out[3] = v.a;
}
inline void store(float* out, glm::vec3 v) { out[0] = v.x, out[1] = v.y, out[2] = v.z; }
inline void store(float* out, glm::vec2 v) { out[0] = v.x, out[1] = v.y; }
inline glm::vec4 load4(const float* in) { return {in[0], in[1], in[2], in[3]}; }
inline glm::vec3 load3(const float* in) { return {in[0], in[1], in[2]}; }

inline glm::vec4 material_color(const VertexInput& in, const DrawUniforms& u) {
  return u.material->use_vertex_colors ? u.material->base_color * in.color : u.material->base_color;
}

inline glm::vec3 safe_normalize(glm::vec3 v) {
  float length_squared = glm::dot(v, v);
  return length_squared > 0.0f ? v * (1.0f / std::sqrt(length_squared)) : glm::vec3(0.0f);
}

// Writes the first kCount slots of the surface layout for one vertex.
template <int kCount>
void surface_vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
  store(out + kTexcoordSlot, in.texcoord);
  store(out + kColorSlot, material_color(in, u));
  if constexpr (kCount > kNormalSlot) store(out + kNormalSlot, in.normal);
  if constexpr (kCount > kPositionSlot) {
    store(out + kPositionSlot, glm::vec3(u.model * glm::vec4(in.position, 1.0f)));
  }
  if constexpr (kCount > kTangentSlot) store(out + kTangentSlot, in.tangent);
}

// A mesh's tangent (object space, w the handedness) in world space, as VertexInput::tangent holds
// it; model3: the draw's model matrix without its translation.
inline glm::vec4 world_tangent(const glm::mat3& model3, const glm::vec4& tangent) {
  return {model3 * glm::vec3(tangent), tangent.w};
}

// The texture coordinates of a run of vertices into their slots (kTexcoordSlot): (0, 0) where
// the mesh has none.
inline void texcoords_vertex_batch(const VertexBatchInput& in, float (*out)[kVertexBatch]) {
  for (int c = 0; c < 2; ++c) {
    float* slot = out[kTexcoordSlot + c];
    if (in.texcoords == nullptr) {
      std::fill_n(slot, in.count, 0.0f);
    } else {
      for (int n = 0; n < in.count; ++n) slot[n] = in.texcoords[n][c];
    }
  }
}

// surface_vertex() for a run of vertices (the batch form, vertex_batch.hpp): out[k][n] is slot
// k of vertex n. The same operations, so the same bits, without a call and a VertexInput per
// vertex; each slot is a loop of its own that the compiler vectorizes.
template <int kCount>
void surface_vertex_batch(const DrawUniforms& u, const VertexBatchInput& in,
                          float (*out)[kVertexBatch]) {
  const int count = in.count;
  // The per-draw choices are made once, outside the loops over the vertices.
  texcoords_vertex_batch(in, out);
  // material_color(): white vertex colors where the mesh has none, multiplied all the same.
  const bool vary = u.material->use_vertex_colors && in.colors != nullptr;
  const glm::vec4 same = u.material->use_vertex_colors ? u.material->base_color * glm::vec4(1.0f)
                                                       : u.material->base_color;
  if (vary) {
    // The four channels in one loop, the factors in locals: a loop per channel would index
    // glm's vec4 by a variable, which GCC compiles into a branch per vertex.
    const float r = u.material->base_color.r, g = u.material->base_color.g,
                b = u.material->base_color.b, a = u.material->base_color.a;
    float* red = out[kColorSlot];
    float* green = out[kColorSlot + 1];
    float* blue = out[kColorSlot + 2];
    float* alpha = out[kColorSlot + 3];
    for (int n = 0; n < count; ++n) {
      const glm::vec4& color = in.colors[n];
      red[n] = r * color.r, green[n] = g * color.g, blue[n] = b * color.b, alpha[n] = a * color.a;
    }
  } else {
    for (int c = 0; c < 4; ++c) std::fill_n(out[kColorSlot + c], count, same[c]);
  }
  if constexpr (kCount > kNormalSlot) {
    for (int c = 0; c < 3; ++c) std::copy_n(in.normal[c], count, out[kNormalSlot + c]);
  }
  if constexpr (kCount > kPositionSlot) {
    for (int n = 0; n < count; ++n) {
      const glm::vec4 position = u.model * glm::vec4(in.positions[n], 1.0f);
      for (int c = 0; c < 3; ++c) out[kPositionSlot + c][n] = position[c];
    }
  }
  if constexpr (kCount > kTangentSlot) {
    if (in.tangents == nullptr) {
      for (int c = 0; c < 4; ++c) std::fill_n(out[kTangentSlot + c], count, 0.0f);
    } else {
      const glm::mat3 model3(u.model);
      for (int n = 0; n < count; ++n) {
        const glm::vec4 tangent = world_tangent(model3, in.tangents[n]);
        for (int c = 0; c < 4; ++c) out[kTangentSlot + c][n] = tangent[c];
      }
    }
  }
}

// The material's base color map at the fragment, sampled ahead by the raster loop for a whole
// batch of pixels (texel_batch.hpp): a model that reads it declares kBaseColorTexcoord.
inline glm::vec4 base_color_texel(const Fragment& f) { return f.base_texel; }

// The mark of models whose normal is the side of the surface seen: the back faces of two-sided
// materials get their normal reversed (pipeline/frame.hpp's DrawPipeline::lights_back_faces).
struct LightsBackFaces {
  static constexpr bool kLightsBackFaces = true;
};

// vertex_batch from the model's own vertex(), a vertex at a time: the vertex stage's batch form
// of every model without one of its own (pipeline/record/pipeline_table.hpp's make_pipeline),
// the same values as vertex() given each vertex's VertexInput.
template <class Model>
void vertex_batch_from_vertex(const DrawUniforms& u, const VertexBatchInput& in,
                              float (*out)[kVertexBatch]) {
  if constexpr (Model::kVaryings > 0) {
    const glm::mat3 model3(u.model);
    for (int n = 0; n < in.count; ++n) {
      VertexInput vertex;
      vertex.position = in.positions[n];
      vertex.normal = {in.normal[0][n], in.normal[1][n], in.normal[2][n]};
      vertex.color = in.colors ? in.colors[n] : glm::vec4(1.0f);
      vertex.texcoord = in.texcoords ? in.texcoords[n] : glm::vec2(0.0f);
      vertex.tangent = in.tangents ? world_tangent(model3, in.tangents[n]) : glm::vec4(0.0f);
      float varyings[Model::kVaryings];
      Model::vertex(vertex, u, varyings);
      for (int k = 0; k < Model::kVaryings; ++k) out[k][n] = varyings[k];
    }
  }
}

}  // namespace facet::shading
