// A shading model without a batch form of its own gets one from its vertex()
// (shading/surface.hpp's vertex_batch_from_vertex, which make_pipeline takes): it gives vertex()'s
// bits for every vertex of a run, each input (position, normal, texture coordinate, color,
// tangent) present or not; and it draws what a batch form written by hand draws, for triangles
// set up straight from the projected vertices, for those clipped against the near plane, and for
// a mesh without normals or texture coordinates (its face normals written per triangle, from
// the corners computed again).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "facet/procedural.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

using shading::kVertexBatch;

// Every input of the vertex as a varying, shown as the fractional parts of their mixes.
struct EveryInput {
  static constexpr int kVaryings = 16;
  static constexpr int kNormalSlot = 3;
  static void vertex(const shading::VertexInput& in, const shading::DrawUniforms& u, float* out) {
    const glm::vec3 world = glm::vec3(u.model * glm::vec4(in.position, 1.0f));
    shading::store(out, world);
    shading::store(out + 3, in.normal);
    shading::store(out + 6, in.color);
    shading::store(out + 10, in.texcoord);
    shading::store(out + 12, in.tangent);
  }
  static glm::vec4 fragment(const shading::Fragment& f, const shading::DrawUniforms&) {
    const float* v = f.v;
    auto part = [](float x) { return x - std::floor(x); };
    return {part(v[0] * 3.0f + v[3] + v[6] + v[12] * 7.0f),
            part(v[1] * 3.0f + v[4] + v[7] + v[10] * 5.0f + v[13] * 7.0f),
            part(v[2] * 3.0f + v[5] + v[8] + v[11] * 5.0f + v[14] * 7.0f + v[15]), 1.0f};
  }
};

// The same values by a batch form of its own, written out slot by slot from the batch input.
struct EveryInputHandBatched : EveryInput {
  static void vertex_batch(const shading::DrawUniforms& u, const shading::VertexBatchInput& in,
                           float (*out)[kVertexBatch]) {
    const glm::mat3 model3(u.model);
    for (int n = 0; n < in.count; ++n) {
      const glm::vec4 world = u.model * glm::vec4(in.positions[n], 1.0f);
      const glm::vec4 color = in.colors ? in.colors[n] : glm::vec4(1.0f);
      const glm::vec2 texcoord = in.texcoords ? in.texcoords[n] : glm::vec2(0.0f);
      glm::vec4 tangent(0.0f);
      if (in.tangents) tangent = glm::vec4(model3 * glm::vec3(in.tangents[n]), in.tangents[n].w);
      for (int c = 0; c < 3; ++c) out[c][n] = world[c], out[3 + c][n] = in.normal[c][n];
      for (int c = 0; c < 4; ++c) out[6 + c][n] = color[c], out[12 + c][n] = tangent[c];
      out[10][n] = texcoord.x, out[11][n] = texcoord.y;
    }
  }
};

