// Clipping: triangles crossing the near and far planes and the guard band, the camera inside
// a box, a vertex behind the eye — no stray pixels, no gaps, no crash.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "facet/procedural.hpp"
#include "pipeline/reference.hpp"
#include "support/geometry.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 64;

TEST(Clipping, CameraInsideABoxSeesEveryPixelExactlyOnce) {
  // From inside a closed box every view ray leaves through exactly one face; the faces in
  // view all cross the near plane or the guard band somewhere.
  Mesh room = box({6.0f, 4.0f, 8.0f});
  const glm::vec3 eyes[] = {{0, 0, 0}, {2.5f, 1.5f, -3.5f}, {-2.9f, -1.9f, 3.9f}};
  const glm::vec3 targets[] = {{0, 0, -1}, {3, 2, 4}, {1, 0.3f, -1}};
  for (const auto& eye : eyes) {
    for (const auto& target : targets) {
      Camera camera = Camera::look_at(eye, target, {0, 1, 0}, 90.0f, 1.5f, 0.05f, 100.0f);
      auto counts = coverage_counts({&room}, camera, kWidth, kHeight, CullMode::none);
      for (int i = 0; i < kWidth * kHeight; ++i) {
        ASSERT_EQ(counts[i], 1) << "pixel " << i % kWidth << "," << i / kWidth;
      }
    }
  }
}

// Compares the coverage of one triangle with ray casting: pixels whose ray hits the triangle
// clearly inside (and within [near, far]) must be covered, clearly outside must not.
void expect_matches_ray_cast(const std::vector<glm::vec3>& tri, float near_plane, float far_plane) {
  Mesh mesh = soup(tri);
  Camera camera = test_camera(kWidth, kHeight, 60.0f, near_plane, far_plane);
  auto counts = coverage_counts({&mesh}, camera, kWidth, kHeight, CullMode::none);
  int covered = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      glm::dvec3 dir = pixel_ray(x, y, kWidth, kHeight);  // dir.z == -1: t is view depth
      auto hit = intersect(dir, tri[0], tri[1], tri[2]);
      int n = counts[y * kWidth + x];
      ASSERT_LE(n, 1);
      covered += n;
      if (!hit) continue;
      bool clearly_in =
          hit->margin > 0.02 && hit->t > near_plane * 1.01 && hit->t < far_plane * 0.99;
      bool clearly_out =
          hit->margin < -0.02 || hit->t < near_plane * 0.99 || hit->t > far_plane * 1.01;
      if (clearly_in) {
        ASSERT_EQ(n, 1) << "gap at " << x << "," << y;
      }
      if (clearly_out) {
        ASSERT_EQ(n, 0) << "stray pixel at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(covered, 0);
}

TEST(Clipping, TriangleCrossingTheNearPlane) {
  expect_matches_ray_cast({{-2, -1, -0.05f}, {2, -1, -0.05f}, {0, 1.5f, -6}}, 0.5f, 100.0f);
}

TEST(Clipping, TriangleWithAVertexBehindTheEye) {
  expect_matches_ray_cast({{-3, -1, -4}, {3, -1, -4}, {0, 0.5f, 5}}, 0.1f, 100.0f);
  expect_matches_ray_cast({{-1, -2, 3}, {1, -2, 3}, {0, 1, -3}}, 0.1f, 100.0f);
}

TEST(Clipping, TriangleCrossingTheFarPlane) {
  expect_matches_ray_cast({{-30, -8, -20}, {30, -8, -20}, {0, 10, -90}}, 0.1f, 50.0f);
}

TEST(Clipping, HugeTrianglesBeyondTheGuardBand) {
  // Two triangles of a quad reaching 10^5 units sideways at depth 1 (millions of pixels off
  // screen): clipped against the guard band, their shared diagonal still covered once.
  const float big = 1.0e5f;
  Mesh quad_mesh = soup({{-big, -big, -1},
                         {big, -big, -1},
                         {big, big, -1},
                         {-big, -big, -1},
                         {big, big, -1},
                         {-big, big, -1}});
  auto counts = coverage_counts({&quad_mesh}, test_camera(kWidth, kHeight), kWidth, kHeight);
  for (int i = 0; i < kWidth * kHeight; ++i) ASSERT_EQ(counts[i], 1) << "pixel " << i;
  expect_matches_ray_cast({{-big, -1, -2}, {big, -1.5f, -2}, {0, 2, -3}}, 0.1f, 100.0f);
}

TEST(Clipping, WireframeLinesAreClippedToo) {
  // Edges through the near plane and far off screen draw without crashing and stay on screen.
  Mesh mesh = soup({{-1e5f, -0.5f, -2}, {1e5f, -0.7f, -2}, {0, 2, 5}});
  Framebuffer fb = render_unlit({&mesh}, test_camera(kWidth, kHeight), kWidth, kHeight);
  Renderer renderer;
  Material material;
  material.shading = ShadingModel::wireframe;
  material.cull = CullMode::none;
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.draw(mesh, material);
  renderer.finish(fb);
  EXPECT_GT(renderer.stats().pixels_shaded, 0u);
}

}  // namespace
}  // namespace facet::test
