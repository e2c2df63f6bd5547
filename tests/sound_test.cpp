// Positional sound, heard through OpenAL Soft's loopback device (no sound card needed): stereo
// panning follows the source and the listener's orientation, distance lowers the level, muting
// silences, Doppler shifts pitch; the synthesized loops are deterministic, audible and seamless;
// with no audio device the scene runs silently after one warning line.
#include "facet/sound.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "support/required_package.hpp"

namespace facet {
namespace {

constexpr int kRate = 44100;
// OpenAL Soft ramps gain and panning changes over its next mixing update, so the frames rendered
// right after a change are thrown away and measurements see the settled mix.
constexpr int kSettleFrames = 8192;
// Levels are measured over exactly one loop of a kLoopSeconds sound: the waterfall swells by
// about +-25% within its loop, and a whole loop has the same RMS wherever it starts.
constexpr double kLoopSeconds = 0.5;
constexpr int kMeasureFrames = static_cast<int>(kLoopSeconds * kRate);

struct Levels {
  double left = 0.0, right = 0.0;
  double total() const { return std::sqrt((left * left + right * right) / 2.0); }
};

Levels rms(const std::vector<float>& stereo) {
  double sum[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < stereo.size(); ++i) sum[i % 2] += double(stereo[i]) * stereo[i];
  const double frames = static_cast<double>(stereo.size() / 2);
  return {std::sqrt(sum[0] / frames), std::sqrt(sum[1] / frames)};
}

// Lets the mix settle after a change, then measures one loop.
Levels settled_levels(SoundScene& scene) {
  scene.render_loopback(kSettleFrames);
  return rms(scene.render_loopback(kMeasureFrames));
}

// (Fields set one by one: GCC 12 warns about designated initializers that skip a member.)
SoundSceneDesc loopback_desc(int sample_rate = kRate) {
  SoundSceneDesc desc;
  desc.output = SoundOutput::loopback;
  desc.loopback_sample_rate = sample_rate;
  return desc;
}

SoundScene loopback_scene() { return SoundScene(loopback_desc()); }

// A device name no backend has, so the scene has no device on any machine.
SoundSceneDesc missing_device_desc() {
  SoundSceneDesc desc;
  desc.device_name = "facet-test-no-such-device";
  return desc;
}

#define REQUIRE_LOOPBACK(scene)                                                      \
  FACET_REQUIRE_PACKAGE((scene).available(),                                         \
                        "OpenAL Soft's loopback device (ALC_SOFT_loopback, Debian: " \
                        "libopenal1) is not available, so nothing can be heard")

// The level a listener at the origin looking down -Z hears from a waterfall at `position`.
Levels levels_from(glm::vec3 position, glm::vec3 forward = {0, 0, -1}) {
  SoundScene scene = loopback_scene();
  if (!scene.available()) return {};
  scene.set_listener(glm::vec3(0.0f), forward, glm::vec3(0, 1, 0));
  const int id = scene.add_source(waterfall_noise(kLoopSeconds), position);
  scene.play(id);
  return settled_levels(scene);
}

TEST(Sound, SourceOnTheRightIsLouderOnTheRight) {
  SoundScene probe = loopback_scene();
  REQUIRE_LOOPBACK(probe);
  const Levels levels = levels_from({5, 0, 0});
  std::printf("source right (+5,0,0): left rms %.5f, right rms %.5f\n", levels.left, levels.right);
  EXPECT_GT(levels.right, 0.01);
  EXPECT_GT(levels.right, 2.0 * levels.left);
}

TEST(Sound, SourceBehindOnTheLeftIsLouderOnTheLeft) {
  SoundScene probe = loopback_scene();
  REQUIRE_LOOPBACK(probe);
  const Levels levels = levels_from({-3, 0, 4});
  std::printf("source behind-left (-3,0,4): left rms %.5f, right rms %.5f\n", levels.left,
              levels.right);
  EXPECT_GT(levels.left, 0.01);
  EXPECT_GT(levels.left, 2.0 * levels.right);
}

TEST(Sound, TurningTheListenerAroundSwapsTheSides) {
  SoundScene probe = loopback_scene();
  REQUIRE_LOOPBACK(probe);
  const Levels levels = levels_from({5, 0, 0}, {0, 0, 1});  // looking down +Z: +X is on the left
  std::printf("listener turned, source at (+5,0,0): left rms %.5f, right rms %.5f\n", levels.left,
              levels.right);
  EXPECT_GT(levels.left, 2.0 * levels.right);
}

TEST(Sound, MovingTheSourceAwayLowersTheLevel) {
  SoundScene scene = loopback_scene();
  REQUIRE_LOOPBACK(scene);
  const int id =
      scene.add_source(waterfall_noise(kLoopSeconds), {0, 0, -2});  // reference distance 4
  scene.play(id);
  const Levels near = settled_levels(scene);
  scene.set_source(id, {0, 0, -20}, glm::vec3(0.0f));
  const Levels far = settled_levels(scene);
  std::printf("distance 2: rms %.5f; distance 20: rms %.5f (ratio %.2f)\n", near.total(),
              far.total(), near.total() / far.total());
  // Inverse distance clamped below 4: gain 1 at distance 2, 4 / 20 at distance 20.
  EXPECT_GT(near.total(), 4.0 * far.total());
  EXPECT_NEAR(near.total() / far.total(), 5.0, 0.25);
  EXPECT_GT(far.total(), 0.001);  // quieter, not silent
}

TEST(Sound, MutingSilencesAndUnmutingRestores) {
  SoundScene scene = loopback_scene();
  REQUIRE_LOOPBACK(scene);
  const int id = scene.add_source(engine_hum(kLoopSeconds), {0, 0, -3});
  scene.play(id);
  const Levels playing = settled_levels(scene);
  scene.set_muted(true);
  EXPECT_TRUE(scene.muted());
  const Levels muted = settled_levels(scene);
  scene.set_muted(false);
  const Levels unmuted = settled_levels(scene);
  std::printf("playing rms %.5f, muted rms %.7f, unmuted rms %.5f\n", playing.total(),
              muted.total(), unmuted.total());
  EXPECT_GT(playing.total(), 0.01);
  EXPECT_LT(muted.total(), 1e-5);
  EXPECT_GT(unmuted.total(), 0.5 * playing.total());
}

TEST(Sound, StoppedSourcesAreSilent) {
  SoundScene scene = loopback_scene();
  REQUIRE_LOOPBACK(scene);
  const int id = scene.add_source(propeller_buzz(kLoopSeconds), {0, 0, -3});
  EXPECT_LT(settled_levels(scene).total(), 1e-6);  // added stopped
  scene.play(id);
  EXPECT_GT(settled_levels(scene).total(), 0.01);
  scene.stop(id);
  EXPECT_LT(settled_levels(scene).total(), 1e-6);
}

// A 441 Hz sine (exactly 441 cycles in its one-second loop).
SoundBuffer sine_441() {
  SoundBuffer buffer;
  buffer.sample_rate = kRate;
  buffer.samples.resize(kRate);
  for (int i = 0; i < kRate; ++i) {
    const double phase = 2.0 * std::numbers::pi * 441.0 * i / kRate;
    buffer.samples[i] = static_cast<std::int16_t>(std::lround(16000.0 * std::sin(phase)));
  }
  return buffer;
}

// Frequency of the left channel from its rising zero crossings over one second.
double left_frequency(SoundScene& scene) {
  scene.render_loopback(kSettleFrames);
  const std::vector<float> stereo = scene.render_loopback(kRate);
  int rising = 0;
  for (std::size_t i = 2; i < stereo.size(); i += 2) rising += stereo[i - 2] < 0 && stereo[i] >= 0;
  return rising;
}

TEST(Sound, DopplerRaisesThePitchOfAnApproachingSource) {
  SoundScene scene = loopback_scene();
  REQUIRE_LOOPBACK(scene);
  const int id = scene.add_source(sine_441(), {0, 0, -10});
  scene.play(id);
  const double still = left_frequency(scene);
  // 34.3 m/s toward the listener: f' = f * c / (c - v) = f * 343 / 308.7 = f * 1.111.
  scene.set_source(id, {0, 0, -10}, {0, 0, 34.3f});
  const double approaching = left_frequency(scene);
  std::printf("441 Hz source: still %.0f Hz, approaching at 34.3 m/s %.0f Hz\n", still,
              approaching);
  EXPECT_NEAR(still, 441.0, 2.0);
  EXPECT_NEAR(approaching / still, 343.0 / 308.7, 0.01);
}

struct Synth {
  const char* name;
  SoundBuffer (*make)(double seconds);
};
constexpr Synth kSynths[] = {
    {"waterfall_noise", waterfall_noise},
    {"engine_hum", engine_hum},
    {"propeller_buzz", propeller_buzz},
};

TEST(Sound, SynthesizersAreDeterministicAudibleAndUnclipped) {
  for (const Synth& synth : kSynths) {
    for (const double seconds : {0.25, 1.5}) {
      SCOPED_TRACE(std::string(synth.name) + " " + std::to_string(seconds) + " s");
      const SoundBuffer a = synth.make(seconds);
      const SoundBuffer b = synth.make(seconds);
      EXPECT_EQ(a.samples, b.samples);
      EXPECT_EQ(a.sample_rate, kRate);
      EXPECT_EQ(a.samples.size(), static_cast<std::size_t>(std::lround(seconds * kRate)));
      double sum = 0.0;
      int peak = 0;
      for (std::int16_t s : a.samples) {
        sum += double(s) * s;
        peak = std::max(peak, std::abs(int(s)));
      }
      const double level = std::sqrt(sum / static_cast<double>(a.samples.size()));
      EXPECT_GT(level, 2000.0);  // about -24 dBFS or louder
      EXPECT_LT(peak, 32000);    // headroom: never at full scale
    }
  }
}

// OpenAL plays a looping buffer end to start, so the step from the last sample to the first must
// look like any other step; a seam shows as a click, a step far outside the usual ones.
TEST(Sound, SynthesizersLoopSeamlessly) {
  for (const Synth& synth : kSynths) {
    SCOPED_TRACE(synth.name);
    const std::vector<std::int16_t> s = synth.make(1.0).samples;
    double sum = 0.0;
    int largest = 0;
    for (std::size_t i = 1; i < s.size(); ++i) {
      const int step = std::abs(s[i] - s[i - 1]);
      sum += double(step) * step;
      largest = std::max(largest, step);
    }
    const double typical = std::sqrt(sum / static_cast<double>(s.size() - 1));
    const int seam = std::abs(s.front() - s.back());
    std::printf("%s: seam step %d, rms step %.0f, largest step %d\n", synth.name, seam, typical,
                largest);
    EXPECT_LE(seam, largest);
    EXPECT_LE(seam, 3.0 * typical);
  }
}

TEST(Sound, SynthesizersRejectBadLengths) {
  for (const Synth& synth : kSynths) {
    for (const double seconds : {0.0, -1.0, 61.0, std::numeric_limits<double>::quiet_NaN()}) {
      EXPECT_THROW(synth.make(seconds), Error) << synth.name << " " << seconds;
    }
  }
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

TEST(Sound, WithoutADeviceTheSceneWarnsOnceAndRunsSilently) {
  testing::internal::CaptureStderr();
  SoundScene scene(missing_device_desc());
  // Every call is accepted and does nothing; ids are still handed out.
  EXPECT_EQ(scene.add_source(waterfall_noise(0.1), {1, 2, 3}), 0);
  EXPECT_EQ(scene.add_source(engine_hum(0.1), {1, 2, 3}), 1);
  scene.set_source(1, {4, 5, 6}, {1, 0, 0});
  scene.play(0);
  scene.stop(0);
  scene.set_listener({0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0});
  scene.set_muted(true);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(scene.available());
  EXPECT_TRUE(scene.muted());
  ASSERT_EQ(lines(err).size(), 1u) << err;
  EXPECT_EQ(err, "facet: no audio device \"facet-test-no-such-device\"; running silently\n");
  EXPECT_THROW(scene.play(2), Error);  // never handed out
}

// This is what runs on servers and CI: without a sound card OpenAL Soft's ALSA backend fails to
// open "default" (and prints a page of ALSA errors, which SoundScene keeps off stderr).
TEST(Sound, DefaultDeviceEitherPlaysOrWarnsOnce) {
  testing::internal::CaptureStderr();
  std::string err;
  {
    SoundScene scene;
    scene.play(scene.add_source(engine_hum(0.1), {0, 0, -5}));
    err = testing::internal::GetCapturedStderr();
    std::printf("default device: %s\n", scene.available() ? "available" : "none");
    if (scene.available()) {
      EXPECT_EQ(err, "");
    } else {
      ASSERT_EQ(lines(err).size(), 1u) << err;
      EXPECT_EQ(err, "facet: no audio device; running silently\n");
    }
  }
}

TEST(Sound, BadArgumentsThrow) {
  SoundScene scene = loopback_scene();
  const SoundBuffer sound = engine_hum(0.1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(scene.add_source(SoundBuffer{}, {0, 0, 0}), Error);
  EXPECT_THROW(scene.add_source(sound, {nan, 0, 0}), Error);
  EXPECT_THROW(scene.add_source(sound, {0, 0, 0}, -1.0f), Error);
  EXPECT_THROW(scene.add_source(sound, {0, 0, 0}, 1.0f, 0.0f), Error);
  const int id = scene.add_source(sound, {0, 0, 0});
  EXPECT_THROW(scene.set_source(id + 1, {0, 0, 0}), Error);
  EXPECT_THROW(scene.set_source(-1, {0, 0, 0}), Error);
  EXPECT_THROW(scene.set_source(id, {0, 0, 0}, {0, nan, 0}), Error);
  EXPECT_THROW(scene.set_listener({0, 0, 0}, {0, 1, 0}, {0, 2, 0}), Error);  // parallel
  EXPECT_THROW(scene.set_listener({0, 0, 0}, {0, 0, 0}, {0, 1, 0}), Error);  // zero
  EXPECT_THROW(scene.render_loopback(-1), Error);
  EXPECT_THROW(SoundScene(loopback_desc(0)), Error);
  SoundScene moved = std::move(scene);
  // Using the moved-from scene is the point here: it must throw, not crash.
  // NOLINTNEXTLINE(bugprone-use-after-move,clang-analyzer-cplusplus.Move)
  EXPECT_THROW(scene.play(id), Error);
  moved.play(id);
}

TEST(Sound, RenderLoopbackNeedsALoopbackScene) {
  testing::internal::CaptureStderr();
  SoundScene scene(missing_device_desc());
  testing::internal::GetCapturedStderr();
  EXPECT_THROW(scene.render_loopback(16), Error);
}

}  // namespace
}  // namespace facet
