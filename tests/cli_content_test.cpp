// `facet render MODEL` with real content, through the real binary: imported models (Debian test
// files and files written by support/cli_content_inputs.cpp) and the content flags changing the
// image the way they should. The error contract is in cli_content_errors_test.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <ostream>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "support/cli_content_inputs.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = kCliWidth;
constexpr int kHeight = kCliHeight;
const std::string& kSize = kCliSize;

// `facet render <args> -o out.png --size 320x180` in a fresh directory: expects success, one
// summary line and nothing else on stdout, and returns the image (empty on failure). Anything
// on stderr is a failure unless allow_stderr.
Rgba8Image render(const std::string& name, const std::string& args, bool allow_stderr = false) {
  fs::path dir = fresh_test_dir("facet_cli_content_", name);
  CommandResult r = run_facet(dir, "render " + args + " -o out.png" + kSize);
  EXPECT_EQ(r.exit_code, 0) << "facet render " << args << "\n" << r.stderr_text;
  if (!allow_stderr) {
    EXPECT_EQ(r.stderr_text, "") << "facet render " << args;
  }
  std::vector<std::string> out = lines_of(r.stdout_text);
  EXPECT_EQ(out.size(), 1u) << r.stdout_text;
  if (!out.empty()) {
    EXPECT_EQ(out[0].rfind("out.png: 320x180, ", 0), 0u) << out[0];
  }
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"out.png"});
  try {
    Rgba8Image image = read_png((dir / "out.png").string());
    EXPECT_EQ(image.width, kWidth);
    EXPECT_EQ(image.height, kHeight);
    return image;
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
    return {};
  }
}

// --- looking at pixels --------------------------------------------------------------------

struct Rgb {
  int r = 0, g = 0, b = 0;
};

Rgb at(const Rgba8Image& image, int x, int y) {
  const std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
  return {p[0], p[1], p[2]};
}

int distance(Rgb a, Rgb b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

// The default --background 0.53,0.66,0.82 as 8-bit sRGB.
const Rgb kBackground{135, 168, 209};

bool is_background(Rgb c) { return distance(c, kBackground) <= 3; }

// Mean over pixels of the per-channel absolute difference, 0..255; 255 for mismatched images.
double mean_difference(const Rgba8Image& a, const Rgba8Image& b) {
  if (a.width != b.width || a.height != b.height || a.pixels.empty()) return 255.0;
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) sum += distance(at(a, x, y), at(b, x, y));
  return sum / (3.0 * a.width * a.height);
}

std::size_t distinct_colors(const Rgba8Image& image) {
  std::set<int> colors;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      Rgb c = at(image, x, y);
      colors.insert(c.r << 16 | c.g << 8 | c.b);
    }
  }
  return colors.size();
}

// The pixels where `plain` shows the model rather than the background.
std::vector<std::pair<int, int>> model_pixels(const Rgba8Image& plain) {
  std::vector<std::pair<int, int>> out;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x)
      if (!is_background(at(plain, x, y))) out.emplace_back(x, y);
  return out;
}

