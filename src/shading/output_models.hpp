// The shading models of the extra outputs (facet/framebuffer.hpp's ExtraOutputs). Each writes
// data, not light, four floats a pixel into a float target: one pass over the frame's draws per
// model (pipeline/output_passes.cpp). The fourth float is the surface's alpha, which the pass of
// a cut-out (masked) draw tests as color does: kMasked models interpolate the unlit layout
// (surface.hpp) for it ahead of their own varyings.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <type_traits>

#include "shading/fragment.hpp"
#include "shading/surface.hpp"
#include "shading/uniforms.hpp"

namespace facet::shading {

// Ids above this are not exact in a float channel (2^24).
inline constexpr std::uint32_t kMaxExactId = 1u << 24;

// What a model of the extra outputs shares: the alpha it cuts out at, when kMasked.
template <bool kMasked>
struct OutputModel {
  static constexpr int kFirstSlot = kMasked ? kUnlitVaryings : 0;  // the model's own varyings
  static constexpr int kNormalSlot = -1;
  static constexpr bool kWritesData = true;  // every channel is the output's (pixel_writer.hpp)

  static void alpha_vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    if constexpr (kMasked) surface_vertex<kUnlitVaryings>(in, u, out);
  }
  static float alpha(const Fragment& f, const DrawUniforms& u) {
    if constexpr (!kMasked) return 1.0f;
    float a = f.v[kColorSlot + 3];
    if (u.material->base_color_map) a *= base_color_texel(f).a;
    return a;
  }
};
// Masked models have their base color map sampled ahead, as the color models do.
struct SamplesBaseColorAhead {
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
};
struct NoBaseColorAhead {};
template <bool kMasked>
using OutputBase = std::conditional_t<kMasked, SamplesBaseColorAhead, NoBaseColorAhead>;

// (distance along the view axis, distance from the eye along the ray, instance id, alpha), from
// the view-space position. An orthographic camera's rays start on the image plane: its ray
// distance is the view depth.
template <bool kMasked>
struct DepthAndInstanceOutput : OutputModel<kMasked>, OutputBase<kMasked> {
  using Base = OutputModel<kMasked>;
  static constexpr int kViewPositionSlot = Base::kFirstSlot;
  static constexpr int kVaryings = kViewPositionSlot + 3;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    Base::alpha_vertex(in, u, out);
    const glm::vec4 world = u.model * glm::vec4(in.position, 1.0f);
    store(out + kViewPositionSlot, glm::vec3(u.frame->view * world));
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const glm::vec3 p = load3(f.v + kViewPositionSlot);
    const float distance = u.frame->orthographic ? -p.z : glm::length(p);
    return {-p.z, distance, static_cast<float>(u.instance_id), Base::alpha(f, u)};
  }
};

// (x, y, z, alpha): the interpolated normal, renormalized, in world space or (kCamera) the
// camera's view space. Meshes without normals get their face normals (kNormalSlot).
template <bool kMasked, bool kCamera>
struct NormalOutput : OutputModel<kMasked>, OutputBase<kMasked> {
  using Base = OutputModel<kMasked>;
  static constexpr int kNormalSlot = Base::kFirstSlot;
  static constexpr int kVaryings = kNormalSlot + 3;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    Base::alpha_vertex(in, u, out);
    store(out + kNormalSlot, in.normal);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    glm::vec3 n = safe_normalize(load3(f.v + kNormalSlot));
    if constexpr (kCamera) n = safe_normalize(glm::mat3(u.frame->view) * n);
    return {n, Base::alpha(f, u)};
  }
};

// (triangle index + 1, barycentric of the second vertex, of the third, alpha). The per-triangle
// hook writes the corners' barycentrics, (0, 0), (1, 0) and (0, 1), which clipping
// and interpolation carry to every pixel perspective-correct, and the index in two 12-bit
// halves: a constant interpolated comes back within a small fraction of itself, which rounds
// to the exact integer for values below 2^12, not for ids of 24 bits.
template <bool kMasked>
struct TriangleOutput : OutputModel<kMasked>, OutputBase<kMasked> {
  using Base = OutputModel<kMasked>;
  static constexpr int kBarycentricSlot = Base::kFirstSlot;  // second and third vertex's
  static constexpr int kIdSlot = kBarycentricSlot + 2;       // low 12 bits, high 12 bits
  static constexpr int kVaryings = kIdSlot + 2;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    Base::alpha_vertex(in, u, out);
    for (int k = kBarycentricSlot; k < kVaryings; ++k) out[k] = 0.0f;
  }
  static void triangle(std::uint32_t index, float* v[3]) {
    const std::uint32_t id = index + 1;
    for (int corner = 0; corner < 3; ++corner) {
      v[corner][kBarycentricSlot] = corner == 1 ? 1.0f : 0.0f;
      v[corner][kBarycentricSlot + 1] = corner == 2 ? 1.0f : 0.0f;
      v[corner][kIdSlot] = static_cast<float>(id & 0xfffu);
      v[corner][kIdSlot + 1] = static_cast<float>(id >> 12);
    }
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    const float id = std::round(f.v[kIdSlot + 1]) * 4096.0f + std::round(f.v[kIdSlot]);
    return {id, f.v[kBarycentricSlot], f.v[kBarycentricSlot + 1], Base::alpha(f, u)};
  }
};

// Linear RGBA: base color x vertex color x base color map, no light and no emission.
struct AlbedoOutput : SamplesBaseColorAhead {
  static constexpr int kVaryings = kUnlitVaryings;
  static constexpr int kNormalSlot = -1;
  static constexpr bool kWritesData = true;  // its alpha is the material's, opaque or not
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    surface_vertex<kUnlitVaryings>(in, u, out);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms& u) {
    glm::vec4 color = load4(f.v + kColorSlot);
    if (u.material->base_color_map) color *= base_color_texel(f);
    return color;
  }
};

}  // namespace facet::shading
