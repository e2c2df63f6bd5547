// Batch vertex lighting of the Gouraud models (see vertex_batch.hpp). Highway compiles this file
// once per SIMD target (foreach_target.h re-includes it); the frame fetches the chosen target's
// kernels (pipeline/kernels.hpp). Each step is written once, lane by lane, with the same IEEE
// operations in the same order on every target (glm's mat4 x vec4 is (m0 x + m1 y) + (m2 z + m3 w);
// no fused multiply-add), so every target gives the same bits; vertex_batch_test checks it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/vertex_batch.cpp"
#include "shading/vertex_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cstring>

#include "shading/batch_math-inl.h"
#include "shading/light_batch-inl.h"
#include "shading/shadow_batch-inl.h"
#include "shading/surface.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The light at a vector of world positions p of unit normals n: the ambient light, then for each
// light that the side of the normal faces (n . l > 0), its radiance after its shadow (looked up in
// the lanes of `active` only) times n . l as diffuse light, and times the material's specular
// color and the Blinn-Phong highlight (max(0, n . h)^shininess, h the half vector) as specular
// light. Under gray light (GouraudLayout) the red channel alone, without the ambient light.
HWY_INLINE void LightVertices(const DrawUniforms& u, const Vec3V& p, const Vec3V& n,
                              BatchMask active, BatchV diffuse[3], BatchV specular[3],
                              bool gray = false) {
  const int channels = gray ? 1 : 3;
  const BatchTag d;
  const Material& material = *u.material;
  const Vec3V eye = Set3(u.frame->eye);
  const Vec3V view = SafeNormalize({hn::Sub(eye.x, p.x), hn::Sub(eye.y, p.y), hn::Sub(eye.z, p.z)});
  for (int c = 0; c < 3; ++c) {
    diffuse[c] = gray ? hn::Zero(d) : hn::Set(d, u.frame->ambient[c]);
    specular[c] = hn::Zero(d);
  }
  for (int i = 0; i < u.frame->light_count; ++i) {
    const LightData& light = u.frame->lights[i];
    const IncidentV in = Incident(light, p);
    const BatchV n_dot_l = Dot(n, in.direction);
    const BatchMask lit = hn::Not(hn::Le(n_dot_l, hn::Zero(d)));  // NaN lights nothing either
    const Vec3V received = ReceivedRadiance(light, in, p, n, hn::And(lit, active));
    const BatchV highlight = Highlight(material, true, n, view, in.direction);
    const BatchV radiance[3] = {received.x, received.y, received.z};
    for (int c = 0; c < channels; ++c) {
      diffuse[c] =
          hn::IfThenElse(lit, hn::Add(diffuse[c], hn::Mul(radiance[c], n_dot_l)), diffuse[c]);
      // (radiance x specular color) x highlight.
      const BatchV tint = hn::Mul(radiance[c], hn::Set(d, material.specular_color[c]));
      specular[c] =
          hn::IfThenElse(lit, hn::Add(specular[c], hn::Mul(tint, highlight)), specular[c]);
    }
  }
}

// The vectors v[j], v[j + 1], ... of count, a vector of each axis; the lanes past count zero
// (computed, then ignored).
HWY_INLINE Vec3V LoadVec3s(const glm::vec3* v, int j, int count) {
  const BatchTag d;
  constexpr std::size_t kLanes = hn::MaxLanes(d);
  Vec3V out;
  if (j + static_cast<int>(hn::Lanes(d)) <= count) {
    hn::LoadInterleaved3(d, &v[j].x, out.x, out.y, out.z);
  } else {
    alignas(64) float padded[3 * kLanes] = {};
    std::memcpy(padded, &v[j], (count - j) * sizeof(glm::vec3));
    hn::LoadInterleaved3(d, padded, out.x, out.y, out.z);
  }
  return out;
}

// Lights the vector of points from j on and stores the light at out[first..first + 5] + j, or
// under gray light (GouraudLayout) its red channel's, without the ambient light, at
// out[first..first + 1] + j; without the lights' shadows unless `shadows`.
HWY_INLINE void LightAndStore(const DrawUniforms& u, const Vec3V& p, const Vec3V& n, int j,
                              int count, int first, float (*out)[kVertexBatch], bool shadows = true,
                              bool gray = false) {
  const BatchTag d;
  BatchV diffuse[3], specular[3];
  const BatchMask active = shadows ? hn::FirstN(d, static_cast<std::size_t>(count - j))
                                   : hn::FirstN(d, 0);  // no lane looks a shadow up
  LightVertices(u, p, n, active, diffuse, specular, gray);
  if (gray) {
    hn::Store(diffuse[0], d, out[first] + j);
    hn::Store(specular[0], d, out[first + 1] + j);
    return;
  }
  for (int c = 0; c < 3; ++c) {
    hn::Store(diffuse[c], d, out[first + c] + j);
    hn::Store(specular[c], d, out[first + 3 + c] + j);
  }
}

void GouraudLightBatch(const DrawUniforms& u, const WorldPoints& in, float (*out)[kVertexBatch]) {
  const int lanes = static_cast<int>(hn::Lanes(BatchTag()));
  for (int j = 0; j < in.count; j += lanes) {
    LightAndStore(u, LoadVec3s(in.positions, j, in.count), LoadVec3s(in.normals, j, in.count), j,
                  in.count, 0, out, in.shadows, in.gray);
  }
}

void GouraudVertexBatch(const DrawUniforms& u, const VertexBatchInput& in, GouraudLayout layout,
                        float (*out)[kVertexBatch]) {
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const glm::mat4& m = u.model;
  for (int j = 0; j < in.count; j += lanes) {
    // glm::vec3(u.model * glm::vec4(position, 1)).
    const Vec3V object = LoadVec3s(in.positions, j, in.count);
    BatchV world[3];
    for (int c = 0; c < 3; ++c) {
      world[c] = hn::Add(
          hn::Add(hn::Mul(hn::Set(d, m[0][c]), object.x), hn::Mul(hn::Set(d, m[1][c]), object.y)),
          hn::Add(hn::Mul(hn::Set(d, m[2][c]), object.z), hn::Set(d, m[3][c] * 1.0f)));
    }
    const Vec3V normal{hn::Load(d, in.normal[0] + j), hn::Load(d, in.normal[1] + j),
                       hn::Load(d, in.normal[2] + j)};
    LightAndStore(u, {world[0], world[1], world[2]}, normal, j, in.count, layout.diffuse, out, true,
                  layout.gray);
  }
  if (!layout.with_surface) return;
  // The texture coordinate and material_color(): copies and one product, per vertex.
  VertexInput vertex;
  for (int n = 0; n < in.count; ++n) {
    const glm::vec2 texcoord = in.texcoords ? in.texcoords[n] : glm::vec2(0.0f);
    out[kTexcoordSlot][n] = texcoord.x;
    out[kTexcoordSlot + 1][n] = texcoord.y;
    vertex.color = in.colors ? in.colors[n] : glm::vec4(1.0f);  // white without vertex colors
    const glm::vec4 color = material_color(vertex, u);
    for (int c = 0; c < 4; ++c) out[kColorSlot + c][n] = color[c];
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::shading {

HWY_EXPORT(GouraudVertexBatch);
HWY_EXPORT(GouraudLightBatch);

GouraudVertexBatchKernel gouraud_vertex_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(GouraudVertexBatch)[target];
}

GouraudLightBatchKernel gouraud_light_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(GouraudLightBatch)[target];
}

}  // namespace facet::shading
#endif  // HWY_ONCE
