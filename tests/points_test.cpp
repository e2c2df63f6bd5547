// Points (Topology::points): the fill rule of src/pipeline/raster/point.cpp — a point of side s
// covers the pixels whose centre lies in [cx - s/2, cx + s/2) x [cy - s/2, cy + s/2) — its
// clipping (dropped when its centre is outside the frustum, cut at the frame's edges), its depth
// test against triangles, its colors and its counts; and a real point cloud through the CLI.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "support/geometry.hpp"
#include "support/golden.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 120;
constexpr int kHeight = 80;
constexpr double kDistance = 4.0;

Material point_material(float size) {
  Material material;
  material.point_size = size;
  return material;
}

// Points at screen positions (pixels), all kDistance away unless `distances` says otherwise.
Mesh points_at(const std::vector<glm::dvec2>& screen, const std::vector<double>& distances = {}) {
  Mesh mesh;
  mesh.topology = Topology::points;
  for (std::size_t i = 0; i < screen.size(); ++i) {
    const double distance = distances.empty() ? kDistance : distances[i];
    mesh.positions.push_back(at_pixel(screen[i].x, screen[i].y, kWidth, kHeight, distance));
  }
  return mesh;
}

struct Drawn {
  const Mesh* mesh;
  Material material;
};

Framebuffer render(const std::vector<Drawn>& draws, RenderSettings settings = {},
                   FrameStats* stats = nullptr) {
  settings.clear_color = glm::vec4(0.0f);
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight, ColorFormat::rgba32f);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  for (const Drawn& d : draws) renderer.draw(*d.mesh, d.material);
  renderer.finish(fb);
  if (stats) *stats = renderer.stats();
  return fb;
}

float red_at(const Framebuffer& fb, int x, int y) { return fb.rgba32f()[(y * kWidth + x) * 4]; }

std::set<std::pair<int, int>> covered(const Framebuffer& fb) {
  std::set<std::pair<int, int>> out;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (red_at(fb, x, y) > 0.0f) out.insert({x, y});
    }
  }
  return out;
}

// The pixels of [lo, hi) along one axis whose centre p + 0.5 lies in it, for a centre snapped
// to 1/256 pixel as setup snaps it.
std::vector<int> span(double centre, double size) {
  const double snapped = std::nearbyint(centre * 256.0) / 256.0;
  std::vector<int> out;
  for (int p = -10; p < 200; ++p) {
    if (p + 0.5 >= snapped - size / 2 && p + 0.5 < snapped + size / 2) out.push_back(p);
  }
  return out;
}

TEST(Points, ASquareCoversExactlyTheHalfOpenSquaresPixels) {
  // Centres on a pixel centre, on a pixel corner (the square's edges then fall on centres: the
  // half-open rule decides) and in between; odd and even sizes.
  const std::vector<glm::dvec2> centres = {{40.5, 30.5},  {40.0, 30.0},   {40.3, 30.7},
                                           {40.75, 30.2}, {40.99, 30.01}, {41.5, 30.0}};
  for (float size : {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 2.5f}) {
    for (const glm::dvec2& c : centres) {
      SCOPED_TRACE("size " + std::to_string(size) + " at " + std::to_string(c.x) + ", " +
                   std::to_string(c.y));
      const Mesh mesh = points_at({c});
      const auto pixels = covered(render({{&mesh, point_material(size)}}));
      std::set<std::pair<int, int>> expected;
      for (int y : span(c.y, size)) {
        for (int x : span(c.x, size)) expected.insert({x, y});
      }
      EXPECT_EQ(pixels, expected);
      if (size == std::floor(size)) {  // a whole size: exactly size x size, wherever it lies
        EXPECT_EQ(pixels.size(), static_cast<std::size_t>(size * size));
      }
    }
  }
}

// Points spaced exactly their size apart tile the plane: every pixel of the grid's area once.
TEST(Points, AGridSpacedByThePointSizeHasNoGapsAndNoDoubles) {
  // Squares' edges between pixel centres, and on them (20.0 for odd sizes, 20.5 for even: only
  // the half-open rule then keeps neighbours from sharing a pixel).
  for (const glm::dvec2 origin :
       {glm::dvec2{20.37, 15.81}, glm::dvec2{20.0, 16.0}, glm::dvec2{20.5, 16.5}})
    for (int size : {2, 3}) {
      SCOPED_TRACE("size " + std::to_string(size) + " from " + std::to_string(origin.x));
      const int columns = 12, rows = 8;
      Mesh mesh;
      mesh.topology = Topology::points;
      std::vector<glm::dvec2> screen;
      for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
          screen.push_back(origin + glm::dvec2(i * size, j * size));
          // A distinct color per point: red (index + 1) / 1024, exact in float.
          const float red = static_cast<float>(screen.size()) / 1024.0f;
          mesh.colors.push_back({red, 0.0f, 0.0f, 1.0f});
        }
      }
      mesh.positions = points_at(screen).positions;
      const Framebuffer fb = render({{&mesh, point_material(static_cast<float>(size))}});
      // At one depth, a later point does not overwrite an earlier one (the depth test is "nearer"):
      // a doubled pixel would leave some point fewer than size x size pixels.
      std::vector<int> per_point(screen.size(), 0);
      int total = 0;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          const float red = red_at(fb, x, y);
          if (red == 0.0f) continue;
          const int index = static_cast<int>(std::lround(red * 1024.0f)) - 1;
          ASSERT_GE(index, 0);
          ASSERT_LT(index, static_cast<int>(screen.size()));
          ++per_point[index], ++total;
        }
      }
      for (int count : per_point) EXPECT_EQ(count, size * size);
      EXPECT_EQ(total, columns * rows * size * size);
      // And the covered area is one solid rectangle.
      const auto xs = span(origin.x, size), ys = span(origin.y, size);
      for (int y = ys.front(); y < ys.front() + rows * size; ++y) {
        for (int x = xs.front(); x < xs.front() + columns * size; ++x) {
          EXPECT_GT(red_at(fb, x, y), 0.0f) << "gap at " << x << "," << y;
        }
      }
    }
}

