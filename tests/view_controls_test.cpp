// The viewer's first-person pace (apps/facet/view/view_controls.cpp), fed held keys without a
// window: a human walk in the built-in worlds, whose units are metres, whatever their size; a pace
// scaled by the size of a model of unknown units; Shift runs.
#include "view_controls.hpp"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "facet/islands.hpp"
#include "facet/procedural.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"

namespace facet::cli {
namespace {

// How far one second of the given keys moves the eye, from a level start camera.
float distance_in_one_second(float speed, const HeldKeys& keys) {
  const Camera start = Camera::look_at({0, 1.7f, 0}, {0, 1.7f, -1});
  ViewControls controls(start, speed, CameraMode::first_person);
  for (int frame = 0; frame < 60; ++frame) controls.move(keys, 1.0 / 60.0);
  return glm::length(controls.camera(60.0f, 1.0f).eye - start.eye);
}

TEST(ViewControls, BuiltInWorldsWalkAtAHumanPace) {
  // The islands' ocean is kilometres wide; walking still crosses 1.4 m a second.
  IslandsWorld islands = make_islands_world();
  EXPECT_FLOAT_EQ(islands.scene.metres_per_unit, 1.0f);
  EXPECT_GT(glm::length(islands.scene.bounds().max - islands.scene.bounds().min), 3000.0f);
  EXPECT_FLOAT_EQ(walking_speed(islands.scene), 1.4f);
  EXPECT_FLOAT_EQ(walking_speed(make_builtin_scene("shapes")), 1.4f);
  // A world in centimetres walks 140 units a second.
  Scene centimetres;
  centimetres.metres_per_unit = 0.01f;
  EXPECT_NEAR(walking_speed(centimetres), 140.0f, 1e-3f);
}

// A scene of one box of this size, in units nobody stated.
Scene box_scene(glm::vec3 size) {
  Scene scene;
  scene.add_object(box(size), Material{});
  return scene;
}

TEST(ViewControls, ModelsOfUnknownUnitsWalkAcrossInTwentySeconds) {
  const Scene small = box_scene({2.0f, 2.0f, 1.0f});        // a 3 unit diagonal
  const Scene large = box_scene({200.0f, 200.0f, 100.0f});  // 300
  EXPECT_EQ(small.metres_per_unit, 0.0f);
  EXPECT_NEAR(walking_speed(small), 0.15f, 1e-5f);
  EXPECT_NEAR(walking_speed(large), 15.0f, 1e-3f);
}

TEST(ViewControls, WWalksAtTheSpeedAndShiftRunsFourTimesAsFast) {
  HeldKeys walk;
  walk.forward = 1.0f;
  EXPECT_NEAR(distance_in_one_second(1.4f, walk), 1.4f, 1e-3f);
  HeldKeys run = walk;
  run.run = true;
  EXPECT_NEAR(distance_in_one_second(1.4f, run), 5.6f, 1e-3f);
  HeldKeys strafe;
  strafe.strafe = -1.0f;
  EXPECT_NEAR(distance_in_one_second(2.0f, strafe), 2.0f, 1e-3f);
  EXPECT_EQ(distance_in_one_second(2.0f, HeldKeys{}), 0.0f);
}

}  // namespace
}  // namespace facet::cli
