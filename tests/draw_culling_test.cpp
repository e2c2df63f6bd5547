// Whole draws outside the view frustum are dropped before their vertices are transformed
// (pipeline/record/draw_culling.cpp); draws that reach into the view are kept. Draws whose bounds
// need no clipping are told apart from those that may.
#include "pipeline/record/draw_culling.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "pipeline/reference.hpp"
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

pipeline::MeshBox box_around(glm::vec3 centre, glm::vec3 half_size) {
  return {centre - half_size, centre + half_size};
}

TEST(DrawCulling, BoxesThatMayNeedClippingAreToldApart) {
  const glm::mat4 view_projection = test_camera(kWidth, kHeight).view_projection();
  const pipeline::ClipBounds guard = pipeline::guard_band_bounds(kWidth, kHeight);
  auto inside = [&](glm::vec3 centre, glm::vec3 half_size) {
    return pipeline::box_inside_clip_bounds(box_around(centre, half_size), view_projection, guard);
  };
  // In view; across the left edge of the view but well inside the guard band (8192 pixels).
  EXPECT_TRUE(inside({0, 0, -10}, glm::vec3(1)));
  EXPECT_TRUE(inside({-6.6f, 0, -10}, glm::vec3(1)));
  // Across the near plane (0.1), behind the eye, across the far plane (100), and so wide
  // that it leaves the guard band.
  EXPECT_FALSE(inside({0, 0, -0.5f}, glm::vec3(1)));
  EXPECT_FALSE(inside({0, 0, 5}, glm::vec3(1)));
  EXPECT_FALSE(inside({0, 0, -100}, glm::vec3(1)));
  EXPECT_FALSE(inside({0, 0, -10}, {1e5f, 1, 1}));
}

// Where box_inside_clip_bounds says yes, no point of the box gets a code that asks for
// clipping from the vertex stage's transform and outcode(): corners and points inside, for
// random boxes (tiny and huge) and cameras (any field of view, near and far, frame size).
TEST(DrawCulling, NoPointOfABoxInsideTheClipBoundsNeedsClipping) {
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), unit(0.0f, 1.0f);
  int accepted = 0, rejected = 0;
  for (int round = 0; round < 4000; ++round) {
    const glm::vec3 eye(any(rng) * 20, any(rng) * 20, any(rng) * 20);
    const float near_plane = 0.05f + unit(rng), far_plane = near_plane + 1 + unit(rng) * 200;
    const Camera camera =
        Camera::look_at(eye, eye + glm::vec3(any(rng), any(rng), any(rng)), {0, 1, 0},
                        20 + unit(rng) * 120, 0.5f + unit(rng) * 2, near_plane, far_plane);
    const int width = 16 + static_cast<int>(rng() % 4000), height = 16 + rng() % 4000;
    const pipeline::ClipBounds guard = pipeline::guard_band_bounds(width, height);
    const glm::mat4 view_projection = camera.view_projection();
    const glm::vec3 centre = eye + glm::vec3(any(rng), any(rng), any(rng)) * far_plane;
    const glm::vec3 half_size =
        glm::vec3(unit(rng), unit(rng), unit(rng)) * (rng() % 2 ? 0.01f : far_plane);
    const pipeline::MeshBox box = box_around(centre, half_size);
    if (!pipeline::box_inside_clip_bounds(box, view_projection, guard)) {
      ++rejected;
      continue;
    }
    ++accepted;
    for (int k = 0; k < 32; ++k) {
      const glm::vec3 t = k < 8 ? glm::vec3(k & 1, k >> 1 & 1, k >> 2 & 1)
                                : glm::vec3(unit(rng), unit(rng), unit(rng));
      const glm::vec4 clip = view_projection * glm::vec4(box.low + t * (box.high - box.low), 1);
      ASSERT_EQ(pipeline::outcode(clip, guard), 0u) << "round " << round;
    }
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
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