// A point is kept or dropped by its centre: outside the frame (or before near, past far) it is
// dropped, inside it is drawn, its square cut at the frame's edges.
TEST(Points, DroppedByTheirCentreAndCutAtTheFramesEdges) {
  const Mesh inside_edge = points_at({{0.7, 40.5}});        // covers columns 0..2 of [-1.8, 3.2)
  const Mesh outside = points_at({{-0.6, 40.5}});           // its square would reach column 1
  const Mesh corner = points_at({{119.9, 79.9}});           // only the corner pixel is left
  const Mesh too_near = points_at({{60.5, 40.5}}, {0.05});  // the near plane is at 0.1
  const Mesh too_far = points_at({{60.5, 40.5}}, {150.0});  // and far at 100
  FrameStats stats;
  auto pixels = covered(render({{&inside_edge, point_material(5.0f)}}, {}, &stats));
  std::set<std::pair<int, int>> expected;
  for (int y = 38; y <= 42; ++y) {
    for (int x = 0; x <= 2; ++x) expected.insert({x, y});
  }
  EXPECT_EQ(pixels, expected);
  EXPECT_EQ(stats.points_drawn, 1u);
  for (const Mesh* dropped : {&outside, &too_near, &too_far}) {
    EXPECT_TRUE(covered(render({{dropped, point_material(5.0f)}}, {}, &stats)).empty());
    EXPECT_EQ(stats.points_drawn, 0u);
    EXPECT_EQ(stats.triangles_in, 1u);  // submitted primitives count points
    EXPECT_EQ(stats.culled, 1u);
  }
  pixels = covered(render({{&corner, point_material(3.0f)}}));
  // [118.4, 121.4): columns 118 and 119 (120 is past the edge); rows 78 and 79 likewise.
  EXPECT_EQ(pixels, (std::set<std::pair<int, int>>{{118, 78}, {119, 78}, {118, 79}, {119, 79}}));
}

// Points pass the depth test against triangles as triangles do, in either drawing order.
TEST(Points, DepthTestedAgainstTriangles) {
  // A big triangle 3 units away, covering the middle of the frame.
  Mesh triangle;
  triangle.positions = {at_pixel(10, 70, kWidth, kHeight, 3.0),
                        at_pixel(110, 70, kWidth, kHeight, 3.0),
                        at_pixel(60, 5, kWidth, kHeight, 3.0)};
  Material blue;
  blue.shading = ShadingModel::unlit;
  blue.base_color = {0.0f, 0.0f, 1.0f, 1.0f};
  blue.cull = CullMode::none;
  // One point in front of it (2 units away), one behind (5 away).
  Mesh points = points_at({{50.5, 50.5}, {70.5, 50.5}}, {2.0, 5.0});
  Material red = point_material(3.0f);
  red.base_color = {1.0f, 0.0f, 0.0f, 1.0f};
  for (bool points_first : {true, false}) {
    SCOPED_TRACE(points_first ? "points first" : "triangle first");
    const Framebuffer fb = points_first ? render({{&points, red}, {&triangle, blue}})
                                        : render({{&triangle, blue}, {&points, red}});
    const float* front = &fb.rgba32f()[(50 * kWidth + 50) * 4];
    const float* behind = &fb.rgba32f()[(50 * kWidth + 70) * 4];
    EXPECT_EQ(front[0], 1.0f);  // the near point shows
    EXPECT_EQ(front[2], 0.0f);
    EXPECT_EQ(behind[0], 0.0f);  // the far one is hidden by the triangle
    EXPECT_EQ(behind[2], 1.0f);
    // The near point's depth is written: nearer than the triangle's beside it.
    EXPECT_LT(fb.depth()[50 * kWidth + 50], fb.depth()[50 * kWidth + 54]);
  }
}

