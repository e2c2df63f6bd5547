// Lights as the shading kernels read them (prepare_light): directions made unit, radiance the
// color times the intensity, the range as its inverse square, cone angles as cosines. What the
// prepared lights give a surface is tested through the kernels (shade_batch_test,
// vertex_batch_test).
#include <gtest/gtest.h>

#include <cmath>

#include "shading/lighting.hpp"

namespace facet::shading {
namespace {

TEST(PrepareLight, DirectionalLightPointsBackAlongItsTravel) {
  const LightData sun = prepare_light(Light::directional({0, -2, 0}, glm::vec3(1.0f), 0.5f));
  EXPECT_EQ(sun.to_light, glm::vec3(0, 1, 0));
  EXPECT_EQ(sun.radiance, glm::vec3(0.5f));
  EXPECT_EQ(sun.inv_range_squared, 0.0f);  // unlimited
}

TEST(PrepareLight, PointLightKeepsItsRangeAsAnInverseSquare) {
  const LightData lamp = prepare_light(Light::point({1, 2, 3}, glm::vec3(1.0f), 4.0f, 2.0f));
  EXPECT_EQ(lamp.position, glm::vec3(1, 2, 3));
  EXPECT_EQ(lamp.radiance, glm::vec3(4.0f));
  EXPECT_EQ(lamp.inv_range_squared, 0.25f);
}

TEST(PrepareLight, SpotConesBecomeCosinesTheInnerWithinTheOuter) {
  const LightData spot = prepare_light(Light::spot({0, 0, 0}, {0, -3, 0}, 20.0f, 30.0f));
  EXPECT_EQ(spot.spot_direction, glm::vec3(0, -1, 0));
  EXPECT_NEAR(spot.cos_inner, std::cos(glm::radians(20.0f)), 1e-6f);
  EXPECT_NEAR(spot.cos_outer, std::cos(glm::radians(30.0f)), 1e-6f);
  // An inner cone wider than the outer is the outer; cones past 90 degrees are 90.
  const LightData wide = prepare_light(Light::spot({0, 0, 0}, {0, -1, 0}, 120.0f, 100.0f));
  EXPECT_NEAR(wide.cos_outer, 0.0f, 1e-6f);
  EXPECT_EQ(wide.cos_inner, wide.cos_outer);
}

}  // namespace
}  // namespace facet::shading
