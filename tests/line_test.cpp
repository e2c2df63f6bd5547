// Lines: a fill rule of their own. Polylines never double a pixel at shared vertices and
// have no gaps; line coverage does not depend on the tile size. Under MSAA a segment is a
// rectangle one pixel wide whose samples average into an anti-aliased line.
#include <gtest/gtest.h>

#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"
#include "support/geometry.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 120;
constexpr int kHeight = 80;

// One white segment (or several) on black, with `samples` a pixel, into a float target: each
// pixel's red is the share of its samples the segment covers.
std::vector<float> line_coverage(const Mesh& mesh, int samples, int tile_size = 64,
                                 int threads = 0) {
  RenderSettings settings;
  settings.msaa = samples;
  settings.tile_size = tile_size;
  settings.threads = threads;
  settings.clear_color = glm::vec4(0.0f);
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight, ColorFormat::rgba32f);
  Material material;
  material.shading = ShadingModel::unlit;
  material.base_color = glm::vec4(1.0f);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.draw(mesh, material);
  renderer.finish(fb);
  std::vector<float> red(kWidth * kHeight);
  for (int i = 0; i < kWidth * kHeight; ++i) red[i] = fb.rgba32f()[i * 4];
  return red;
}

std::vector<int> line_counts(const Mesh& mesh, int tile_size) {
  // Each segment drawn alone, so a pixel two of them cover counts twice.
  std::vector<int> counts(kWidth * kHeight, 0);
  for (std::size_t s = 0; s + 1 < mesh.positions.size(); s += 2) {
    Mesh one;
    one.topology = Topology::lines;
    one.positions = {mesh.positions[s], mesh.positions[s + 1]};
    const std::vector<float> covered = line_coverage(one, 1, tile_size);
    for (int i = 0; i < kWidth * kHeight; ++i) counts[i] += covered[i] > 0.5f ? 1 : 0;
  }
  return counts;
}

Mesh polyline(const std::vector<glm::dvec2>& points) {
  Mesh mesh;
  mesh.topology = Topology::lines;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    mesh.positions.push_back(at_pixel(points[i].x, points[i].y, kWidth, kHeight, 2.0));
    mesh.positions.push_back(at_pixel(points[i + 1].x, points[i + 1].y, kWidth, kHeight, 2.0));
  }
  return mesh;
}

TEST(Lines, PolylineCoversEachPixelOnceWithoutGaps) {
  // Mostly-horizontal zig-zag: x-major segments share end points.
  Mesh mesh = polyline({{5.3, 10.2}, {30.7, 20.9}, {61.1, 12.4}, {90.5, 30.5}, {115.2, 25.0}});
  auto counts = line_counts(mesh, 64);
  // One pixel per column from the first centre at or after x = 5.3 up to the last before 115.2.
  for (int x = 0; x < kWidth; ++x) {
    int column = 0;
    for (int y = 0; y < kHeight; ++y) {
      ASSERT_LE(counts[y * kWidth + x], 1) << "doubled pixel " << x << "," << y;
      column += counts[y * kWidth + x];
    }
    bool spanned = x + 0.5 >= 5.3 && x + 0.5 < 115.2;
    EXPECT_EQ(column, spanned ? 1 : 0) << "column " << x;
  }
}

TEST(Lines, SteepPolylineCoversEachRowOnce) {
  Mesh mesh = polyline({{40.2, 2.7}, {50.9, 40.5}, {35.0, 77.3}});
  auto counts = line_counts(mesh, 16);
  for (int y = 0; y < kHeight; ++y) {
    int row = 0;
    for (int x = 0; x < kWidth; ++x) row += counts[y * kWidth + x];
    bool spanned = y + 0.5 >= 2.7 && y + 0.5 < 77.3;
    EXPECT_EQ(row, spanned ? 1 : 0) << "row " << y;
  }
  EXPECT_EQ(counts, line_counts(mesh, 64));  // tiles do not change coverage
}

TEST(Lines, MultisampledSegmentsAreAntiAliasedRectanglesOnePixelWide) {
  // x-major, 105.4 pixels along x: a rectangle one pixel tall along it has that area.
  const Mesh segment = polyline({{5.3, 10.2}, {110.7, 40.9}});
  const Mesh steep = polyline({{60.2, 2.7}, {40.9, 75.5}});  // y-major, 72.8 pixels along y
  for (int samples : {4, 8, 16}) {
    SCOPED_TRACE(samples);
    for (const auto& [mesh, length] : {std::pair{&segment, 105.4}, std::pair{&steep, 72.8}}) {
      const std::vector<float> coverage = line_coverage(*mesh, samples);
      double area = 0.0;
      int partial = 0;
      for (float c : coverage) {
        area += c;
        partial += c > 0.0f && c < 1.0f;
        EXPECT_LE(c, 1.0f);
      }
      EXPECT_NEAR(area, length, 0.02 * length);
      EXPECT_GT(partial, length / 2) << "edge pixels partly covered: anti-aliased";
      // Tiles and threads do not change coverage.
      EXPECT_EQ(line_coverage(*mesh, samples, 16, 1), coverage);
      EXPECT_EQ(line_coverage(*mesh, samples, 32, 3), coverage);
    }
  }
}

TEST(Lines, MultisampledPolylinesCoverEachSampleOnce) {
  // One segment, and the same segment cut in two at a point between pixel centres: no sample
  // doubled or lost at the shared end. (The cut snaps to 1/256 pixel, so the halves are not
  // exactly the whole: a sample at the rectangle's edge may change sides.)
  const Mesh whole = polyline({{5.3, 10.2}, {110.7, 40.9}});
  const double t = 0.4137;
  const glm::dvec2 cut{5.3 + t * (110.7 - 5.3), 10.2 + t * (40.9 - 10.2)};
  const Mesh first = polyline({{5.3, 10.2}, cut}), second = polyline({cut, {110.7, 40.9}});
  const std::vector<float> one = line_coverage(whole, 8);
  const std::vector<float> a = line_coverage(first, 8), b = line_coverage(second, 8);
  double halves = 0.0, whole_area = 0.0;
  int moved = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    EXPECT_LE(a[i] + b[i], 1.0f) << "pixel " << i % kWidth << "," << i / kWidth;
    halves += a[i] + b[i], whole_area += one[i];
    moved += a[i] + b[i] != one[i];
  }
  EXPECT_NEAR(halves, whole_area, 2.0 / 8.0);  // two samples at most
  EXPECT_LE(moved, 2);
}

// Segments are counted apart from triangles: a wireframe draws no triangle, and its frame is not
// "0 drawn" (FrameStats::lines_drawn).
TEST(Lines, SegmentsAreCountedAsLinesDrawn) {
  Mesh polyline;
  polyline.topology = Topology::lines;
  polyline.positions = {{-1, -1, -3}, {1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
  Mesh tri;
  tri.positions = {{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  Material lines;
  lines.shading = ShadingModel::unlit;
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.draw(polyline, lines);
  renderer.finish(fb);
  EXPECT_EQ(renderer.stats().lines_drawn, 2u);
  EXPECT_EQ(renderer.stats().drawn, 0u);
  Material wireframe;
  wireframe.shading = ShadingModel::wireframe;
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.draw(tri, wireframe);
  renderer.finish(fb);
  EXPECT_EQ(renderer.stats().lines_drawn, 3u);  // the triangle's three edges
  EXPECT_EQ(renderer.stats().drawn, 0u);
}

}  // namespace
}  // namespace facet::test
