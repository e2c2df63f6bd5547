// The SIMD lighting of the Gouraud models (shading/vertex_batch.cpp), written once for every
// target, gives the same bits on every SIMD target as on the portable one: lit by zero to three
// directional, point and spot lights (with and without a range), from any side, inside and
// outside spot cones, with and without texture coordinates, vertex colors and a highlight, for
// every run length, and per face for meshes without normals; vertex() is its batch of one; and
// it gives the values worked out by hand of a few simple cases. The batch form of the surface
// models (surface_vertex_batch: unlit, Lambert, Phong, PBR) gives surface_vertex()'s bits.
#include "shading/vertex_batch.hpp"

#include <gtest/gtest.h>
#include <hwy/targets.h>

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
#include "support/light_reference.hpp"

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

// A random run of vertices: object positions, unit normals facing anywhere (now and then none:
// the pass gives zero), texture coordinates, colors and tangents, each present or not.
struct VertexRun {
  int count = 0;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> texcoords;
  std::vector<glm::vec4> colors;
  std::vector<glm::vec4> tangents;  // object space, w the handedness
  alignas(64) float normal[3][kVertexBatch] = {};
  bool with_texcoords = false, with_colors = false, with_tangents = false;

  void randomize(std::mt19937& rng, int round) {
    std::uniform_real_distribution<float> any(-3.0f, 3.0f), unit(0.0f, 1.0f);
    count = 1 + static_cast<int>(rng() % kVertexBatch);
    positions.resize(count), texcoords.resize(count), colors.resize(count), tangents.resize(count);
    for (int n = 0; n < count; ++n) {
      positions[n] = {any(rng), any(rng), any(rng)};
      texcoords[n] = {any(rng), any(rng)};
      colors[n] = {unit(rng), unit(rng), unit(rng), unit(rng)};
      tangents[n] = {any(rng), any(rng), any(rng), rng() % 2 ? 1.0f : -1.0f};
      const glm::vec3 nv = rng() % 8 == 0 ? glm::vec3(0.0f)
                                          : glm::normalize(glm::vec3(any(rng), any(rng), any(rng)));
      for (int c = 0; c < 3; ++c) normal[c][n] = nv[c];
    }
    with_texcoords = round % 2 == 0, with_colors = round % 3 != 0, with_tangents = round % 4 < 2;
  }
  shading::VertexBatchInput input() const {
    return {count,
            positions.data(),
            {normal[0], normal[1], normal[2]},
            with_texcoords ? texcoords.data() : nullptr,
            with_colors ? colors.data() : nullptr,
            with_tangents ? tangents.data() : nullptr};
  }
  // What the vertex stage hands vertex(): the tangent turned to world space by `model`.
  shading::VertexInput vertex(int n, const glm::mat4& model) const {
    shading::VertexInput v;
    v.position = positions[n];
    v.normal = {normal[0][n], normal[1][n], normal[2][n]};
    v.color = with_colors ? colors[n] : glm::vec4(1.0f);
    v.texcoord = with_texcoords ? texcoords[n] : glm::vec2(0.0f);
    v.tangent = with_tangents ? glm::vec4(glm::mat3(model) * glm::vec3(tangents[n]), tangents[n].w)
                              : glm::vec4(0.0f);
    return v;
  }
};

using Varyings = float[shading::kMaxVaryings][kVertexBatch];

