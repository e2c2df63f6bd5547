// The SIMD vertex form of the Gouraud models (shading/vertex_batch.cpp) gives vertex()'s bits on
// every SIMD target: lit by zero to three directional, point and spot lights (with and without
// a range), from any side, inside and outside spot cones, with and without texture
// coordinates, vertex colors and a highlight, for every run length. The batch form of the unlit and
// Lambert models (surface_vertex_batch) gives their vertex()'s bits too.
#include "shading/vertex_batch.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "facet/light.hpp"
#include "shading/kernels.hpp"
#include "shading/lighting.hpp"
#include "shading/lit_models.hpp"
#include "shading/models.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using shading::GouraudShading;
using shading::kVertexBatch;

struct Draw {
  Material material;
  shading::LightData lights[3];
  shading::ShadingKernels kernels;
  shading::FrameUniforms frame;
  shading::DrawUniforms uniforms;
};

void randomize(std::mt19937& rng, Draw& d) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), unit(0.0f, 1.0f);
  d.uniforms.material = &d.material;
  d.uniforms.frame = &d.frame;
  d.kernels = shading::shading_kernels(chosen_simd_target());  // the forced target's
  d.frame.kernels = &d.kernels;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 3; ++r) d.uniforms.model[c][r] = any(rng) * (c == 3 ? 10.0f : 2.0f);
  }
  d.frame.eye = {any(rng) * 5.0f, any(rng) * 5.0f, any(rng) * 5.0f};
  d.frame.ambient = {unit(rng) * 0.2f, unit(rng) * 0.2f, unit(rng) * 0.2f};
  d.material.base_color = {unit(rng), unit(rng), unit(rng), unit(rng)};
  d.material.use_vertex_colors = rng() % 2 == 0;
  d.frame.light_count = static_cast<int>(rng() % 4);
  for (int i = 0; i < d.frame.light_count; ++i) {
    // Directional, point or spot, among the vertices (the world positions reach about 25 from
    // the origin), with and without a range, the spot cones narrow to wide.
    const glm::vec3 color(unit(rng), unit(rng), unit(rng));
    const glm::vec3 position = glm::vec3(any(rng), any(rng), any(rng)) * 12.0f;
    const glm::vec3 direction = glm::vec3(any(rng), any(rng), any(rng)) + 0.01f;
    const float intensity = 1.0f + unit(rng) * 100.0f;
    const float range = rng() % 2 ? 0.0f : 5.0f + unit(rng) * 30.0f;
    const float outer = 5.0f + unit(rng) * 85.0f, inner = outer * unit(rng);
    switch (rng() % 3) {
      case 0:
        d.lights[i] =
            shading::prepare_light(Light::directional(direction, color, unit(rng) * 3.0f));
        break;
      case 1:
        d.lights[i] = shading::prepare_light(Light::point(position, color, intensity, range));
        break;
      default:
        d.lights[i] = shading::prepare_light(
            Light::spot(position, direction, inner, outer, color, intensity, range));
        break;
    }
  }
  d.frame.lights = d.lights;
  d.material.specular_color = {unit(rng), unit(rng), unit(rng)};
  d.material.shininess = rng() % 5 == 0 ? 0.0f : 1.0f + unit(rng) * 127.0f;
}

// Compares Model::vertex_batch with Model::vertex() for random draws and vertices.
template <class Model>
void expect_vertex_batch_gives_vertexs_bits() {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<float> any(-3.0f, 3.0f), unit(0.0f, 1.0f);
  int compared = 0;
  // Vertices a point or spot light reaches (inside its range and cone) and does not.
  int reached = 0, unreached = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int round = 0; round < 60; ++round) {
      Draw draw;
      randomize(rng, draw);
      const int count = 1 + static_cast<int>(rng() % kVertexBatch);
      std::vector<glm::vec3> positions(count);
      std::vector<glm::vec2> texcoords(count);
      std::vector<glm::vec4> colors(count);
      alignas(64) float normal[3][kVertexBatch] = {};
      for (int n = 0; n < count; ++n) {
        positions[n] = {any(rng), any(rng), any(rng)};
        texcoords[n] = {any(rng), any(rng)};
        colors[n] = {unit(rng), unit(rng), unit(rng), unit(rng)};
        // Unit normals facing anywhere, and now and then none (the pass gives zero).
        glm::vec3 nv = rng() % 8 == 0 ? glm::vec3(0.0f)
                                      : glm::normalize(glm::vec3(any(rng), any(rng), any(rng)));
        for (int c = 0; c < 3; ++c) normal[c][n] = nv[c];
      }
      const bool with_texcoords = round % 2 == 0, with_colors = round % 3 != 0;
      shading::VertexBatchInput in;
      in.count = count;
      in.positions = positions.data();
      for (int c = 0; c < 3; ++c) in.normal[c] = normal[c];
      in.texcoords = with_texcoords ? texcoords.data() : nullptr;
      in.colors = with_colors ? colors.data() : nullptr;
      alignas(64) float out[shading::kMaxVaryings][kVertexBatch];
      Model::vertex_batch(draw.uniforms, in, out);
      for (int n = 0; n < count; ++n) {
        shading::VertexInput vertex;
        vertex.position = positions[n];
        vertex.normal = {normal[0][n], normal[1][n], normal[2][n]};
        vertex.color = with_colors ? colors[n] : glm::vec4(1.0f);
        vertex.texcoord = with_texcoords ? texcoords[n] : glm::vec2(0.0f);
        vertex.tangent = glm::vec4(0.0f);
        float expected[Model::kVaryings];
        Model::vertex(vertex, draw.uniforms, expected);
        for (int k = 0; k < Model::kVaryings; ++k) {
          ASSERT_EQ(std::memcmp(&expected[k], &out[k][n], sizeof(float)), 0)
              << hwy::TargetName(target) << ", round " << round << ", vertex " << n << ", varying "
              << k << ": " << out[k][n] << ", vertex() gives " << expected[k];
        }
        ++compared;
        const glm::vec3 world(draw.uniforms.model * glm::vec4(positions[n], 1.0f));
        for (int i = 0; i < draw.frame.light_count; ++i) {
          if (draw.lights[i].type == LightType::directional) continue;
          const glm::vec3 radiance = shading::incident(draw.lights[i], world).radiance;
          ++(radiance == glm::vec3(0.0f) ? unreached : reached);
        }
      }
    }
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(reached, 500);
  EXPECT_GT(unreached, 500);
}

TEST(VertexBatch, GouraudGivesVertexsBitsOnEveryTarget) {
  expect_vertex_batch_gives_vertexs_bits<GouraudShading>();
}

TEST(VertexBatch, ConstantColorGouraudGivesVertexsBitsOnEveryTarget) {
  expect_vertex_batch_gives_vertexs_bits<shading::ConstantColorGouraudShading>();
}

TEST(VertexBatch, SurfaceModelsGiveVertexsBits) {
  expect_vertex_batch_gives_vertexs_bits<shading::UnlitShading>();
  expect_vertex_batch_gives_vertexs_bits<shading::LambertShading>();
  expect_vertex_batch_gives_vertexs_bits<shading::UnpositionedLambertShading>();
}

TEST(VertexBatch, GouraudTakesEveryLight) {
  Draw draw;
  std::mt19937 rng(3);
  randomize(rng, draw);
  draw.frame.light_count = 3;
  draw.lights[0].type = LightType::directional;
  draw.lights[1].type = LightType::point;
  draw.lights[2].type = LightType::spot;
  EXPECT_TRUE(GouraudShading::batch_vertices(draw.uniforms));
}

}  // namespace
}  // namespace facet::test
