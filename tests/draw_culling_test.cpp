// Whole draws outside the view frustum are dropped before their vertices are transformed
// (pipeline/draw_culling.cpp); draws that reach into the view are kept.
#include "pipeline/draw_culling.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 64, kHeight = 48;

bool outside(const Mesh& mesh, const glm::mat4& view_projection) {
  std::optional<pipeline::MeshBox> box = pipeline::finite_bounds(mesh);
  return box && pipeline::box_outside_frustum(*box, view_projection);
}

Mesh triangle_at(glm::vec3 centre) {
  return soup(
      {centre + glm::vec3(-1, -1, 0), centre + glm::vec3(1, -1, 0), centre + glm::vec3(0, 1, 0)});
}

TEST(DrawCulling, MeshesOutsideEachPlaneAreDropped) {
  const glm::mat4 view_projection = test_camera(kWidth, kHeight).view_projection();
  // Left, right, below, above, behind the eye, beyond the far plane (100).
  for (glm::vec3 centre : {glm::vec3(-500, 0, -10), glm::vec3(500, 0, -10), glm::vec3(0, -500, -10),
                           glm::vec3(0, 500, -10), glm::vec3(0, 0, 10), glm::vec3(0, 0, -500)}) {
    EXPECT_TRUE(outside(triangle_at(centre), view_projection))
        << centre.x << "," << centre.y << "," << centre.z;
  }
  // In view, straddling the left edge, and straddling the near plane are kept.
  for (glm::vec3 centre :
       {glm::vec3(0, 0, -10), glm::vec3(-6.6f, 0, -10), glm::vec3(0, 0, -0.1f)}) {
    EXPECT_FALSE(outside(triangle_at(centre), view_projection))
        << centre.x << "," << centre.y << "," << centre.z;
  }
}

TEST(DrawCulling, NonFiniteOrEmptyMeshesAreLeftToThePipeline) {
  Mesh with_nan = triangle_at({500, 0, -10});
  with_nan.positions[1].x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(pipeline::finite_bounds(with_nan));
  EXPECT_FALSE(pipeline::finite_bounds(Mesh{}));
}

// finite_bounds walks four vertices a step, then the rest one at a time: every vertex of
// meshes of 1 to 11 vertices, in every coordinate, is checked for its bounds and for a
// non-finite value there.
TEST(DrawCulling, BoundsSeeEveryCoordinateOfEveryVertex) {
  const float kNonFinite[] = {std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity()};
  for (int count = 1; count <= 11; ++count) {
    Mesh mesh;
    for (int i = 0; i < count; ++i) mesh.positions.push_back({i, -i, 0.5f * i});
    for (int i = 0; i < count; ++i) {
      for (int axis = 0; axis < 3; ++axis) {
        Mesh changed = mesh;
        changed.positions[i][axis] = 1000.0f;
        std::optional<pipeline::MeshBox> box = pipeline::finite_bounds(changed);
        ASSERT_TRUE(box);
        EXPECT_EQ(box->high[axis], 1000.0f) << count << " " << i << " " << axis;
        changed.positions[i][axis] = -1000.0f;
        EXPECT_EQ(pipeline::finite_bounds(changed)->low[axis], -1000.0f);
        for (float bad : kNonFinite) {
          changed.positions[i][axis] = bad;
          EXPECT_FALSE(pipeline::finite_bounds(changed)) << count << " " << i << " " << axis;
        }
      }
    }
    const std::optional<pipeline::MeshBox> box = pipeline::finite_bounds(mesh);
    ASSERT_TRUE(box);
    EXPECT_EQ(box->low, glm::vec3(0, 1 - count, 0));
    EXPECT_EQ(box->high, glm::vec3(count - 1, 0, 0.5f * (count - 1)));
  }
}

TEST(DrawCulling, DroppedDrawsCountAsCulledAndDrawNothing) {
  Mesh outside = triangle_at({500, 0, -10});
  Mesh inside = triangle_at({0, 0, -10});
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.draw(outside, Material{});
  renderer.draw(inside, Material{});
  renderer.finish(fb);
  EXPECT_EQ(renderer.stats().triangles_in, 2u);
  EXPECT_EQ(renderer.stats().culled, 1u);
  EXPECT_EQ(renderer.stats().drawn, 1u);
  EXPECT_GT(renderer.stats().pixels_shaded, 0u);
}

}  // namespace
}  // namespace facet::test