// Compares Model::vertex_batch with surface_vertex() (surface.hpp, the one-vertex form of the
// surface layout) for random draws and vertices on every target.
template <class Model>
void expect_vertex_batch_gives_vertexs_bits() {
  std::mt19937 rng(20261122);
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int round = 0; round < 60; ++round) {
      Draw draw;
      randomize(rng, draw);
      VertexRun run;
      run.randomize(rng, round);
      alignas(64) Varyings out;
      Model::vertex_batch(draw.uniforms, run.input(), out);
      for (int n = 0; n < run.count; ++n) {
        float expected[Model::kVaryings];
        shading::surface_vertex<Model::kVaryings>(run.vertex(n, draw.uniforms.model), draw.uniforms,
                                                  expected);
        for (int k = 0; k < Model::kVaryings; ++k) {
          ASSERT_EQ(std::memcmp(&expected[k], &out[k][n], sizeof(float)), 0)
              << hwy::TargetName(target) << ", round " << round << ", vertex " << n << ", varying "
              << k << ": " << out[k][n] << ", vertex() gives " << expected[k];
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

// Every target's Model::vertex_batch against the portable target's, for random draws and runs.
template <class Model>
void expect_every_target_gives_portable_bits() {
  const std::vector<std::int64_t> targets = simd_targets();
  const std::int64_t portable = portable_simd_target();
  ASSERT_NE(portable, 0);
  ASSERT_GE(targets.size(), 2u);
  std::mt19937 rng(20261122);
  int compared = 0;
  // Vertices a point or spot light reaches (inside its range and cone) and does not.
  int reached = 0, unreached = 0;
  for (int round = 0; round < 100; ++round) {
    Draw draw;
    randomize(rng, draw);
    VertexRun run;
    run.randomize(rng, round);
    compared += expect_rows_alike_on_every_target<shading::kVertexBatch>(
        Model::kVaryings, run.count,
        [&](float(*out)[shading::kVertexBatch]) {
          draw.kernels = shading::shading_kernels(chosen_simd_target());
          Model::vertex_batch(draw.uniforms, run.input(), out);
        },
        "round " + std::to_string(round));
    for (int n = 0; n < run.count; ++n) {
      const glm::vec3 world(draw.uniforms.model * glm::vec4(run.positions[n], 1.0f));
      for (int i = 0; i < draw.frame.light_count; ++i) {
        if (draw.lights[i].type == LightType::directional) continue;
        ++(incident(draw.lights[i], world).radiance == glm::vec3(0.0f) ? unreached : reached);
      }
    }
  }
  EXPECT_GT(compared, 1000 * static_cast<int>(targets.size()));
  EXPECT_GT(reached, 500);
  EXPECT_GT(unreached, 500);
}

TEST(VertexBatch, GouraudGivesPortableBitsOnEveryTarget) {
  expect_every_target_gives_portable_bits<GouraudShading>();
}

TEST(VertexBatch, ConstantColorGouraudGivesPortableBitsOnEveryTarget) {
  expect_every_target_gives_portable_bits<shading::ConstantColorGouraudShading>();
  expect_every_target_gives_portable_bits<shading::GrayLightGouraudShading>();
}

// vertex() lights one vertex as a run lights it wherever it is in the run.
TEST(VertexBatch, SurfaceModelsGiveVertexsBits) {
  expect_vertex_batch_gives_vertexs_bits<shading::UnlitShading>();
  expect_vertex_batch_gives_vertexs_bits<shading::LambertShading>();
  expect_vertex_batch_gives_vertexs_bits<shading::UnpositionedLambertShading>();
  expect_vertex_batch_gives_vertexs_bits<shading::PhongShading>();
  expect_vertex_batch_gives_vertexs_bits<shading::PbrShading>();
}

// A triangle of a mesh without normals: its three corners take the light of its centre with
// its face normal, the same bits on every target as on the portable one.
template <class Model>
void expect_face_without_normals_gives_portable_bits() {
  const std::int64_t portable = portable_simd_target();
  ASSERT_NE(portable, 0);
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> any(-3.0f, 3.0f);
  int compared = 0;
  for (int round = 0; round < 200; ++round) {
    Draw draw;
    randomize(rng, draw);
    const glm::vec3 centre(any(rng), any(rng), any(rng));
    const glm::vec3 normal = glm::normalize(glm::vec3(any(rng), any(rng), any(rng)));
    float expected[3][Model::kVaryings], out[3][Model::kVaryings];
    float* corners[3] = {expected[0], expected[1], expected[2]};
    {
      ForcedTarget forced(portable);
      draw.kernels = shading::shading_kernels(chosen_simd_target());
      Model::face_without_normals(normal, centre, draw.uniforms, corners);
    }
    for (int i = 1; i < 3; ++i) {
      ASSERT_EQ(std::memcmp(expected[0], expected[i], sizeof expected[0]), 0) << "corner " << i;
    }
    for (std::int64_t target : simd_targets()) {
      ForcedTarget forced(target);
      draw.kernels = shading::shading_kernels(chosen_simd_target());
      float* out_corners[3] = {out[0], out[1], out[2]};
      Model::face_without_normals(normal, centre, draw.uniforms, out_corners);
      ASSERT_EQ(std::memcmp(expected, out, sizeof out), 0)
          << hwy::TargetName(target) << ", round " << round;
      ++compared;
    }
  }
  EXPECT_GT(compared, 200);
}

TEST(VertexBatch, GouraudFaceWithoutNormalsGivesPortableBitsOnEveryTarget) {
  expect_face_without_normals_gives_portable_bits<shading::ConstantColorGouraudShading>();
  expect_face_without_normals_gives_portable_bits<shading::GrayLightGouraudShading>();
}

// Cases worked out by hand, on every target: a vertex at the origin, facing +z, seen from
// (0, 0, 5), under one light, no highlight (shininess 0: the highlight is 1), specular color
// one half. Its diffuse light is the ambient light plus the radiance arriving times n . l, its
// specular light half the radiance arriving.
TEST(VertexBatch, GouraudGivesHandWorkedLight) {
  using Model = shading::ConstantColorGouraudShading;
  const glm::vec3 ambient(0.125f, 0.25f, 0.375f);
  const glm::vec3 color(4.0f, 8.0f, 12.0f);
  struct Case {
    const char* what;
    Light light;
    glm::vec3 normal;
    glm::vec3 diffuse, specular;
  };
  const glm::vec3 slanted(0.6f, 0.0f, 0.8f);
  const Case cases[] = {
      // A white light of radiance 1 along -z: n . l = 0.8 exactly (0.6 x -0 + 0 x -0 + 0.8 x 1).
      {"directional", Light::directional({0, 0, -1}), slanted, ambient + 0.8f, glm::vec3(0.5f)},
      {"directional from behind", Light::directional({0, 0, 1}), slanted, ambient, glm::vec3(0.0f)},
      // At distance 2: a quarter of the radiance.
      {"point", Light::point({0, 0, 2}, color), {0, 0, 1}, ambient + color * 0.25f, color * 0.125f},
      // At its range: nothing.
      {"point at its range",
       Light::point({0, 0, 2}, color, 1.0f, 2.0f),
       {0, 0, 1},
       ambient,
       glm::vec3(0.0f)},
      {"spot, inside its inner cone",
       Light::spot({0, 0, 2}, {0, 0, -1}, 10, 20, color),
       {0, 0, 1},
       ambient + color * 0.25f,
       color * 0.125f},
      // Pointing along +x: the vertex is 90 degrees off its axis.
      {"spot, outside its cone",
       Light::spot({0, 0, 2}, {1, 0, 0}, 10, 20, color),
       {0, 0, 1},
       ambient,
       glm::vec3(0.0f)},
  };
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (const Case& c : cases) {
      Draw draw;
      draw.uniforms.material = &draw.material;
      draw.uniforms.frame = &draw.frame;
      draw.kernels = shading::shading_kernels(chosen_simd_target());
      draw.frame.kernels = &draw.kernels;
      draw.frame.eye = {0.0f, 0.0f, 5.0f};
      draw.frame.ambient = ambient;
      draw.material.specular_color = glm::vec3(0.5f);
      draw.material.shininess = 0.0f;
      draw.lights[0] = shading::prepare_light(c.light);
      draw.frame.lights = draw.lights;
      draw.frame.light_count = 1;
      const float want[6] = {c.diffuse.x,  c.diffuse.y,  c.diffuse.z,
                             c.specular.x, c.specular.y, c.specular.z};
      // A run of 11 such vertices, and a face.
      VertexRun run;
      run.count = 11;
      run.positions.assign(11, glm::vec3(0.0f));
      for (int n = 0; n < 11; ++n) {
        for (int k = 0; k < 3; ++k) run.normal[k][n] = c.normal[k];
      }
      alignas(64) Varyings out;
      Model::vertex_batch(draw.uniforms, run.input(), out);
      float corner[3][Model::kVaryings];
      float* corners[3] = {corner[0], corner[1], corner[2]};
      Model::face_without_normals(c.normal, glm::vec3(0.0f), draw.uniforms, corners);
      for (int k = 0; k < 6; ++k) {
        for (int n = 0; n < 11; ++n) {
          EXPECT_EQ(out[Model::kDiffuseSlot + k][n], want[k])
              << hwy::TargetName(target) << ", " << c.what << ", varying " << k;
        }
        EXPECT_EQ(corner[2][Model::kDiffuseSlot + k], want[k])
            << hwy::TargetName(target) << ", " << c.what << ", face, varying " << k;
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
