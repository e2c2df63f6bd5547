// The viewer's islands sound (apps/facet/view/view_sound.cpp), heard through OpenAL Soft's loopback
// device: the sources sit where the world's parts are and follow them as the world animates, the
// listener is the camera, and muting silences everything.
#include "view_sound.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "facet/islands.hpp"

namespace facet::test {
namespace {

constexpr int kSettleFrames = 8192;  // OpenAL Soft ramps gain changes; skip them
constexpr int kMeasureFrames = 44100;

SoundSceneDesc loopback() {
  SoundSceneDesc desc;
  desc.output = SoundOutput::loopback;
  return desc;
}

double level(cli::IslandsSound& sound) {
  sound.scene().render_loopback(kSettleFrames);
  std::vector<float> stereo = sound.scene().render_loopback(kMeasureFrames);
  double sum = 0.0;
  for (float v : stereo) sum += double(v) * v;
  return std::sqrt(sum / static_cast<double>(stereo.size()));
}

// A camera at `eye` looking at `target`.
Camera looking(glm::vec3 eye, glm::vec3 target) { return Camera::look_at(eye, target); }

TEST(ViewSound, LoudAtTheWaterfallQuietFarAwayAndSilentWhenMuted) {
  IslandsWorld world = make_islands_world();
  world.animate(0.0);
  cli::IslandsSound sound(world, loopback());
  glm::vec3 falls = world.waterfall_position();
  sound.update(world, looking(falls + glm::vec3(6, 0, 0), falls), 0.0);
  double near = level(sound);
  sound.update(world, looking(falls + glm::vec3(0, 300, 300), falls), 0.0);
  double far = level(sound);
  EXPECT_GT(near, 0.01);
  EXPECT_GT(near, 4.0 * far) << "near " << near << " far " << far;
  sound.set_muted(true);
  EXPECT_EQ(level(sound), 0.0);
  sound.set_muted(false);
  EXPECT_GT(level(sound), 0.0);
}

TEST(ViewSound, TheBoatsSourceFollowsTheBoat) {
  // Listen from just above where the boat is at t0, then let the boat sail on: its engine, the
  // loudest source there, fades as the boat leaves.
  IslandsWorld world = make_islands_world();
  const double t0 = 10.0;
  world.animate(t0);
  glm::vec3 boat = world.boat_position();
  Camera listener = looking(boat + glm::vec3(0, 3, 0.1f), boat);
  cli::IslandsSound sound(world, loopback());
  sound.update(world, listener, 0.0);
  double aboard = level(sound);
  // The time within half a minute (a lap takes 24 s) when the boat is farthest from where it was.
  double t1 = t0, farthest = 0.0;
  for (double t = t0; t < t0 + 30.0; t += 0.5) {
    world.animate(t);
    double d = glm::length(world.boat_position() - boat);
    if (d > farthest) farthest = d, t1 = t;
  }
  ASSERT_GT(farthest, 30.0) << "the boat does not move";
  world.animate(t1);
  sound.update(world, listener, t1 - t0);
  double left_behind = level(sound);
  EXPECT_GT(aboard, 2.0 * left_behind) << "aboard " << aboard << " later " << left_behind;
}

}  // namespace
}  // namespace facet::test
