// Batch vertex lighting of the Gouraud model (see vertex_batch.hpp). Highway compiles this file
// once per SIMD target (foreach_target.h re-includes it); the frame fetches the chosen target's
// kernel (pipeline/kernels.hpp). Each step repeats the Gouraud models' vertex() with the same IEEE
// operations in the same order (glm's mat4 x vec4 is (m0 x + m1 y) + (m2 z + m3 w); no fused
// multiply-add), so every target gives its bits; vertex_batch_test checks it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/vertex_batch.cpp"
#include "shading/vertex_batch.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cstring>

#include "shading/batch_math-inl.h"
#include "shading/lighting.hpp"
#include "shading/shadow_batch-inl.h"
#include "shading/surface.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void GouraudVertexBatch(const DrawUniforms& u, const VertexBatchInput& in, GouraudLayout layout,
                        float (*out)[kVertexBatch]) {
  const BatchTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const glm::mat4& m = u.model;
  const Material& material = *u.material;
  const Vec3V eye = Set3(u.frame->eye);
  for (int j = 0; j < in.count; j += lanes) {
    // glm::vec3(u.model * glm::vec4(position, 1)), the positions a vector of each axis (the
    // last few zero-padded: computed, then ignored).
    BatchV x, y, z;
    if (j + lanes <= in.count) {
      hn::LoadInterleaved3(d, &in.positions[j].x, x, y, z);
    } else {
      alignas(64) float padded[3 * kVertexBatch] = {};
      std::memcpy(padded, &in.positions[j], (in.count - j) * sizeof(glm::vec3));
      hn::LoadInterleaved3(d, padded, x, y, z);
    }
    BatchV world[3];
    for (int c = 0; c < 3; ++c) {
      world[c] = hn::Add(hn::Add(hn::Mul(hn::Set(d, m[0][c]), x), hn::Mul(hn::Set(d, m[1][c]), y)),
                         hn::Add(hn::Mul(hn::Set(d, m[2][c]), z), hn::Set(d, m[3][c] * 1.0f)));
    }
    // light_vertex().
    const Vec3V normal{hn::Load(d, in.normal[0] + j), hn::Load(d, in.normal[1] + j),
                       hn::Load(d, in.normal[2] + j)};
    const Vec3V view = SafeNormalize(
        {hn::Sub(eye.x, world[0]), hn::Sub(eye.y, world[1]), hn::Sub(eye.z, world[2])});
    BatchV diffuse[3] = {hn::Set(d, u.frame->ambient.x), hn::Set(d, u.frame->ambient.y),
                         hn::Set(d, u.frame->ambient.z)};
    BatchV specular[3] = {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
    for (int i = 0; i < u.frame->light_count; ++i) {
      const LightData& l = u.frame->lights[i];  // directional: incident() is to_light and radiance
      const Vec3V to_light = Set3(l.to_light);
      const BatchV n_dot_l = Dot(normal, to_light);
      const auto lit = hn::Not(hn::Le(n_dot_l, hn::Zero(d)));  // the scalar loop's continue
      // blinn_phong_specular(): the half vector, then the power.
      const Vec3V half = Normalize(
          {hn::Add(to_light.x, view.x), hn::Add(to_light.y, view.y), hn::Add(to_light.z, view.z)});
      const BatchV highlight =
          material.shininess == 0.0f
              ? hn::Set(d, 1.0f)
              : PortablePow(StdMax(Dot(normal, half), hn::Zero(d)), material.shininess);
      // received_radiance(): the radiance after the light's shadow at the vertex.
      BatchV visibility = hn::Set(d, 1.0f);
      if (l.shadow) {
        const auto active = hn::FirstN(d, static_cast<std::size_t>(in.count - j));
        visibility = ShadowVisibility(*l.shadow, {world[0], world[1], world[2]}, normal,
                                      hn::And(lit, active));
      }
      for (int c = 0; c < 3; ++c) {
        const BatchV radiance = hn::Set(d, l.radiance[c]);
        if (l.shadow) {  // (radiance x visibility) x specular color x highlight
          const BatchV received = hn::Mul(radiance, visibility);
          diffuse[c] =
              hn::IfThenElse(lit, hn::Add(diffuse[c], hn::Mul(received, n_dot_l)), diffuse[c]);
          const BatchV tint = hn::Mul(received, hn::Set(d, material.specular_color[c]));
          specular[c] =
              hn::IfThenElse(lit, hn::Add(specular[c], hn::Mul(tint, highlight)), specular[c]);
          continue;
        }
        diffuse[c] =
            hn::IfThenElse(lit, hn::Add(diffuse[c], hn::Mul(radiance, n_dot_l)), diffuse[c]);
        const BatchV tint = hn::Set(d, l.radiance[c] * material.specular_color[c]);
        specular[c] =
            hn::IfThenElse(lit, hn::Add(specular[c], hn::Mul(tint, highlight)), specular[c]);
      }
    }
    for (int c = 0; c < 3; ++c) {
      hn::Store(diffuse[c], d, out[layout.diffuse + c] + j);
      hn::Store(specular[c], d, out[layout.diffuse + 3 + c] + j);
    }
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

bool gouraud_batches_vertices(const DrawUniforms& u) {
  return only_directional_lights(u) && only_orthographic_shadows(u);
}

GouraudVertexBatchKernel gouraud_vertex_batch_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(GouraudVertexBatch)[target];
}

}  // namespace facet::shading
#endif  // HWY_ONCE
