// Shadowed draws on the SIMD batch paths: the batch kernels of the models lit per pixel
// (shade_batch.cpp) and the Gouraud models' vertex batch (vertex_batch.cpp), with their shadow
// lookup (shadow_batch-inl.h), give fragment()'s and vertex()'s bits on every SIMD target, for
// random points and normals against random depth maps of a sun with one or three cascades:
// points inside a map, partly over its edges, outside it and beyond its far plane; and the batch
// forms decline what they leave to the scalar models.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "shading/kernels.hpp"
#include "shading/lit_models.hpp"
#include "shading/models.hpp"
#include "shading/shadow_map.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using shading::kShadeBatch;
using shading::ShadowMaps;

// A sun's maps over a scene about the origin: each an orthographic view along `travel`, the
// cascades nested (each twice as wide as the one before), of random depths: occluders of 6 x 6
// texels at depths between 0.3 and 0.7, where the receivers are, give or take a little per
// texel, or nothing drawn (1), one in five.
struct Sun {
  glm::vec3 travel{0.0f};
  std::vector<float> depth[shading::kMaxShadowCascades];
  ShadowMaps maps;
};

void make_sun(std::mt19937& rng, int cascades, int size, Sun& sun) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), depth(0.3f, 0.7f);
  sun.travel = glm::normalize(glm::vec3(any(rng), -1.5f, any(rng)));
  const glm::vec3 up = std::abs(sun.travel.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::mat4 view = glm::lookAt(-20.0f * sun.travel, glm::vec3(0.0f), up);
  const float s = static_cast<float>(size);
  glm::mat4 to_map(1.0f);  // as pipeline/shadow/shadow_passes.cpp's shadow_map_of
  to_map[0][0] = 0.5f * s, to_map[3][0] = 0.5f * s - 0.5f;
  to_map[1][1] = -0.5f * s, to_map[3][1] = 0.5f * s - 0.5f;
  to_map[2][2] = 0.5f, to_map[3][2] = 0.5f;
  sun.maps.count = cascades;
  for (int c = 0; c < cascades; ++c) {
    const float half = 3.0f * static_cast<float>(1 << c);
    const glm::mat4 projection = glm::ortho(-half, half, -half, half, 1.0f, 40.0f);
    std::vector<float>& texels = sun.depth[c];
    texels.resize(static_cast<std::size_t>(size) * size);
    constexpr int kOccluder = 6;
    const int occluders = (size + kOccluder - 1) / kOccluder;
    std::vector<float> occluder(static_cast<std::size_t>(occluders) * occluders);
    for (float& o : occluder) o = rng() % 5 == 0 ? 1.0f : depth(rng);
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const float o = occluder[(y / kOccluder) * occluders + x / kOccluder];
        texels[static_cast<std::size_t>(y) * size + x] = o == 1.0f ? o : o + 0.02f * any(rng);
      }
    }
    sun.maps.maps[c] =
        shading::make_shadow_map(to_map * projection * view, texels.data(), size, false);
  }
}

// A random point of cascade `c`'s map: mostly near it (its edges included), now and then far
// outside it or beyond its far plane.
glm::vec3 random_point(std::mt19937& rng, const Sun& sun, int c) {
  const shading::ShadowMap& map = sun.maps.maps[c];
  const float size = static_cast<float>(map.size);
  std::uniform_real_distribution<float> across(-6.0f, size + 6.0f), edge(-3.0f, 3.0f),
      depth(0.25f, 0.75f), beyond(1.0f, 1.3f), far(-1e6f, 1e6f);
  glm::vec3 m(across(rng), across(rng), depth(rng));
  switch (rng() % 16) {
    case 0:  // far outside the map, now and then beyond 2^23 texels (no fraction left)
      m.x = far(rng), m.y = far(rng);
      if (rng() % 2) m.x *= 1000.0f;
      break;
    case 1:  // beyond the far plane
      m.z = beyond(rng);
      break;
    case 2:
    case 3:  // the footprint over an edge or a corner
      m.x = (rng() % 2 ? size : 0.0f) + edge(rng);
      if (rng() % 2) m.y = (rng() % 2 ? size : 0.0f) + edge(rng);
      break;
    default:
      break;
  }
  return glm::vec3(glm::inverse(map.world_to_map) * glm::vec4(m, 1.0f));
}

