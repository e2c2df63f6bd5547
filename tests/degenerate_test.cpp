// Degenerate input: zero-area triangles, repeated vertices, NaN/Inf positions, empty meshes,
// the smallest framebuffer, bad indices. Skipped or reported, never a crash.
#include <gtest/gtest.h>

#include <limits>
#include <utility>

#include "facet/error.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 48;
constexpr int kHeight = 32;
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

int total(const std::vector<int>& counts) {
  int sum = 0;
  for (int n : counts) sum += n;
  return sum;
}

const std::vector<glm::vec3> kGood = {{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};

TEST(Degenerate, ZeroAreaAndRepeatedVerticesDrawNothing) {
  Mesh mesh = soup({{-1, -1, -3},
                    {0, 0, -3},
                    {1, 1, -3},  // collinear
                    {0.2f, 0.1f, -3},
                    {0.2f, 0.1f, -3},
                    {0.2f, 0.1f, -3},  // one point
                    {-1, 0, -3},
                    {-1, 0, -3},
                    {1, 0.5f, -3}});  // repeated vertex
  auto counts = coverage_counts({&mesh}, test_camera(kWidth, kHeight), kWidth, kHeight);
  EXPECT_EQ(total(counts), 0);
}

TEST(Degenerate, NonFiniteVerticesAreSkippedAndTheRestDrawn) {
  Mesh good = soup(kGood);
  int expected = total(coverage_counts({&good}, test_camera(kWidth, kHeight), kWidth, kHeight));
  ASSERT_GT(expected, 0);
  for (float bad : {kNaN, kInf, -kInf}) {
    std::vector<glm::vec3> positions = {{bad, 0, -3}, {1, -1, -3}, {0, 1, -3},
                                        {0, 0, bad},  {1, -1, -3}, {0, 1, -3}};
    positions.insert(positions.end(), kGood.begin(), kGood.end());
    Mesh mesh = soup(positions);
    auto counts = coverage_counts({&mesh}, test_camera(kWidth, kHeight), kWidth, kHeight);
    EXPECT_EQ(total(counts), expected) << bad;
  }
  // A NaN in the transform poisons every vertex: nothing drawn, no crash.
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.draw(good, Material{}, glm::mat4(kNaN));
  renderer.finish(fb);
  EXPECT_EQ(renderer.stats().pixels_shaded, 0u);
}

TEST(Degenerate, EmptyMeshesAndNoDraws) {
  Mesh empty;
  Mesh strip;
  strip.topology = Topology::triangle_strip;
  strip.positions = {{0, 0, -3}, {1, 0, -3}};  // two vertices: no triangle
  auto counts = coverage_counts({&empty, &strip}, test_camera(kWidth, kHeight), kWidth, kHeight);
  EXPECT_EQ(total(counts), 0);
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.finish(fb);  // nothing recorded: a cleared frame
  EXPECT_EQ(fb.depth_at(0, 0), 1.0f);
}

TEST(Degenerate, OneByOneFramebuffer) {
  Mesh mesh = soup({{-5, -5, -2}, {5, -5, -2}, {0, 5, -2}});
  auto counts = coverage_counts({&mesh}, test_camera(1, 1), 1, 1);
  EXPECT_EQ(counts, std::vector<int>{1});
  Framebuffer fb = render_unlit({&mesh}, test_camera(1, 1), 1, 1);
  EXPECT_LT(fb.depth_at(0, 0), 1.0f);
}

TEST(Degenerate, BadSizesAndIndicesAreReportedNotCrashed) {
  EXPECT_THROW(Framebuffer(0, 5), Error);
  EXPECT_THROW(Framebuffer(8193, 1), Error);
  EXPECT_NO_THROW(Framebuffer(8192, 1));
  Mesh mesh = soup(kGood);
  mesh.indices = {0, 1, 7};
  Renderer renderer;
  renderer.begin_frame(test_camera(kWidth, kHeight));
  try {
    renderer.draw(mesh, Material{});
    FAIL() << "an out-of-range index must throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("index"), std::string::npos) << e.what();
  }
  RenderSettings bad;
  bad.threads = -1;
  EXPECT_THROW(Renderer{bad}, Error);
  bad.threads = 0;
  bad.tile_size = 48;
  EXPECT_THROW(Renderer{bad}, Error);
}

TEST(Degenerate, PixelReadsOutsideTheImageOrWithoutDepthThrow) {
  const Framebuffer with_depth(4, 3);
  EXPECT_EQ(with_depth.depth_at(3, 2), 1.0f);
  EXPECT_NO_THROW(with_depth.pixel(3, 2));
  for (auto [x, y] : {std::pair{-1, 0}, {4, 0}, {0, -1}, {0, 3}}) {
    EXPECT_THROW(with_depth.pixel(x, y), Error) << x << ", " << y;
    EXPECT_THROW(with_depth.depth_at(x, y), Error) << x << ", " << y;
  }
  const Framebuffer color_only(4, 3, ColorFormat::rgba32f, DepthImage::none);
  EXPECT_NO_THROW(color_only.pixel(0, 0));
  try {
    color_only.depth_at(0, 0);
    FAIL() << "depth_at without a depth image must throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("DepthImage::none"), std::string::npos) << e.what();
  }
}

TEST(Degenerate, StripsKeepTheirWinding) {
  // A strip of 4 triangles, all front-facing: with back-face culling every one must draw.
  Mesh strip;
  strip.topology = Topology::triangle_strip;
  strip.positions = {{-2, -1, -4}, {-2, 1, -4}, {-1, -1, -4}, {-1, 1, -4}, {0, -1, -4}, {0, 1, -4}};
  // First triangle (v0, v1, v2) must be counter-clockwise: v0 bottom-left, v1 top-left,
  // v2 bottom-right is clockwise, so reverse the first two.
  std::swap(strip.positions[0], strip.positions[1]);
  std::swap(strip.positions[2], strip.positions[3]);
  std::swap(strip.positions[4], strip.positions[5]);
  Mesh list =
      soup({strip.positions[0], strip.positions[1], strip.positions[2], strip.positions[2],
            strip.positions[1], strip.positions[3], strip.positions[2], strip.positions[3],
            strip.positions[4], strip.positions[4], strip.positions[3], strip.positions[5]});
  auto from_strip =
      coverage_counts({&strip}, test_camera(kWidth, kHeight), kWidth, kHeight, CullMode::back);
  auto from_list =
      coverage_counts({&list}, test_camera(kWidth, kHeight), kWidth, kHeight, CullMode::none);
  EXPECT_GT(total(from_list), 0);
  EXPECT_EQ(from_strip, from_list);
}

}  // namespace
}  // namespace facet::test
