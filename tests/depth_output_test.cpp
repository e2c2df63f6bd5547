// What a framebuffer's depth holds: window depth in [0, 1], 1 where nothing was drawn, which
// Camera::view_distance turns into distances in scene units.
#include <gtest/gtest.h>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"

namespace facet::test {
namespace {

TEST(DepthOutput, ViewDistanceOfTheDepthIsTheDistanceDrawnAt) {
  constexpr int kWidth = 64, kHeight = 48;
  const Camera camera = Camera::look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f,
                                        float(kWidth) / kHeight, 0.5f, 50.0f);
  EXPECT_FLOAT_EQ(camera.view_distance(0.0f), 0.5f);
  EXPECT_FLOAT_EQ(camera.view_distance(1.0f), 50.0f);
  // A wall facing the camera over the upper half of the frame, the lower half empty.
  for (float distance : {0.75f, 4.0f, 37.0f}) {
    const Mesh wall = quad({-100, 0, -distance}, {100, 0, -distance}, {100, 100, -distance},
                           {-100, 100, -distance});
    Renderer renderer;
    Framebuffer image(kWidth, kHeight);
    renderer.begin_frame(camera);
    Material material;
    material.shading = ShadingModel::unlit;
    renderer.draw(wall, material);
    renderer.finish(image);
    const float wall_depth = image.depth_at(kWidth / 2, kHeight / 4);
    EXPECT_GT(wall_depth, 0.0f);
    EXPECT_LT(wall_depth, 1.0f);
    EXPECT_NEAR(camera.view_distance(wall_depth), distance, distance * 1e-4f) << distance;
    EXPECT_EQ(image.depth_at(kWidth / 2, kHeight * 3 / 4), 1.0f);  // nothing drawn there
  }
}

}  // namespace
}  // namespace facet::test