// A random normal: any direction and length (the models normalize it), toward the light,
// across the light ray (a receiver-plane slope beyond the clamp), or none.
glm::vec3 random_normal(std::mt19937& rng, const Sun& sun) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), length(0.5f, 2.0f);
  switch (rng() % 8) {
    case 0:
      return glm::vec3(0.0f);
    case 1:
      return -sun.travel * length(rng);
    case 2:
      return glm::cross(sun.travel, glm::vec3(any(rng), any(rng), any(rng)));
    default:
      return glm::vec3(any(rng), any(rng), any(rng)) * length(rng);
  }
}

// The view the cascades split: their far depths at a third and two thirds of the points'.
void split_cascades(std::mt19937& rng, const std::vector<glm::vec3>& points, Sun& sun) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f);
  sun.maps.eye = {any(rng) * 10.0f, 5.0f, any(rng) * 10.0f};
  sun.maps.forward = glm::normalize(-sun.maps.eye + glm::vec3(any(rng), 0.0f, any(rng)));
  std::vector<float> depths;
  for (const glm::vec3& p : points) depths.push_back(glm::dot(p - sun.maps.eye, sun.maps.forward));
  std::sort(depths.begin(), depths.end());
  for (int c = 0; c < sun.maps.count; ++c) {
    sun.maps.far_depth[c] = depths[(depths.size() - 1) * (c + 1) / sun.maps.count];
  }
}

// What the scalar lookup gives the points: fully lit, fully shadowed or in between, from
// footprints inside a map and partly over its edges. Each kind must be compared.
struct Seen {
  int lit = 0, shadowed = 0, partly = 0, partly_at_edge = 0;
  void add(const ShadowMaps& maps, glm::vec3 p, glm::vec3 n) {
    const float v = shading::shadow_visibility(maps, p, shading::safe_normalize(n));
    if (v == 1.0f) ++lit;
    if (v == 0.0f) ++shadowed;
    if (v <= 0.0f || v >= 1.0f) return;
    ++partly;
    const float depth = glm::dot(p - maps.eye, maps.forward);
    int c = 0;
    while (c + 1 < maps.count && depth > maps.far_depth[c]) ++c;
    const glm::vec4 m = maps.maps[c].world_to_map * glm::vec4(p, 1.0f);
    const float size = static_cast<float>(maps.maps[c].size);
    if (m.x < 2.0f || m.y < 2.0f || m.x >= size - 2.0f || m.y >= size - 2.0f) ++partly_at_edge;
  }
  void expect_each_kind() const {
    EXPECT_GT(lit, 50);
    EXPECT_GT(shadowed, 50);
    EXPECT_GT(partly, 50);
    EXPECT_GT(partly_at_edge, 10);
  }
};

struct Draw {
  Material material;
  Lighting lighting;
  shading::LightData lights[2];
  shading::ShadingKernels kernels;
  shading::FrameUniforms frame;
  shading::DrawUniforms uniforms;
};

// One or two directional lights, the first the sun casting through `maps`, the second
// (when there) unshadowed or casting too.
void make_draw(std::mt19937& rng, const Sun& sun, Draw& d) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), unit(0.0f, 1.0f);
  d.uniforms.material = &d.material;
  d.uniforms.frame = &d.frame;
  d.kernels = shading::shading_kernels(chosen_simd_target());  // the forced target's
  d.frame.kernels = &d.kernels;
  d.frame.lighting = &d.lighting;
  d.frame.eye = {any(rng) * 5.0f, any(rng) * 5.0f, any(rng) * 5.0f};
  d.frame.ambient = {unit(rng) * 0.2f, unit(rng) * 0.2f, unit(rng) * 0.2f};
  d.frame.light_count = 1 + static_cast<int>(rng() % 2);
  d.lights[0].to_light = -sun.travel;
  d.lights[0].shadow = &sun.maps;
  d.lights[1].to_light = glm::normalize(glm::vec3(any(rng), any(rng), any(rng)) + 0.01f);
  d.lights[1].shadow = rng() % 2 ? &sun.maps : nullptr;
  for (shading::LightData& light : d.lights) {
    light.radiance = {0.5f + unit(rng) * 3.0f, 0.5f + unit(rng) * 3.0f, 0.5f + unit(rng) * 3.0f};
  }
  d.frame.lights = d.lights;
  d.material.cull = rng() % 2 ? CullMode::none : CullMode::back;
  d.material.base_color = {0.2f + unit(rng), 0.2f + unit(rng), 0.2f + unit(rng), 1.0f};
  d.material.specular_color = {unit(rng), unit(rng), unit(rng)};
  d.material.shininess = rng() % 5 == 0 ? 0.0f : 1.0f + unit(rng) * 127.0f;
}

