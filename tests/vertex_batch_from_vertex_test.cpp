// A shading model given a batch form by VertexBatchFromVertex (shading/surface.hpp) draws exactly
// what its vertex() draws a vertex at a time: every input it reads (position, normal, texture
// coordinate, color) reaches it alike, for triangles set up straight from the projected vertices,
// for those clipped against the near plane, and for a mesh without normals or texture
// coordinates (its face normals written per triangle, from the corners computed again).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/procedural.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

// Every input of the vertex as a varying, shown as the fractional parts of their mixes.
struct EveryInput {
  static constexpr int kVaryings = 12;
  static constexpr int kNormalSlot = 3;
  static void vertex(const shading::VertexInput& in, const shading::DrawUniforms& u, float* out) {
    const glm::vec3 world = glm::vec3(u.model * glm::vec4(in.position, 1.0f));
    shading::store(out, world);
    shading::store(out + 3, in.normal);
    shading::store(out + 6, in.color);
    shading::store(out + 10, in.texcoord);
  }
  static glm::vec4 fragment(const shading::Fragment& f, const shading::DrawUniforms&) {
    const float* v = f.v;
    auto part = [](float x) { return x - std::floor(x); };
    return {part(v[0] * 3.0f + v[3] + v[6]), part(v[1] * 3.0f + v[4] + v[7] + v[10] * 5.0f),
            part(v[2] * 3.0f + v[5] + v[8] + v[11] * 5.0f), 1.0f};
  }
};
struct EveryInputBatched : EveryInput, shading::VertexBatchFromVertex<EveryInputBatched> {};

Framebuffer render(const pipeline::DrawPipeline& pipe) {
  constexpr int kWidth = 240, kHeight = 180;
  Mesh sphere = uv_sphere(1.0f, 24, 12);
  sphere.colors.resize(sphere.positions.size());
  for (std::size_t i = 0; i < sphere.colors.size(); ++i) {
    const glm::vec3& p = sphere.positions[i];
    sphere.colors[i] = {p.x * 0.5f + 0.5f, p.y * 0.25f + 0.5f, 0.3f, 1.0f};
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

TEST(VertexBatchFromVertex, DrawsWhatTheModelsVertexDraws) {
  const pipeline::DrawPipeline one_at_a_time = pipeline::make_pipeline<EveryInput>();
  const pipeline::DrawPipeline batched = pipeline::make_pipeline<EveryInputBatched>();
  ASSERT_EQ(one_at_a_time.vertex_batch, nullptr);
  ASSERT_NE(batched.vertex_batch, nullptr);
  const Framebuffer expected = render(one_at_a_time), got = render(batched);
  int drawn = 0;
  for (std::size_t i = 0; i < got.rgba8().size(); ++i) {
    ASSERT_EQ(got.rgba8()[i], expected.rgba8()[i]) << "byte " << i;
    drawn += i % 4 == 3 && got.depth()[i / 4] < 1.0f;
  }
  EXPECT_GT(drawn, 240 * 180 / 3);
}

}  // namespace
}  // namespace facet::test
