// The varying layout shared by the lit shading models, and the per-pixel surface they light:
// position, (normal-mapped) normal, view direction and albedo with its texture applied.
//
//   slot  0-1  texture coordinate   6-8  world position
//         2-5  color (material x    9-11  world normal
//              vertex color)       12-15  world tangent, w = handedness
// Ordered by how many models need them, so a model that needs fewer interpolates a prefix:
// unlit uses slots 0-5 only.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

#include "shading/fragment.hpp"
#include "shading/uniforms.hpp"

namespace facet::shading {

inline constexpr int kTexcoordSlot = 0;
inline constexpr int kColorSlot = 2;
inline constexpr int kPositionSlot = 6;
inline constexpr int kNormalSlot = 9;
inline constexpr int kTangentSlot = 12;
inline constexpr int kUnlitVaryings = 6;                // texture coordinate and color
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
  return u.use_vertex_colors ? u.base_color * in.color : u.base_color;
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
  if constexpr (kCount > kPositionSlot) {
    store(out + kPositionSlot, glm::vec3(u.model * glm::vec4(in.position, 1.0f)));
    store(out + kNormalSlot, in.normal);
  }
  if constexpr (kCount > kTangentSlot) store(out + kTangentSlot, in.tangent);
}

// Samples a texture map at the fragment's texture coordinate, with the level of detail from
// the coordinate's exact screen-space derivatives.
glm::vec4 sample_map(const TextureMap& map, const Fragment& f);

struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 normal;  // unit, normal map applied, facing the viewer for two-sided materials
  glm::vec3 view;    // unit, toward the eye
  glm::vec4 albedo;  // color x base color map
};

// The lit models' common start. kWithTangent: the layout holds tangents (normal mapping).
template <bool kWithTangent>
SurfacePoint surface_point(const Fragment& f, const DrawUniforms& u);

// Emissive light of the material (factor x map).
glm::vec3 emission(const Fragment& f, const DrawUniforms& u);

}  // namespace facet::shading