constexpr int kRounds = 30;

// Pixel n of varyings v shaded as the draw without shadows, each shadowed light's radiance
// scaled by the scalar shadow_visibility at the pixel: what the batch kernel gives the shadowed
// draw if its lookup gives shadow_visibility's bits (received_radiance is radiance x visibility).
template <class Shading>
glm::vec4 unshadowed_with_scalar_visibility(const Draw& shadowed, const float (*v)[kShadeBatch],
                                            int n) {
  Draw d = shadowed;
  d.uniforms.material = &d.material;
  d.uniforms.frame = &d.frame;
  d.frame.kernels = &d.kernels;
  d.frame.lighting = &d.lighting;
  d.frame.lights = d.lights;
  alignas(64) float one[shading::kMaxVaryings][kShadeBatch] = {};
  for (int k = 0; k < shading::kMaxVaryings; ++k) one[k][0] = v[k][n];
  const glm::vec3 p(v[shading::kPositionSlot][n], v[shading::kPositionSlot + 1][n],
                    v[shading::kPositionSlot + 2][n]);
  const glm::vec3 normal = shading::safe_normalize(
      {v[shading::kNormalSlot][n], v[shading::kNormalSlot + 1][n], v[shading::kNormalSlot + 2][n]});
  for (shading::LightData& light : d.lights) {
    if (light.shadow == nullptr) continue;
    light.radiance = light.radiance * shading::shadow_visibility(*light.shadow, p, normal);
    light.shadow = nullptr;
  }
  alignas(64) float w[kShadeBatch] = {1.0f}, z[kShadeBatch] = {};
  alignas(64) float rgba[kShadeBatch][4];
  Shading::fragment_batch(d.uniforms, {1, w, z, one, nullptr, &d.lighting.fog}, rgba);
  return {rgba[0][0], rgba[0][1], rgba[0][2], rgba[0][3]};
}