TEST(VertexBatchFromVertex, GivesVertexsBitsForEveryVertex) {
  std::mt19937 rng(20261204);
  std::uniform_real_distribution<float> any(-2.0f, 2.0f);
  shading::DrawUniforms u;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 3; ++r) u.model[c][r] = any(rng);
  }
  const glm::mat3 model3(u.model);
  constexpr int kCount = 37;
  std::vector<glm::vec3> positions(kCount);
  std::vector<glm::vec2> texcoords(kCount);
  std::vector<glm::vec4> colors(kCount), tangents(kCount);
  alignas(64) float normal[3][kVertexBatch] = {};
  for (int n = 0; n < kCount; ++n) {
    positions[n] = {any(rng), any(rng), any(rng)};
    texcoords[n] = {any(rng), any(rng)};
    colors[n] = {any(rng), any(rng), any(rng), any(rng)};
    tangents[n] = {any(rng), any(rng), any(rng), n % 2 ? 1.0f : -1.0f};
    for (int c = 0; c < 3; ++c) normal[c][n] = any(rng);
  }
  for (int present = 0; present < 8; ++present) {  // texture coordinates, colors, tangents
    const bool with_texcoords = present & 1, with_colors = present & 2, with_tangents = present & 4;
    const shading::VertexBatchInput in{kCount,
                                       positions.data(),
                                       {normal[0], normal[1], normal[2]},
                                       with_texcoords ? texcoords.data() : nullptr,
                                       with_colors ? colors.data() : nullptr,
                                       with_tangents ? tangents.data() : nullptr};
    alignas(64) float out[EveryInput::kVaryings][kVertexBatch];
    shading::vertex_batch_from_vertex<EveryInput>(u, in, out);
    for (int n = 0; n < kCount; ++n) {
      shading::VertexInput vertex;
      vertex.position = positions[n];
      vertex.normal = {normal[0][n], normal[1][n], normal[2][n]};
      vertex.color = with_colors ? colors[n] : glm::vec4(1.0f);
      vertex.texcoord = with_texcoords ? texcoords[n] : glm::vec2(0.0f);
      vertex.tangent = with_tangents ? glm::vec4(model3 * glm::vec3(tangents[n]), tangents[n].w)
                                     : glm::vec4(0.0f);
      float expected[EveryInput::kVaryings];
      EveryInput::vertex(vertex, u, expected);
      for (int k = 0; k < EveryInput::kVaryings; ++k) {
        ASSERT_EQ(std::memcmp(&expected[k], &out[k][n], sizeof(float)), 0)
            << "inputs " << present << ", vertex " << n << ", varying " << k;
      }
    }
  }
}

Framebuffer render(const pipeline::DrawPipeline& pipe) {
  constexpr int kWidth = 240, kHeight = 180;
  Mesh sphere = uv_sphere(1.0f, 24, 12);
  sphere.colors.resize(sphere.positions.size());
  sphere.tangents.resize(sphere.positions.size());
  for (std::size_t i = 0; i < sphere.colors.size(); ++i) {
    const glm::vec3& p = sphere.positions[i];
    sphere.colors[i] = {p.x * 0.5f + 0.5f, p.y * 0.25f + 0.5f, 0.3f, 1.0f};
    sphere.tangents[i] = {-p.z, 0.1f, p.x, p.y < 0.0f ? -1.0f : 1.0f};
  }
  // A floor running from under the camera into the distance: its near triangles are clipped.
  const Mesh floor = plane(40.0f, 40.0f, 8, 8);
  Mesh bare = uv_sphere(0.6f, 12, 6);
  bare.normals.clear();
  bare.texcoords.clear();
  Material material;
  Renderer renderer;
  renderer.begin_frame(test_camera(kWidth, kHeight));
  pipeline::draw_with_pipeline(renderer, sphere, material,
                               glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -4.0f)), pipe);
  pipeline::draw_with_pipeline(renderer, floor, material,
                               glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.0f, 0.0f)), pipe);
  pipeline::draw_with_pipeline(renderer, bare, material,
                               glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 0.5f, -3.5f)), pipe);
  Framebuffer target(kWidth, kHeight);
  renderer.finish(target);
  EXPECT_GT(renderer.stats().clipped, 0u);
  return target;
}

TEST(VertexBatchFromVertex, DrawsWhatAHandWrittenBatchFormDraws) {
  const pipeline::DrawPipeline from_vertex = pipeline::make_pipeline<EveryInput>();
  const pipeline::DrawPipeline hand_batched = pipeline::make_pipeline<EveryInputHandBatched>();
  ASSERT_EQ(from_vertex.vertex_batch, &shading::vertex_batch_from_vertex<EveryInput>);
  ASSERT_EQ(hand_batched.vertex_batch, &EveryInputHandBatched::vertex_batch);
  const Framebuffer expected = render(hand_batched), got = render(from_vertex);
  int drawn = 0;
  for (std::size_t i = 0; i < got.rgba8().size(); ++i) {
    ASSERT_EQ(got.rgba8()[i], expected.rgba8()[i]) << "byte " << i;
    drawn += i % 4 == 3 && got.depth()[i / 4] < 1.0f;
  }
  EXPECT_GT(drawn, 240 * 180 / 3);
}

}  // namespace
}  // namespace facet::test
