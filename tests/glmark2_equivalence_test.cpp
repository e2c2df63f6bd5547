// "Same work, checked": each glmark2-equivalent benchmark scene's frame at t = 0, rendered at
// 1920x1080, must match the frame glmark2 2023.01 itself rendered on llvmpipe
// (FACET_SHARED_DIR/bench/ref/<benchmark>.t0.png, ':' in the name replaced by '_'): PSNR over
// RGB of at least 30 dB, and the same silhouette. Otherwise `facet bench` would not be timing
// the same work as glmark2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/renderer.hpp"
#include "scenes/bench_scenes.hpp"
#include "scenes/glmark2_model.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 1920;
constexpr int kHeight = 1080;
constexpr double kMinPsnr = 30.0;
// Silhouettes: the sets of non-black pixels may differ in at most 0.5% of the frame (10,368
// pixels at 1080p). Coverage follows llvmpipe's rules (pixel centres, top-left fill rule, 8
// sub-pixel bits), so today the sets differ by at most 0.004% (80 pixels, texture): edge pixels
// where a vertex sits on a sub-pixel boundary, and pixels within one 8-bit step of black (build
// and gouraud have no ambient term). The margin is for the performance work on the pipeline,
// whose float rounding in setup and interpolation may move such pixels; the wrong model,
// camera fit, transform or culling changes several percent. (It does not catch an offset of
// the whole outline by a pixel or two: that is 0.18% per pixel for the horse.)
constexpr double kMaxSilhouetteDifference = 0.005;

fs::path reference_dir() { return fs::path(FACET_SHARED_DIR) / "bench" / "ref"; }

std::string reference_file(std::string benchmark) {
  for (char& c : benchmark) {
    if (c == ':') c = '_';
  }
  return benchmark + ".t0.png";
}

struct Comparison {
  double psnr = 0.0;
  double silhouette_difference = 0.0;  // fraction of the frame's pixels
  std::size_t silhouette_pixels = 0;   // how many
};

Comparison compare(const Framebuffer& rendered, const Rgba8Image& reference) {
  const std::vector<std::uint8_t>& ours = rendered.rgba8();
  const std::vector<std::uint8_t>& theirs = reference.pixels;
  double squared_error = 0.0;
  std::size_t silhouette_mismatches = 0;
  const std::size_t pixels = static_cast<std::size_t>(kWidth) * kHeight;
  for (std::size_t i = 0; i < pixels; ++i) {
    bool ours_lit = false, theirs_lit = false;
    for (std::size_t k = 0; k < 3; ++k) {
      const double d = static_cast<double>(ours[i * 4 + k]) - theirs[i * 4 + k];
      squared_error += d * d;
      ours_lit = ours_lit || ours[i * 4 + k] != 0;
      theirs_lit = theirs_lit || theirs[i * 4 + k] != 0;
    }
    silhouette_mismatches += ours_lit != theirs_lit;
  }
  Comparison c;
  const double mse = squared_error / (3.0 * static_cast<double>(pixels));
  c.psnr = mse == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / mse);
  c.silhouette_pixels = silhouette_mismatches;
  c.silhouette_difference = static_cast<double>(silhouette_mismatches) / pixels;
  return c;
}

class Glmark2Equivalence : public ::testing::TestWithParam<std::string> {};