// Compares Shading::fragment_batch on shadowed draws with the same draws unshadowed but for the
// scalar shadow_visibility (unshadowed_with_scalar_visibility) over random batches, on every
// SIMD target, with one and three cascades.
template <class Shading>
void expect_fragments_bits() {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), w(0.2f, 50.0f);
  Seen seen;
  int compared = 0;
  for (std::int64_t target : targets) {
    ForcedTarget forced(target);
    for (int round = 0; round < kRounds; ++round) {
      Sun sun;
      make_sun(rng, round % 2 == 0 ? 1 : 3, round % 3 == 0 ? 16 : 40, sun);
      alignas(64) float in_w[kShadeBatch], in_z[kShadeBatch];
      alignas(64) float v[shading::kMaxVaryings][kShadeBatch];
      std::vector<glm::vec3> points(kShadeBatch), normals(kShadeBatch);
      for (int n = 0; n < kShadeBatch; ++n) {
        points[n] = random_point(rng, sun, static_cast<int>(rng() % sun.maps.count));
        normals[n] = random_normal(rng, sun);
        in_w[n] = w(rng), in_z[n] = unit(rng);
        for (int k = 0; k < shading::kMaxVaryings; ++k) v[k][n] = unit(rng);
        for (int c = 0; c < 3; ++c) {
          v[shading::kPositionSlot + c][n] = points[n][c];
          v[shading::kNormalSlot + c][n] = normals[n][c];
        }
      }
      split_cascades(rng, points, sun);
      Draw draw;
      make_draw(rng, sun, draw);
      const int count = round % 4 == 0 ? kShadeBatch : 1 + static_cast<int>(rng() % kShadeBatch);
      alignas(64) float rgba[kShadeBatch][4];
      const shading::ShadeInput input{count, in_w, in_z, v, nullptr, &draw.lighting.fog};
      Shading::fragment_batch(draw.uniforms, input, rgba);
      for (int n = 0; n < count; ++n) {
        const glm::vec4 expected = unshadowed_with_scalar_visibility<Shading>(draw, v, n);
        ASSERT_EQ(std::memcmp(&expected, rgba[n], sizeof expected), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel " << n << ": ("
            << rgba[n][0] << ", " << rgba[n][1] << ", " << rgba[n][2] << "), fragment() gives ("
            << expected.r << ", " << expected.g << ", " << expected.b << "), visibility "
            << shading::shadow_visibility(sun.maps, points[n], shading::safe_normalize(normals[n]));
        seen.add(sun.maps, points[n], normals[n]);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 500 * static_cast<int>(targets.size()));
  seen.expect_each_kind();
}

TEST(ShadowBatch, LambertGivesFragmentsBitsOnEveryTarget) {
  expect_fragments_bits<shading::LambertShading>();
}

TEST(ShadowBatch, PhongAndBlinnPhongGiveFragmentsBitsOnEveryTarget) {
  expect_fragments_bits<shading::PhongShading>();
  expect_fragments_bits<shading::BlinnPhongShading>();
}

// The Gouraud models look the shadow up per vertex: their vertex batch against vertex().
template <class Model>
void expect_vertexs_bits() {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Seen seen;
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int round = 0; round < kRounds; ++round) {
      Sun sun;
      make_sun(rng, round % 2 == 0 ? 1 : 3, round % 3 == 0 ? 16 : 40, sun);
      Draw draw;
      const int count = 1 + static_cast<int>(rng() % shading::kVertexBatch);
      // World positions through a model transform: object positions from the random points.
      draw.uniforms.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, -0.25f, 1.0f));
      const glm::mat4 to_object = glm::inverse(draw.uniforms.model);
      std::vector<glm::vec3> positions(count), points(count);
      alignas(64) float normal[3][shading::kVertexBatch] = {};
      for (int n = 0; n < count; ++n) {
        points[n] = random_point(rng, sun, static_cast<int>(rng() % sun.maps.count));
        positions[n] = glm::vec3(to_object * glm::vec4(points[n], 1.0f));
        const glm::vec3 nv = shading::safe_normalize(random_normal(rng, sun));  // unit, or none
        for (int c = 0; c < 3; ++c) normal[c][n] = nv[c];
      }
      split_cascades(rng, points, sun);
      make_draw(rng, sun, draw);
      ASSERT_TRUE(Model::batch_vertices(draw.uniforms));
      shading::VertexBatchInput in;
      in.count = count;
      in.positions = positions.data();
      for (int c = 0; c < 3; ++c) in.normal[c] = normal[c];
      alignas(64) float out[shading::kMaxVaryings][shading::kVertexBatch];
      Model::vertex_batch(draw.uniforms, in, out);
      for (int n = 0; n < count; ++n) {
        shading::VertexInput vertex;
        vertex.position = positions[n];
        vertex.normal = {normal[0][n], normal[1][n], normal[2][n]};
        vertex.color = glm::vec4(1.0f);
        vertex.texcoord = glm::vec2(0.0f);
        vertex.tangent = glm::vec4(0.0f);
        float expected[Model::kVaryings];
        Model::vertex(vertex, draw.uniforms, expected);
        for (int k = 0; k < Model::kVaryings; ++k) {
          ASSERT_EQ(std::memcmp(&expected[k], &out[k][n], sizeof(float)), 0)
              << hwy::TargetName(target) << ", round " << round << ", vertex " << n << ", varying "
              << k << ": " << out[k][n] << ", vertex() gives " << expected[k];
        }
        const glm::vec3 world(draw.uniforms.model * glm::vec4(positions[n], 1.0f));
        seen.add(sun.maps, world, vertex.normal);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 500 * static_cast<int>(simd_targets().size()));
  seen.expect_each_kind();
}

TEST(ShadowBatch, GouraudVerticesGiveVertexsBitsOnEveryTarget) {
  expect_vertexs_bits<shading::GouraudShading>();
  expect_vertexs_bits<shading::ConstantColorGouraudShading>();
}

// A spot light's perspective map keeps the Gouraud models' scalar vertex().
TEST(ShadowBatch, GouraudDeclinesPerspectiveMapsAtVertices) {
  std::mt19937 rng(5);
  Sun sun;
  make_sun(rng, 1, 16, sun);
  Draw draw;
  make_draw(rng, sun, draw);
  draw.frame.light_count = 1;
  EXPECT_TRUE(shading::GouraudShading::batch_vertices(draw.uniforms));
  sun.maps.maps[0].perspective = true;
  EXPECT_FALSE(shading::GouraudShading::batch_vertices(draw.uniforms));
}

}  // namespace
}  // namespace facet::test
