// `facet view` without a person at the keyboard: scripted frames under Xvfb match `facet render`
// of the same camera, the islands' animation is a function of --time, and with no display the
// command fails with one line that points to xvfb-run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/golden.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kUsageError = 2;

bool have_xvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// Runs `facet view <args>` on a fresh virtual display. In sanitizer builds, leak reports are
// turned off for this child: libX11 and SDL keep allocations until exit that are not ours.
CommandResult run_view_under_xvfb(const std::string& args) {
  return run_command(std::string("ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" ") +
                     "xvfb-run -a -s \"-screen 0 1280x720x24\" " + FACET_CLI + " view " + args);
}

// Pixels differ by at most the golden tolerance: channel delta, and the fraction of outliers.
void expect_images_match(const Rgba8Image& a, const Rgba8Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  std::size_t outliers = 0;
  for (std::size_t p = 0; p < a.pixels.size(); p += 4) {
    int delta = 0;
    for (std::size_t c = 0; c < 4; ++c)
      delta = std::max(delta, std::abs(a.pixels[p + c] - b.pixels[p + c]));
    if (delta > kGoldenTolerance.max_channel_delta) ++outliers;
  }
  double fraction = static_cast<double>(outliers) / (a.pixels.size() / 4);
  EXPECT_LE(fraction, kGoldenTolerance.max_outlier_fraction) << outliers << " pixels differ";
}

TEST(View, ScriptedFramesMatchRenderOfTheSameCamera) {
  FACET_REQUIRE_PACKAGE(have_xvfb(), "xvfb-run is not installed");
  fs::path dir = fresh_test_dir("facet_view_", "shapes");
  std::string shot = (dir / "v.png").string();
  CommandResult r =
      run_view_under_xvfb("--scene shapes --frames 3 --size 320x180 --screenshot '" + shot + "'");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("3 frames"), std::string::npos) << r.stdout_text;
  std::string rendered = (dir / "r.png").string();
  // The viewer draws no shadows (yet): the render leaves them out too.
  CommandResult rr =
      run_command(std::string(FACET_CLI) +
                  " render --scene shapes --size 320x180 --shadows off -o '" + rendered + "'");
  ASSERT_EQ(rr.exit_code, 0) << rr.stderr_text;
  Rgba8Image view = read_png(shot);
  EXPECT_EQ(view.width, 320);
  EXPECT_EQ(view.height, 180);
  expect_images_match(view, read_png(rendered));
}

// A glTF model's animation plays in the viewer: --time 1 and 4 show two poses, each the same
// again at the same time (AnimatedModel's poses are tested against import in
// gltf_khronos_test.cpp).
TEST(View, AnimatedModelsArePosedByTheClock) {
  FACET_REQUIRE_PACKAGE(have_xvfb(), "xvfb-run is not installed");
  const fs::path dir = fresh_test_dir("facet_view_", "animated");
  const std::string model = std::string(FACET_KHRONOS_DIR) + "/SimpleSkin.gltf";
  auto shot_at = [&](const std::string& time, const std::string& name) {
    const std::string shot = (dir / name).string();
    const CommandResult r = run_view_under_xvfb("'" + model + "' --frames 2 --time " + time +
                                                " --size 160x90 --screenshot '" + shot + "'");
    EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
    return read_png(shot);
  };
  const Rgba8Image first = shot_at("1", "a.png"), again = shot_at("1", "b.png");
  const Rgba8Image later = shot_at("4", "c.png");
  EXPECT_TRUE(first.pixels == again.pixels) << "the same --time gave different images";
  EXPECT_FALSE(first.pixels == later.pixels) << "the pose did not change";
}

TEST(View, ShadowsWhenAskedFor) {
  FACET_REQUIRE_PACKAGE(have_xvfb(), "xvfb-run is not installed");
  const fs::path dir = fresh_test_dir("facet_view_", "shadows");
  auto shot_with = [&](const std::string& shadows) {
    const std::string shot = (dir / (shadows + ".png")).string();
    const CommandResult r =
        run_view_under_xvfb("--scene shapes --frames 2 --size 160x90 --shadows " + shadows +
                            " --screenshot '" + shot + "'");
    EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
    return read_png(shot);
  };
  EXPECT_FALSE(shot_with("on").pixels == shot_with("off").pixels) << "no shadow drawn";
  const CommandResult bad = run_view_under_xvfb("--scene shapes --frames 1 --shadow-map-size 0");
  EXPECT_EQ(bad.exit_code, 2) << bad.stderr_text;
}

TEST(View, IslandsAtAFixedTimeAreDeterministic) {
  FACET_REQUIRE_PACKAGE(have_xvfb(), "xvfb-run is not installed");
  fs::path dir = fresh_test_dir("facet_view_", "islands");
  std::string shots[2] = {(dir / "a.png").string(), (dir / "b.png").string()};
  for (const std::string& shot : shots) {
    // One sample a pixel: the golden holds the world at t = 3, not the anti-aliasing.
    CommandResult r = run_view_under_xvfb(
        "--scene islands --frames 2 --time 5 --size 320x180 "
        "--screenshot '" +
        shot + "'");
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  }
  Rgba8Image a = read_png(shots[0]);
  Rgba8Image b = read_png(shots[1]);
  EXPECT_EQ(a.width, 320);
  EXPECT_EQ(a.height, 180);
  EXPECT_TRUE(a.pixels == b.pixels) << "the same --time gave different images";
}

// The islands world as `facet view` shows it at t = 3 s, held against a golden image; the same t
// renders the same image again.
TEST(View, IslandsAtThreeSecondsMatchTheGolden) {
  FACET_REQUIRE_PACKAGE(have_xvfb(), "xvfb-run is not installed");
  fs::path dir = fresh_test_dir("facet_view_", "islands_golden");
  std::string shots[2] = {(dir / "a.png").string(), (dir / "b.png").string()};
  for (const std::string& shot : shots) {
    CommandResult r = run_view_under_xvfb(
        "--scene islands --frames 5 --time 3 --size 320x180 --msaa 1 --screenshot '" + shot + "'");
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  }
  expect_matches_golden(shots[0], "view_islands_t3");
  EXPECT_TRUE(read_png(shots[0]).pixels == read_png(shots[1]).pixels)
      << "the same --time gave different images";
}

TEST(View, WithoutADisplayFailsWithOneLineSuggestingXvfb) {
  fs::path dir = fresh_test_dir("facet_view_", "nodisplay");
  std::string shot = (dir / "v.png").string();
  CommandResult r =
      run_command(std::string("ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" ") +
                  "env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " + FACET_CLI +
                  " view --scene shapes --frames 1 --size 64x36 " + "--screenshot '" + shot + "'");
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("xvfb-run"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(shot));
}

// A sample count MSAA does not have is refused before any window opens.
TEST(View, UnsupportedMsaaIsOneErrorLine) {
  for (const char* samples : {"3", "0", "32"}) {
    const CommandResult r =
        run_command(std::string("env -u DISPLAY -u WAYLAND_DISPLAY ") + FACET_CLI +
                    " view --scene shapes --frames 1 --msaa " + samples);
    EXPECT_EQ(r.exit_code, kUsageError) << samples;
    EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find("--msaa: must be 1, 2, 4, 8 or 16"), std::string::npos)
        << r.stderr_text;
  }
}

}  // namespace
}  // namespace facet::test