// Unlit: the vertex color times the material's base color, whatever the shading model; white
// vertex colors when the mesh has none or the material does not use them.
TEST(Points, ColorIsVertexColorTimesBaseColor) {
  Mesh mesh = points_at({{30.5, 40.5}});
  mesh.colors = {{0.5f, 1.0f, 0.25f, 1.0f}};
  Material material = point_material(1.0f);
  material.shading = ShadingModel::phong;  // ignored: points are unlit
  material.base_color = {0.5f, 0.5f, 1.0f, 1.0f};
  Framebuffer fb = render({{&mesh, material}});
  const float* c = &fb.rgba32f()[(40 * kWidth + 30) * 4];
  EXPECT_EQ(c[0], 0.25f);
  EXPECT_EQ(c[1], 0.5f);
  EXPECT_EQ(c[2], 0.25f);
  material.use_vertex_colors = false;
  fb = render({{&mesh, material}});
  c = &fb.rgba32f()[(40 * kWidth + 30) * 4];
  EXPECT_EQ(c[0], 0.5f);
  EXPECT_EQ(c[2], 1.0f);
}

TEST(Points, AreCountedAsPointsDrawn) {
  Mesh mesh = points_at({{10.5, 10.5}, {20.5, 10.5}, {30.5, 10.5}});
  mesh.indices = {2, 0, 0};  // indexed: every index is a point
  FrameStats stats;
  render({{&mesh, point_material(2.0f)}}, {}, &stats);
  EXPECT_EQ(stats.points_drawn, 3u);
  EXPECT_EQ(stats.triangles_in, 3u);
  EXPECT_EQ(stats.drawn, 0u);
  EXPECT_EQ(stats.lines_drawn, 0u);
  EXPECT_EQ(mesh.primitive_count(), 3u);
}

TEST(Points, ASizeOutsideItsRangeIsRefused) {
  const Mesh mesh = points_at({{10.5, 10.5}});
  for (float size : {0.0f, -1.0f, 257.0f, std::nanf("")}) {
    EXPECT_THROW(render({{&mesh, point_material(size)}}), Error) << size;
  }
}

// A real shape as a point cloud through `facet render`, against a golden: the vertices of
// assimp's Wuson.ply (11184, a corner each) written as a PLY without faces, colored by their
// normals, so the file goes the way a scanner's does (assimp's PLY reader, points, vertex colors).
TEST(Points, PlyPointCloudRendersLikeItsGolden) {
  const std::string wuson = "/usr/share/assimp/models/PLY/Wuson.ply";
  FACET_REQUIRE_PACKAGE(fs::exists(wuson), "assimp-testmodels is not installed");
  const Scene mesh_scene = import_scene(wuson);
  std::vector<glm::vec3> positions, normals;
  for (const auto& mesh : mesh_scene.meshes) {
    positions.insert(positions.end(), mesh->positions.begin(), mesh->positions.end());
    normals.insert(normals.end(), mesh->normals.begin(), mesh->normals.end());
  }
  ASSERT_EQ(positions.size(), normals.size());
  const fs::path dir = fresh_test_dir("facet_points_", "wuson");
  const fs::path cloud = dir / "wuson_points.ply";
  {
    std::ofstream out(cloud);
    out << "ply\nformat ascii 1.0\nelement vertex " << positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\n"
           "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const glm::ivec3 rgb(glm::round((normals[i] * 0.5f + 0.5f) * 255.0f));
      out << positions[i].x << ' ' << positions[i].y << ' ' << positions[i].z << ' ' << rgb.r << ' '
          << rgb.g << ' ' << rgb.b << '\n';
    }
  }
  const fs::path output = dir / "points_wuson.png";
  const std::string command = std::string(FACET_CLI) + " render '" + cloud.string() +
                              "' --size 320x180 --point-size 2 --tone-mapping none -o '" +
                              output.string() + "'";
  CommandResult result = run_command(command);
  ASSERT_EQ(result.exit_code, 0) << command << "\n" << result.stderr_text;
  EXPECT_NE(result.stdout_text.find(std::to_string(positions.size()) + " points drawn"),
            std::string::npos)
      << result.stdout_text;
  expect_matches_golden(output.string(), "points_wuson");
}

TEST(Points, InfoSaysHowManyPoints) {
  const std::string ply = "/usr/share/assimp/models/PLY/points.ply";
  FACET_REQUIRE_PACKAGE(fs::exists(ply), "assimp-testmodels is not installed");
  CommandResult result = run_command(std::string(FACET_CLI) + " info " + ply);
  ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  const std::string& text = result.stdout_text;
  const std::size_t row = text.find("\npoints ");
  ASSERT_NE(row, std::string::npos) << text;
  EXPECT_EQ(text.substr(row, text.find('\n', row + 1) - row), "\npoints      4") << text;
  EXPECT_NE(text.find("\ntriangles   0 "), std::string::npos) << text;
}

TEST(Points, RenderRefusesABadPointSize) {
  const fs::path output = fresh_test_dir("facet_points_", "bad_size") / "out.png";
  CommandResult result =
      run_command(std::string(FACET_CLI) + " render --scene shapes --point-size 0 -o '" +
                  output.string() + "'");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_FALSE(fs::exists(output));
  EXPECT_NE(result.stderr_text.find("--point-size"), std::string::npos) << result.stderr_text;
}

}  // namespace
}  // namespace facet::test