TEST_P(Glmark2Equivalence, FrameZeroMatchesGlmark2) {
  FACET_REQUIRE_PACKAGE(fs::is_directory(reference_dir()),
                        reference_dir() << " missing: no glmark2 reference frames");
  FACET_REQUIRE_PACKAGE(fs::is_directory("/usr/share/glmark2/models"),
                        "/usr/share/glmark2 missing (Debian package glmark2-data)");
  const std::string& benchmark = GetParam();
  const fs::path reference_path = reference_dir() / reference_file(benchmark);
  ASSERT_TRUE(fs::exists(reference_path)) << reference_path;
  const Rgba8Image reference = read_png(reference_path.string());
  ASSERT_EQ(reference.width, kWidth);
  ASSERT_EQ(reference.height, kHeight);

  auto scene = bench::make_glmark2_scene(benchmark);
  ASSERT_NE(scene, nullptr) << benchmark;
  RenderSettings settings;
  settings.threads = 0;
  settings.clear_color = scene->clear_color();
  Renderer renderer(settings);
  Framebuffer framebuffer(kWidth, kHeight);
  scene->record(renderer, 0.0, kWidth, kHeight);
  renderer.finish(framebuffer);
  // Kept for looking at next to the reference.
  const fs::path rendered_path =
      fs::path(::testing::TempDir()) / ("facet_" + reference_file(benchmark));
  write_image(framebuffer, rendered_path.string());

  const Comparison c = compare(framebuffer, reference);
  std::printf("[ glmark2  ] %-32s PSNR %6.2f dB, silhouette difference %.4f%% (%zu px) (%s)\n",
              benchmark.c_str(), c.psnr, c.silhouette_difference * 100.0, c.silhouette_pixels,
              rendered_path.c_str());
  EXPECT_GE(c.psnr, kMinPsnr) << benchmark << " vs " << reference_path;
  EXPECT_LE(c.silhouette_difference, kMaxSilhouetteDifference)
      << benchmark << " vs " << reference_path;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, Glmark2Equivalence,
                         ::testing::ValuesIn(bench::glmark2_scene_names()), test_name);

TEST(Glmark2Scenes, NamesAreTheGlmark2BenchmarkStrings) {
  const std::vector<std::string> expected = {"build:use-vbo=true",
                                             "texture:texture-filter=linear",
                                             "texture:texture-filter=mipmap",
                                             "shading:shading=gouraud",
                                             "shading:shading=blinn-phong-inf",
                                             "shading:shading=phong",
                                             "shading:shading=cel",
                                             "bump:bump-render=normals",
                                             "bump:bump-render=high-poly",
                                             "shadow",
                                             "refract"};
  EXPECT_EQ(bench::glmark2_scene_names(), expected);
  EXPECT_EQ(bench::make_glmark2_scene("jellyfish"), nullptr);
}

// The reader and glmark2's normals on the smallest model: cube.3ds has 20 vertices and 12
// faces; most corners are split per face and get flat normals, but 4 vertices are shared by
// two faces and get 45° normals (GLMARK2_SCENES.md §1.4).
TEST(Glmark2Model, CubeNormalsAreGlmark2s) {
  const std::string path = "/usr/share/glmark2/models/cube.3ds";
  FACET_REQUIRE_PACKAGE(fs::exists(path), path << " missing (Debian package glmark2-data)");
  const bench::Glmark2Model cube = bench::load_3ds(path);
  EXPECT_EQ(cube.positions.size(), 20u);
  EXPECT_EQ(cube.indices.size(), 36u);
  EXPECT_EQ(cube.texcoords.size(), 20u);
  for (int k = 0; k < 3; ++k) {  // a +-1 cube, to float precision (stored as +-(1 + few ulp))
    EXPECT_NEAR(cube.bbox_min[k], -1.0f, 1e-6f);
    EXPECT_NEAR(cube.bbox_max[k], 1.0f, 1e-6f);
  }
  int flat = 0, diagonal = 0;
  for (const glm::vec3& n : bench::glmark2_normals(cube)) {
    const glm::vec3 a = glm::abs(n);
    const float largest = std::max({a.x, a.y, a.z});
    if (std::abs(largest - 1.0f) < 1e-6f) ++flat;
    if (std::abs(largest - std::sqrt(0.5f)) < 1e-6f) ++diagonal;
  }
  EXPECT_EQ(flat, 16);
  EXPECT_EQ(diagonal, 4);
  const Mesh drawn = bench::glmark2_mesh(cube, {.normals = true, .texcoords = true});
  EXPECT_EQ(drawn.positions.size(), 36u);  // de-indexed, as glmark2 draws it
  EXPECT_TRUE(drawn.indices.empty());
}

}  // namespace
}  // namespace facet::test
