// The built-in shading models as C++ types. The raster loop (pipeline/raster.cpp) is a
// template over these, chosen once per draw, so the per-pixel code has no virtual calls and
// no branches on material settings.
//
// A shading model provides:
//   kVaryings       floats it passes from vertex to fragment (interpolated perspective-correct)
//   kNormalSlot     index of a world normal in its varyings (or -1): filled with the face
//                   normal when the mesh has no normals
//   vertex(in, uniforms, out)          per vertex: writes kVaryings floats
//   face(face_normal, uniforms, v[3])  optional, per triangle before clipping: may rewrite
//                                      the three vertices' varyings (flat shading)
//   fragment(varyings, view_depth, uniforms) -> linear RGBA
#pragma once

#include <algorithm>
#include <glm/glm.hpp>

#include "shading/color.hpp"
#include "shading/uniforms.hpp"

namespace facet::shading {

inline glm::vec4 material_color(const VertexInput& in, const DrawUniforms& u) {
  return u.use_vertex_colors ? u.base_color * in.color : u.base_color;
}

// Diffuse + ambient from the directional lights (the classic teaching setup).
// Point and spot lights need a position; models without one light as if from infinitely far.
inline glm::vec3 lambert_light(glm::vec3 albedo, glm::vec3 unit_normal, const DrawUniforms& u) {
  glm::vec3 light = u.ambient;
  for (int i = 0; i < u.light_count; ++i) {
    float n_dot_l = std::max(0.0f, glm::dot(unit_normal, u.lights[i].to_light));
    light += u.lights[i].radiance * n_dot_l;
  }
  return albedo * light;
}

inline void store(float* out, glm::vec4 v) {
  out[0] = v.r, out[1] = v.g, out[2] = v.b, out[3] = v.a;
}
inline void store(float* out, glm::vec3 v) { out[0] = v.x, out[1] = v.y, out[2] = v.z; }
inline glm::vec4 load4(const float* in) { return {in[0], in[1], in[2], in[3]}; }
inline glm::vec3 load3(const float* in) { return {in[0], in[1], in[2]}; }

// base color x vertex color, no lighting.
struct UnlitShading {
  static constexpr int kVaryings = 4;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    store(out, material_color(in, u));
  }
  static glm::vec4 fragment(const float* v, float, const DrawUniforms&) { return load4(v); }
};

// The mesh's vertex colors only (white where it has none).
struct VertexColorShading : UnlitShading {
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    store(out, in.color);
  }
};

// One lit color per triangle from its face normal: the face hook lights the triangle's
// average color and writes it to all three vertices, so interpolation keeps it constant.
struct FlatShading : UnlitShading {
  static void face(glm::vec3 face_normal, const DrawUniforms& u, float* v[3]) {
    glm::vec4 average = (load4(v[0]) + load4(v[1]) + load4(v[2])) / 3.0f;
    glm::vec4 lit{lambert_light(glm::vec3(average), face_normal, u), average.a};
    for (int i = 0; i < 3; ++i) store(v[i], lit);
  }
};

// Per-pixel Lambert: the interpolated normal is renormalized and lit at each pixel.
struct LambertShading {
  static constexpr int kVaryings = 7;  // normal xyz, color rgba
  static constexpr int kNormalSlot = 0;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    store(out, in.normal);
    store(out + 3, material_color(in, u));
  }
  static glm::vec4 fragment(const float* v, float, const DrawUniforms& u) {
    glm::vec3 n = load3(v);
    float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f);
    glm::vec4 albedo = load4(v + 3);
    return {lambert_light(glm::vec3(albedo), n, u), albedo.a};
  }
};

// Lambert with the triangle edges drawn on top (the raster loop draws them; raster.hpp).
struct WireOverlayShading : LambertShading {
  static constexpr bool kEdgeOverlay = true;
};

// Debug view: linear view depth, near -> white, far -> black. The gray is written so that
// the sRGB encode at resolve gives back the linear ramp (the view shows distance, not light).
struct DepthShading {
  static constexpr int kVaryings = 0;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput&, const DrawUniforms&, float*) {}
  static glm::vec4 fragment(const float*, float view_depth, const DrawUniforms& u) {
    float t = (view_depth - u.near_plane) / (u.far_plane - u.near_plane);
    float gray = srgb_to_linear(std::clamp(1.0f - t, 0.0f, 1.0f));
    return {gray, gray, gray, 1.0f};
  }
};

// Debug view: world-space normal, renormalized per pixel, shown as n * 0.5 + 0.5 without
// sRGB encoding (pre-decoded here so that resolve's encode writes the value itself).
struct NormalsShading {
  static constexpr int kVaryings = 3;
  static constexpr int kNormalSlot = 0;
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    store(out, in.normal);
  }
  static glm::vec4 fragment(const float* v, float, const DrawUniforms&) {
    glm::vec3 n = load3(v);
    float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f);
    glm::vec3 shown = n * 0.5f + 0.5f;
    return {srgb_to_linear(shown.x), srgb_to_linear(shown.y), srgb_to_linear(shown.z), 1.0f};
  }
};

// Debug counter: every covered pixel centre adds 1 to red, with no depth test, so a float
// target holds how many times each pixel was hit (fill-rule tests, overdraw heat maps).
struct OverdrawCountShading {
  static constexpr int kVaryings = 0;
  static constexpr int kNormalSlot = -1;
  static constexpr bool kDepthTest = false;
  static constexpr bool kAdditive = true;
  static void vertex(const VertexInput&, const DrawUniforms&, float*) {}
  static glm::vec4 fragment(const float*, float, const DrawUniforms&) { return {1, 0, 0, 0}; }
};

}  // namespace facet::shading
