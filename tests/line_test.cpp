// Lines: a fill rule of their own. Polylines never double a pixel at shared vertices and
// have no gaps; line coverage does not depend on the tile size.
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

std::vector<int> line_counts(const Mesh& mesh, int tile_size) {
  // Lines ignore the depth test only through their bias; draw each with the counter by
  // rendering into a float target where lines write their color (1, 0, 0, 0) additively is
  // not available, so count via separate renders: one per segment, summed.
  std::vector<int> counts(kWidth * kHeight, 0);
  for (std::size_t s = 0; s + 1 < mesh.positions.size(); s += 2) {
    Mesh one;
    one.topology = Topology::lines;
    one.positions = {mesh.positions[s], mesh.positions[s + 1]};
    RenderSettings settings;
    settings.tile_size = tile_size;
    settings.clear_color = glm::vec4(0.0f);
    Renderer renderer(settings);
    Framebuffer fb(kWidth, kHeight, ColorFormat::rgba32f);
    Material material;
    material.shading = ShadingModel::unlit;
    material.base_color = glm::vec4(1.0f);
    renderer.begin_frame(test_camera(kWidth, kHeight));
    renderer.draw(one, material);
    renderer.finish(fb);
    for (int i = 0; i < kWidth * kHeight; ++i) counts[i] += fb.rgba32f()[i * 4] > 0.5f ? 1 : 0;
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
