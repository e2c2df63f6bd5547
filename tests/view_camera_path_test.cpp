// `facet view --camera-path FILE`: bad files fail with one "FILE:LINE: problem" line and exit
// code 2, before any window opens; a good path drives the camera exactly, so a scripted frame at
// a key's time matches `facet render` from that key's pose, and between keys the pose is
// interpolated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/golden.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kUsageError = 2;

CommandResult view_with_path(const fs::path& path, const std::string& more = "") {
  std::string command = "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" ";
  command += std::string(FACET_CLI) + " view --scene shapes --frames 1 --size 64x36";
  command += " --camera-path '" + path.string() + "' " + more;
  return run_command(command);
}

// The one line a bad path file gives, or a failure.
std::string path_error(const std::string& name, const std::string& text) {
  fs::path dir = fresh_test_dir("facet_camera_path_", name);
  fs::path file = dir / "path.txt";
  std::ofstream(file) << text;
  CommandResult r = view_with_path(file);
  EXPECT_EQ(r.exit_code, kUsageError) << r.stderr_text;
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  std::string prefix = file.string() + ":";
  EXPECT_NE(r.stderr_text.find(prefix), std::string::npos) << r.stderr_text;
  return r.stderr_text;
}

TEST(ViewCameraPath, BadFilesNameTheFileAndLine) {
  EXPECT_NE(path_error("count", "# t x y z yaw pitch\n0 0 1 5 0 0\n\n2 1 1 5\n")
                .find(":4: expected 6 numbers"),
            std::string::npos);
  EXPECT_NE(path_error("word", "0 0 1 5 0 0\n1 0 1 five 0 0\n").find(":2: 'five' is not a number"),
            std::string::npos);
  EXPECT_NE(path_error("order", "0 0 1 5 0 0\n2 0 1 5 0 0\n2 1 1 5 0 0\n")
                .find(":3: times must increase"),
            std::string::npos);
  EXPECT_NE(path_error("pitch", "0 0 1 5 0 95\n").find(":1: pitch must be inside"),
            std::string::npos);
  EXPECT_NE(path_error("empty", "# nothing here\n\n").find("no camera keys"), std::string::npos);
  EXPECT_NE(path_error("far", "0 0 1 5 0 0\n1 1e39 1 5 0 0\n").find(":2: values must lie within"),
            std::string::npos);
}

TEST(ViewCameraPath, MissingFileIsOneLine) {
  fs::path dir = fresh_test_dir("facet_camera_path_", "missing");
  CommandResult r = view_with_path(dir / "absent.txt");
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("absent.txt: cannot open the camera path"), std::string::npos)
      << r.stderr_text;
}

bool have_xvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// The eye and the point one unit ahead for a yaw/pitch pose (FirstPersonCamera's convention:
// yaw 0 looks down -Z, positive yaw turns left, positive pitch looks up).
std::string render_flags(float x, float y, float z, float yaw_degrees, float pitch_degrees) {
  float yaw = yaw_degrees * 3.14159265358979f / 180.0f;
  float pitch = pitch_degrees * 3.14159265358979f / 180.0f;
  float fx = -std::sin(yaw) * std::cos(pitch), fy = std::sin(pitch),
        fz = -std::cos(yaw) * std::cos(pitch);
  char text[256];
  std::snprintf(text, sizeof text, " --eye %.9g,%.9g,%.9g --target %.9g,%.9g,%.9g", x, y, z, x + fx,
                y + fy, z + fz);
  return text;
}

// A frame of `facet view` at --time t on the path, and `facet render` from `pose_flags`.
void expect_view_matches_render(const std::string& name, const std::string& path_text, double t,
                                const std::string& pose_flags) {
  fs::path dir = fresh_test_dir("facet_camera_path_", name);
  fs::path file = dir / "path.txt";
  std::ofstream(file) << path_text;
  std::string shot = (dir / "view.png").string(), rendered = (dir / "render.png").string();
  std::string command = "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" ";
  command += "xvfb-run -a -s '-screen 0 1280x720x24' " + std::string(FACET_CLI);
  command += " view --scene shapes --frames 2 --size 320x180 --time " + std::to_string(t);
  command += " --camera-path '" + file.string() + "' --screenshot '" + shot + "'";
  CommandResult v = run_command(command);
  ASSERT_EQ(v.exit_code, 0) << v.stderr_text;
  // The viewer draws no shadows (yet): the render leaves them out too.
  std::string render =
      std::string(FACET_CLI) + " render --scene shapes --size 320x180 --shadows off";
  render += pose_flags + " -o '" + rendered + "'";
  CommandResult r = run_command(render);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  Rgba8Image a = read_png(shot), b = read_png(rendered);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  std::size_t outliers = 0;
  for (std::size_t p = 0; p < a.pixels.size(); p += 4) {
    int delta = 0;
    for (int c = 0; c < 3; ++c)
      delta = std::max(delta, std::abs(a.pixels[p + c] - b.pixels[p + c]));
    if (delta > kGoldenTolerance.max_channel_delta) ++outliers;
  }
  EXPECT_LE(static_cast<double>(outliers) / (a.pixels.size() / 4),
            kGoldenTolerance.max_outlier_fraction)
      << outliers << " pixels differ";
}

const std::string kPath =
    "# a short fly-by of the shapes scene\n"
    "0    -6 3 8    -30 -15\n"
    "4     2 2 9      10 -10   # the second key\n"
    "8     7 4 5      45 -25\n";

TEST(ViewCameraPath, FrameAtAKeyTimeMatchesRenderFromThatKey) {
  FACET_REQUIRE_PACKAGE(have_xvfb(), "xvfb-run is not installed");
  expect_view_matches_render("key", kPath, 4.0, render_flags(2, 2, 9, 10, -10));
  // Outside the keys the camera holds the first and the last key.
  expect_view_matches_render("after", kPath, 100.0, render_flags(7, 4, 5, 45, -25));
}

TEST(ViewCameraPath, BetweenTwoKeysTheMidpointIsHalfway) {
  FACET_REQUIRE_PACKAGE(have_xvfb(), "xvfb-run is not installed");
  // With two keys the spline's end tangents make t = 5 exactly the average of the two poses.
  expect_view_matches_render("mid", "0 -4 2 8 -20 -10\n10 4 4 8 20 -20\n", 5.0,
                             render_flags(0, 3, 8, 0, -15));
}

}  // namespace
}  // namespace facet::test