double luminance(Rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// A model render is a picture: the background shows, the model covers a good part of the
// frame, and there are many colors (shading), not one flat fill.
void expect_a_picture(const Rgba8Image& image, std::size_t min_colors = 50) {
  if (image.pixels.empty()) return;  // already reported
  std::size_t covered = model_pixels(image).size();
  std::size_t total = static_cast<std::size_t>(image.width) * image.height;
  EXPECT_GT(covered, total / 20) << "the model covers almost nothing";
  EXPECT_LT(covered, total) << "no background left: not framed";
  EXPECT_GE(distinct_colors(image), min_colors) << "a flat image";
}

// --- models render ------------------------------------------------------------------------

TEST(CliContentModels, BunnyObj) {
  REQUIRE_INSTALLED(kBunny);
  expect_a_picture(render("bunny", kBunny));
}

TEST(CliContentModels, TexturedGlb) {
  REQUIRE_INSTALLED(kBoxGlb);
  Rgba8Image image = render("box_glb", kBoxGlb);
  expect_a_picture(image);
}

TEST(CliContentModels, ObjWithMtlMaterials) {
  Rgba8Image image = render("cube_obj", input("cube.obj"));
  // Three flat faces under directional lights are three flat colors, plus the background.
  expect_a_picture(image, 4);
  // The three materials' colors all show: some pixel is mostly red, green, blue.
  bool red = false, green = false, blue = false;
  for (auto [x, y] : model_pixels(image)) {
    Rgb c = at(image, x, y);
    red = red || (c.r > c.g + 60 && c.r > c.b + 60);
    green = green || (c.g > c.r + 60 && c.g > c.b + 60);
    blue = blue || (c.b > c.r + 60 && c.b > c.g + 60);
  }
  EXPECT_TRUE(red && green && blue) << "red " << red << " green " << green << " blue " << blue;
}

TEST(CliContentModels, CourseFormatD) { expect_a_picture(render("ball_d", input("ball.d"))); }

TEST(CliContentModels, MissingTextureWarnsOnceAndDrawsAChecker) {
  fs::path dir = fresh_test_dir("facet_cli_content_", "lost_texture");
  CommandResult r = run_facet(dir, "render " + input("lost_texture.obj") + " -o out.png" + kSize);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(lines_of(r.stdout_text).size(), 1u) << r.stdout_text;
  std::vector<std::string> warnings = lines_of(r.stderr_text);
  ASSERT_EQ(warnings.size(), 1u) << "two materials share the texture; warn once:\n"
                                 << r.stderr_text;
  EXPECT_EQ(warnings[0].rfind("facet: warning:", 0), 0u) << warnings[0];
  EXPECT_NE(warnings[0].find("nowhere.png"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("lost_texture.obj"), std::string::npos) << warnings[0];
  expect_a_picture(read_png((dir / "out.png").string()));
}

// --- flags change the image ---------------------------------------------------------------

// Two renders of the same model must differ by more than rounding (mean channel difference
// over the whole image; the ball covers about a third of it).
constexpr double kClearlyDifferent = 0.25;

TEST(CliContentFlags, ShadingModelOverride) {
  std::string ball = input("ball.d");
  Rgba8Image pbr = render("shading_pbr", ball + " --shading pbr");
  Rgba8Image phong = render("shading_phong", ball + " --shading phong");
  expect_a_picture(pbr);
  expect_a_picture(phong);
  EXPECT_GT(mean_difference(pbr, phong), kClearlyDifferent);
}

TEST(CliContentFlags, LightKindsAndCount) {
  std::string ball = input("ball.d");
  Rgba8Image plain = render("light_default", ball);
  Rgba8Image down = render("light_dir", ball + " --light dir,0,-1,0");
  Rgba8Image point = render("light_point", ball + " --light point,2,3,3,1,1,1,20");
  Rgba8Image both = render("light_two", ball + " --light dir,0,-1,0 --light dir,1,0,0,1,0,0");
  EXPECT_GT(mean_difference(plain, down), kClearlyDifferent) << "--light replaces the defaults";
  EXPECT_GT(mean_difference(down, point), kClearlyDifferent);
  EXPECT_GT(mean_difference(down, both), kClearlyDifferent) << "the second --light is ignored";
  // A light from above: the top of the ball is brighter than the bottom.
  if (down.pixels.empty()) return;
  auto pixels = model_pixels(plain);
  ASSERT_FALSE(pixels.empty());
  auto [top_y, bottom_y] = std::minmax_element(pixels.begin(), pixels.end(),
                                               [](auto a, auto b) { return a.second < b.second; });
  EXPECT_GT(luminance(at(down, kWidth / 2, top_y->second + 4)),
            luminance(at(down, kWidth / 2, bottom_y->second - 4)) + 20);
  // The added red light travels +x: the left side gains red, the right side does not.
  int left_x = kWidth, right_x = 0;
  for (auto [x, y] : pixels) {
    if (y == kHeight / 2) left_x = std::min(left_x, x), right_x = std::max(right_x, x);
  }
  Rgb left_down = at(down, left_x + 4, kHeight / 2), left_both = at(both, left_x + 4, kHeight / 2);
  EXPECT_GT(left_both.r, left_down.r + 20);
  EXPECT_NEAR(left_both.g, left_down.g, 3);
  EXPECT_LE(distance(at(both, right_x - 4, kHeight / 2), at(down, right_x - 4, kHeight / 2)), 6);
}

// Fog pulls every model pixel toward the fog color (default: the background).
void expect_fogged(const Rgba8Image& plain, const Rgba8Image& fogged) {
  double before = 0.0, after = 0.0;
  auto pixels = model_pixels(plain);
  ASSERT_FALSE(pixels.empty());
  if (fogged.pixels.empty()) return;
  for (auto [x, y] : pixels) {
    before += distance(at(plain, x, y), kBackground);
    after += distance(at(fogged, x, y), kBackground);
  }
  EXPECT_LT(after, before * 0.8) << "model pixels did not move toward the fog color";
}

TEST(CliContentFlags, FogDefaultsMoveTheModelTowardTheFogColor) {
  std::string ball = input("ball.d");
  Rgba8Image plain = render("fog_none", ball);
  expect_fogged(plain, render("fog_linear", ball + " --fog linear"));
  expect_fogged(plain, render("fog_exp", ball + " --fog exp,0.3"));
}

TEST(CliContentFlags, FogGrowsWithDistance) {
  // A floor running away from the camera; red linear fog from 2 to 30 units, a red the
  // default tone mapping shows as it is (its brightest channel below the curve's knee).
  std::string floor = input("floor.d") + " --eye 0,1,1 --target 0,0,-10";
  Rgba8Image plain = render("fog_floor_plain", floor);
  Rgba8Image fogged = render("fog_floor_linear", floor + " --fog linear,2,30 --fog-color 0.85,0,0");
  if (plain.pixels.empty() || fogged.pixels.empty()) return;
  // The floor's rows in the centre column: the top row is the far end, the bottom the near.
  int far_y = -1, near_y = -1;
  for (int y = 0; y < kHeight; ++y) {
    if (is_background(at(plain, kWidth / 2, y))) continue;
    if (far_y < 0) far_y = y;
    near_y = y;
  }
  ASSERT_GE(far_y, 0) << "the floor is not in view";
  const Rgb red{217, 0, 0};
  EXPECT_LE(distance(at(fogged, kWidth / 2, far_y + 1), red), 12) << "far floor not fully fogged";
  EXPECT_LE(distance(at(fogged, kWidth / 2, near_y), at(plain, kWidth / 2, near_y)), 6)
      << "the floor under the camera, nearer than the fog start, changed";
  int middle_y = (far_y + near_y) / 2;
  int moved = distance(at(fogged, kWidth / 2, middle_y), at(plain, kWidth / 2, middle_y));
  EXPECT_GT(moved, 6) << "no fog between start and end";
  EXPECT_GT(distance(at(plain, kWidth / 2, middle_y), red), 12);
}

TEST(CliContentFlags, SkyEnvironmentReplacesTheFlatBackground) {
  std::string ball = input("ball.d");
  Rgba8Image plain = render("env_none", ball);
  Rgba8Image sky = render("env_sky", ball + " --env sky");
  if (sky.pixels.empty()) return;
  EXPECT_TRUE(is_background(at(plain, 0, 0)));
  Rgb top = at(sky, 0, 0), bottom = at(sky, 0, kHeight - 1);
  EXPECT_FALSE(is_background(top));
  EXPECT_FALSE(is_background(bottom));
  EXPECT_GT(distance(top, bottom), 30) << "no gradient from zenith to ground";
  EXPECT_GT(distinct_colors(sky), distinct_colors(plain));
}

TEST(CliContentFlags, TextureProjectionsDiffer) {
  std::string ball = input("ball.d") + " --texture " + input("texture.png");
  Rgba8Image plain = render("texture_none", input("ball.d"));
  Rgba8Image spherical = render("texture_spherical", ball + " --projection spherical");
  Rgba8Image cylindrical = render("texture_cylindrical", ball + " --projection cylindrical");
  Rgba8Image planar = render("texture_planar", ball + " --projection planar");
  Rgba8Image defaulted = render("texture_default", ball);
  EXPECT_GT(mean_difference(plain, spherical), 10.0) << "the texture does not show";
  EXPECT_GT(mean_difference(spherical, cylindrical), kClearlyDifferent);
  EXPECT_GT(mean_difference(spherical, planar), kClearlyDifferent);
  EXPECT_GT(mean_difference(cylindrical, planar), kClearlyDifferent);
  EXPECT_EQ(mean_difference(spherical, defaulted), 0.0) << "spherical is the default";
  expect_a_picture(planar);
}

TEST(CliContentFlags, ExposureBrightens) {
  std::string ball = input("ball.d");
  Rgba8Image plain = render("exposure_0", ball);
  Rgba8Image bright = render("exposure_1", ball + " --exposure 1");
  auto pixels = model_pixels(plain);
  ASSERT_FALSE(pixels.empty());
  if (bright.pixels.empty()) return;
  double before = 0.0, after = 0.0;
  int darker = 0;
  for (auto [x, y] : pixels) {
    before += luminance(at(plain, x, y));
    after += luminance(at(bright, x, y));
    darker += luminance(at(bright, x, y)) < luminance(at(plain, x, y)) - 1.0;
  }
  EXPECT_GT(after, before * 1.1);
  EXPECT_EQ(darker, 0) << "pixels got darker with more exposure";
}

TEST(CliContentFlags, FileCamera) {
  REQUIRE_INSTALLED(kCamerasGltf);
  // The file has a perspective camera and an orthographic one, both kept.
  CommandResult info = run_command(std::string(FACET_CLI) + " info " + kCamerasGltf);
  ASSERT_EQ(info.exit_code, 0) << info.stderr_text;
  ASSERT_NE(info.stdout_text.find("\ncameras     2\n"), std::string::npos) << info.stdout_text;
  EXPECT_NE(info.stdout_text.find("orthographic, 2 units tall"), std::string::npos)
      << info.stdout_text;
  Rgba8Image framed = render("camera_default", kCamerasGltf);
  Rgba8Image file_camera = render("camera_0", kCamerasGltf + " --camera 0");
  EXPECT_GT(mean_difference(framed, file_camera), kClearlyDifferent);
  // The file's camera stands at (0.5, 0.5, 3) looking down -z at a unit square tilted back
  // 45 degrees around its bottom edge (x 0..1 at y 0, z 0): the square is centred
  // horizontally and its bottom edge is below the image centre.
  auto pixels = model_pixels(file_camera);
  ASSERT_FALSE(pixels.empty());
  int low_x = kWidth, high_x = 0, low_y = kHeight, high_y = 0;
  for (auto [x, y] : pixels) {
    low_x = std::min(low_x, x), high_x = std::max(high_x, x);
    low_y = std::min(low_y, y), high_y = std::max(high_y, y);
  }
  EXPECT_NEAR((low_x + high_x) / 2.0, kWidth / 2.0, 2.0);
  EXPECT_NEAR(high_y, 131, 3);  // tan(20.05 deg) * 3 = 1.095 units above and below the centre
  EXPECT_NEAR(low_y, 76, 3);    // the top edge at y 0.707, z -0.707
}

}  // namespace
}  // namespace facet::test
