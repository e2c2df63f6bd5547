// Multisample anti-aliasing (RenderSettings::msaa, src/pipeline/raster/msaa.hpp): every sample
// covered once along shared edges, edge pixels' coverage against the exact area, the same image
// for any thread count, tile size and SIMD target, a golden, and refused sample counts.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <string>
#include <vector>

#include "facet/color.hpp"
#include "facet/error.hpp"
#include "facet/image_io.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"
#include "support/forced_target.hpp"
#include "support/geometry.hpp"
#include "support/golden.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 72;
constexpr double kDistance = 2.0;
constexpr int kSampleCounts[] = {1, 2, 4, 8, 16};

// The mean, over each pixel's samples, of how many triangles covered the sample (the overdraw
// counter, additive and without depth test, resolved in a float target): exactly 1 where every
// sample is covered once.
std::vector<float> mean_sample_counts(const Mesh& mesh, int samples) {
  RenderSettings settings;
  settings.msaa = samples;
  settings.clear_color = glm::vec4(0.0f);
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight, ColorFormat::rgba32f);
  Material material;
  material.cull = CullMode::none;
  renderer.begin_frame(test_camera(kWidth, kHeight));
  pipeline::draw_with_pipeline(renderer, mesh, material, glm::mat4(1.0f),
                               pipeline::make_pipeline<shading::OverdrawCountShading>());
  renderer.finish(fb);
  std::vector<float> counts(static_cast<std::size_t>(kWidth) * kHeight);
  for (std::size_t i = 0; i < counts.size(); ++i) counts[i] = fb.rgba32f()[i * 4];
  return counts;
}

// A grid of quads over more than the screen, split into triangles, its interior vertices moved
// at random to sixteenths of a pixel: the sample positions' grid, so that many shared edges run
// exactly through samples, where only the fill rule decides.
Mesh sixteenth_grid(int cells_x, int cells_y, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> jitter(-40, 40);  // sixteenths: 2.5 pixels at most
  Mesh mesh;
  const double cell_w = (kWidth + 20.0) / cells_x, cell_h = (kHeight + 20.0) / cells_y;
  for (int j = 0; j <= cells_y; ++j) {
    for (int i = 0; i <= cells_x; ++i) {
      const bool interior = i > 0 && j > 0 && i < cells_x && j < cells_y;
      const double sx =
          std::round((-10.0 + i * cell_w) * 16.0) / 16.0 + (interior ? jitter(rng) / 16.0 : 0.0);
      const double sy =
          std::round((-10.0 + j * cell_h) * 16.0) / 16.0 + (interior ? jitter(rng) / 16.0 : 0.0);
      mesh.positions.push_back(at_pixel(sx, sy, kWidth, kHeight, kDistance));
    }
  }
  for (int j = 0; j < cells_y; ++j) {
    for (int i = 0; i < cells_x; ++i) {
      const std::uint32_t a = j * (cells_x + 1) + i, b = a + 1, c = a + cells_x + 1, d = c + 1;
      // Both diagonals, at random: edges of every direction.
      if (rng() & 1) {
        mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
      } else {
        mesh.indices.insert(mesh.indices.end(), {a, c, d, a, d, b});
      }
    }
  }
  return mesh;
}

// A fan of triangles around (cx, cy) (pixels), its rim `radius` pixels away, outside the screen.
Mesh fan(double cx, double cy, int spokes, double phase, double radius = 200.0) {
  Mesh mesh;
  mesh.positions.push_back(at_pixel(cx, cy, kWidth, kHeight, kDistance));
  for (int k = 0; k < spokes; ++k) {
    const double angle = phase + k * 2.0 * 3.14159265358979323846 / spokes;
    mesh.positions.push_back(at_pixel(cx + radius * std::cos(angle), cy + radius * std::sin(angle),
                                      kWidth, kHeight, kDistance));
  }
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(spokes); ++k) {
    mesh.indices.insert(mesh.indices.end(), {0, 1 + (k + 1) % spokes, 1 + k});
  }
  return mesh;
}

// A sample covered twice or missed moves its pixel's mean off 1 by 1/N; to hide, it would need
// the opposite mistake at another sample of the same pixel.
void expect_every_sample_once(const Mesh& mesh, int samples, const std::string& what) {
  const std::vector<float> counts = mean_sample_counts(mesh, samples);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      ASSERT_EQ(counts[y * kWidth + x], 1.0f)
          << what << ", " << samples << " samples: pixel " << x << "," << y;
    }
  }
}

TEST(Msaa, SharedEdgesCoverEverySampleExactlyOnce) {
  for (int samples : kSampleCounts) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Mesh grid = sixteenth_grid(9 + 2 * seed, 7 + seed, seed);
      expect_every_sample_once(grid, samples, "grid seed " + std::to_string(seed));
    }
    // Spokes through a pixel centre, a pixel corner, a 4x sample and anywhere; phase 0 puts
    // spokes along rows and columns, through whole rows of samples.
    const double centres[][2] = {
        {40.5, 30.5}, {40.0, 30.0}, {40.5 - 2.0 / 16, 30.5 - 6.0 / 16}, {33.37, 41.81}};
    for (const auto& c : centres) {
      for (double phase : {0.0, 0.377}) {
        expect_every_sample_once(fan(c[0], c[1], 24, phase), samples,
                                 "fan at " + std::to_string(c[0]) + "," + std::to_string(c[1]));
        // Edges over 1024 pixels long: too long for the 32-bit search, searched in doubles.
        expect_every_sample_once(
            fan(c[0], c[1], 24, phase, 3000.0), samples,
            "wide fan at " + std::to_string(c[0]) + "," + std::to_string(c[1]));
      }
    }
  }
}

// The area of triangle (x[i], y[i]) (pixels) inside the pixel square [px, px+1] x [py, py+1]:
// the triangle clipped by the square's four sides (Sutherland-Hodgman), then the shoelace.
double area_in_pixel(const double x[3], const double y[3], int px, int py) {
  std::vector<glm::dvec2> polygon = {{x[0], y[0]}, {x[1], y[1]}, {x[2], y[2]}};
  // Keep the side where sign * (coordinate - bound) >= 0.
  const struct {
    int axis;
    double bound, sign;
  } sides[4] = {
      {0, double(px), 1.0}, {0, px + 1.0, -1.0}, {1, double(py), 1.0}, {1, py + 1.0, -1.0}};
  for (const auto& side : sides) {
    std::vector<glm::dvec2> kept;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      const double da = side.sign * (a[side.axis] - side.bound);
      const double db = side.sign * (b[side.axis] - side.bound);
      if (da >= 0) kept.push_back(a);
      if ((da >= 0) != (db >= 0)) kept.push_back(a + (b - a) * (da / (da - db)));
    }
    polygon = kept;
    if (polygon.empty()) return 0.0;
  }
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return std::abs(twice) * 0.5;
}

// The mean absolute difference, over the edge pixels of random triangles (those the exact area
// covers in part), between the covered fraction msaa gives (white on black, resolved in a float
// target: k/N) and the exact area.
double edge_coverage_error(int samples) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> coordinate(4.0, 92.0);
  RenderSettings settings;
  settings.msaa = samples;
  settings.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kWidth, ColorFormat::rgba32f);
  Material material;
  material.shading = ShadingModel::unlit;
  material.cull = CullMode::none;
  double error = 0.0;
  int edge_pixels = 0;
  for (int triangle = 0; triangle < 40; ++triangle) {
    double x[3], y[3];
    for (int i = 0; i < 3; ++i) x[i] = coordinate(rng), y[i] = coordinate(rng);
    Mesh mesh;
    for (int i = 0; i < 3; ++i) mesh.positions.push_back(at_pixel(x[i], y[i], kWidth, kWidth, 3.0));
    mesh.indices = {0, 1, 2};
    renderer.begin_frame(test_camera(kWidth, kWidth));
    renderer.draw(mesh, material);
    renderer.finish(fb);
    for (int py = 0; py < kWidth; ++py) {
      for (int px = 0; px < kWidth; ++px) {
        const double exact = area_in_pixel(x, y, px, py);
        if (exact <= 1e-9 || exact >= 1.0 - 1e-9) continue;
        error += std::abs(fb.rgba32f()[(py * kWidth + px) * 4] - exact);
        ++edge_pixels;
      }
    }
  }
  return error / edge_pixels;
}

// Measured (40 random triangles, 96x96): 1 sample 0.198, 4: 0.0695, 8: 0.0443, 16: 0.0344
// (docs/pipeline.md, "Anti-aliasing"); a separate emulation of the sample patterns in double
// precision gives the same. At 4 samples the positions are the standard pattern llvmpipe's 4x
// MSAA uses too, so its error is llvmpipe's. The bounds leave a little room; they fail if the
// samples sat at the pixel centre (0.198), were spread wrongly, or 8 and 16 were not clearly
// better.
TEST(Msaa, EdgePixelsCoverageIsCloseToTheExactArea) {
  const double one = edge_coverage_error(1), four = edge_coverage_error(4);
  const double eight = edge_coverage_error(8), sixteen = edge_coverage_error(16);
  std::printf("mean edge coverage error: 1x %.4f, 4x %.4f, 8x %.4f, 16x %.4f\n", one, four, eight,
              sixteen);
  EXPECT_GT(one, 0.15);
  EXPECT_LT(four, 0.075);
  EXPECT_LT(eight, 0.75 * four);
  EXPECT_LT(sixteen, 0.85 * eight);
  EXPECT_LT(sixteen, 0.6 * four);
}

// A cut-out quad whose alpha runs from 0 at the left to 1 at the right, white on black: its red
// channel per pixel in a float target, row `row`.
std::vector<float> cut_out_row(int samples, int row) {
  Mesh quad;
  const double left = 8.0, right = 88.0, top = 10.0, bottom = 60.0;
  quad.positions = {at_pixel(left, top, kWidth, kHeight, kDistance),
                    at_pixel(right, top, kWidth, kHeight, kDistance),
                    at_pixel(right, bottom, kWidth, kHeight, kDistance),
                    at_pixel(left, bottom, kWidth, kHeight, kDistance)};
  quad.colors = {{1, 1, 1, 0}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 0}};
  quad.indices = {0, 2, 1, 0, 3, 2};
  Material material;
  material.shading = ShadingModel::vertex_color;
  material.use_vertex_colors = true;
  material.alpha_mode = AlphaMode::mask;
  material.alpha_cutoff = 0.5f;
  material.cull = CullMode::none;
  RenderSettings settings;
  settings.msaa = samples;
  settings.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight, ColorFormat::rgba32f);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.draw(quad, material);
  renderer.finish(fb);
  std::vector<float> values(kWidth);
  for (int x = 0; x < kWidth; ++x) values[x] = fb.rgba32f()[(row * kWidth + x) * 4];
  return values;
}

// Alpha to coverage: under MSAA a cut-out keeps round(N * a') of its samples, a' being alpha
// mapped so that the cutoff keeps half; at 1 sample it is the plain cutoff.
TEST(Msaa, AlphaToCoverageSoftensCutOutEdges) {
  const std::vector<float> one = cut_out_row(1, 35), four = cut_out_row(4, 35);
  int first_kept = -1;  // the first column the one-sample cutoff keeps
  for (int x = 0; x < kWidth; ++x) {
    ASSERT_TRUE(one[x] == 0.0f || one[x] == 1.0f) << x;
    if (one[x] == 1.0f && first_kept < 0) first_kept = x;
  }
  ASSERT_GT(first_kept, 40);
  ASSERT_LT(first_kept, 56);  // alpha 0.5 at pixel 48
  bool seen[5] = {};
  for (int x = 9; x < 87; ++x) {
    EXPECT_LE(four[x], four[x + 1]) << "coverage falls at column " << x;  // alpha only grows
    const float k = four[x] * 4.0f;
    ASSERT_EQ(k, std::round(k)) << x;
    seen[static_cast<int>(k)] = true;
  }
  for (int k = 0; k <= 4; ++k) EXPECT_TRUE(seen[k]) << k << " of 4 samples never kept";
  // Half the samples where the one-sample cutoff switches.
  EXPECT_EQ(four[first_kept], 0.5f);
  const std::vector<float> above = cut_out_row(4, 5);  // above the quad: nothing
  EXPECT_EQ(*std::max_element(above.begin(), above.end()), 0.0f);
}

TEST(Msaa, UnsupportedSampleCountsAreRefused) {
  for (int samples : {-4, 0, 3, 6, 32}) {
    RenderSettings settings;
    settings.msaa = samples;
    try {
      Renderer renderer(settings);
      ADD_FAILURE() << "msaa " << samples << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("msaa must be 1, 2, 4, 8 or 16"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("got " + std::to_string(samples)), std::string::npos)
          << e.what();
    }
  }
  for (int samples : kSampleCounts) {
    RenderSettings settings;
    settings.msaa = samples;
    EXPECT_NO_THROW(Renderer{settings});
  }
}

// The shapes scene (with its sky, lines of the wireframe, blended and cut-out draws where the
// scene has them) at msaa 4.
Framebuffer render_shapes_msaa(ShadingModel model, int threads, int tile_size) {
  RenderSettings settings;
  settings.threads = threads;
  settings.tile_size = tile_size;
  settings.msaa = 4;
  return render_shapes(model, 203, 117, settings);
}

// A rectangle of the screen's pixels [x0, x1] x [y0, y1] at `distance`, as two triangles.
Mesh screen_rectangle(double x0, double y0, double x1, double y1, double distance) {
  return soup(
      {at_pixel(x0, y0, kWidth, kHeight, distance), at_pixel(x0, y1, kWidth, kHeight, distance),
       at_pixel(x1, y1, kWidth, kHeight, distance), at_pixel(x0, y0, kWidth, kHeight, distance),
       at_pixel(x1, y1, kWidth, kHeight, distance), at_pixel(x1, y0, kWidth, kHeight, distance)});
}

// Unlit, two-sided meshes drawn in order, each in its color, in front of test_camera on opaque
// black, at `samples` a pixel.
struct Layer {
  const Mesh* mesh;
  glm::vec4 color;
};
Framebuffer render_layers(const std::vector<Layer>& layers, int samples) {
  RenderSettings settings;
  settings.msaa = samples;
  settings.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  Material material;
  material.shading = ShadingModel::unlit;
  material.cull = CullMode::none;
  for (const Layer& layer : layers) {
    material.base_color = layer.color;
    renderer.draw(*layer.mesh, material);
  }
  renderer.finish(fb);
  return fb;
}

// A far layer over the whole screen, then small near squares (their pixels may wait), then a
// middle layer: the near squares must stay in front of the middle layer at every sample count,
// however the middle layer's whole covered blocks are written.
TEST(Msaa, LaterLayersBehindSmallNearTrianglesDoNotCoverThem) {
  const Mesh far = screen_rectangle(-20, -20, kWidth + 20, kHeight + 20, 6.0);
  Mesh near;
  for (int k = 0; k < 6; ++k) {
    const double x = 3.0 + 15.0 * k, y = 5.0 + 9.0 * k;
    const Mesh square = screen_rectangle(x, y, x + 3.0, y + 3.0, 2.0);
    near.positions.insert(near.positions.end(), square.positions.begin(), square.positions.end());
  }
  const Mesh middle = screen_rectangle(-20, -20, kWidth + 20, kHeight + 20, 4.0);
  for (int samples : kSampleCounts) {
    const Framebuffer fb = render_layers(
        {{&far, {1, 0, 0, 1}}, {&near, {0, 1, 0, 1}}, {&middle, {0, 0, 1, 1}}}, samples);
    for (int k = 0; k < 6; ++k) {  // the squares' middle pixels: green, every sample
      const int x = 4 + 15 * k, y = 6 + 9 * k;
      const std::uint8_t* rgba = fb.rgba8().data() + 4 * (static_cast<std::size_t>(y) * kWidth + x);
      EXPECT_EQ(rgba[0], 0) << samples << " samples, square " << k;
      EXPECT_EQ(rgba[1], 255) << samples << " samples, square " << k;
      EXPECT_EQ(rgba[2], 0) << samples << " samples, square " << k;
    }
  }
}

// A far red layer over the whole screen, then a near blue triangle covering every pixel centre of
// the first tiles but not every sample of the first column (its left edge 0.3 pixels in): the
// occlusion skip (occlusion.hpp) must not take the blue one for a hider of the tiles there, so
// those pixels blend red and blue at every sample count.
TEST(Msaa, OcclusionSkipKeepsWhatShowsBetweenSamples) {
  const Mesh red = screen_rectangle(-20, -20, kWidth + 20, kHeight + 20, 6.0);
  const Mesh blue = soup({at_pixel(0.3, -200.0, kWidth, kHeight, 2.0),
                          at_pixel(0.3, kHeight + 200.0, kWidth, kHeight, 2.0),
                          at_pixel(kWidth + 400.0, kHeight / 2.0, kWidth, kHeight, 2.0)});
  for (int samples : kSampleCounts) {
    const Framebuffer fb = render_layers({{&red, {1, 0, 0, 1}}, {&blue, {0, 0, 1, 1}}}, samples);
    for (int y = 0; y < kHeight; ++y) {
      const std::uint8_t* rgba = fb.rgba8().data() + 4 * static_cast<std::size_t>(y) * kWidth;
      if (samples == 1) {  // the centre is blue's
        ASSERT_EQ(rgba[0], 0) << "row " << y;
      } else {
        ASSERT_GT(rgba[0], 0) << samples << " samples, row " << y;
      }
      ASSERT_GT(rgba[2], 0) << samples << " samples, row " << y;
    }
  }
}

TEST(Msaa, ThreadsAndTileSizesGiveIdenticalImages) {
  for (ShadingModel model : {ShadingModel::lambert, ShadingModel::wireframe,
                             ShadingModel::wire_overlay, ShadingModel::pbr}) {
    const Framebuffer expected = render_shapes_msaa(model, 1, 64);
    for (int threads : {2, 3}) {
      for (int tile : {16, 32, 128}) {
        const Framebuffer fb = render_shapes_msaa(model, threads, tile);
        ASSERT_EQ(fb.rgba8(), expected.rgba8())
            << to_string(model) << " with " << threads << " threads, tile " << tile;
        ASSERT_EQ(fb.depth(), expected.depth());
      }
    }
  }
}

TEST(Msaa, EverySimdTargetGivesThePortableTargetsImage) {
  const std::vector<std::int64_t> targets = simd_targets();
  for (ShadingModel model :
       {ShadingModel::unlit, ShadingModel::phong, ShadingModel::pbr, ShadingModel::wire_overlay}) {
    const Framebuffer expected = [&] {
      ForcedTarget portable(targets.back());  // the list is best first
      return render_shapes_msaa(model, 0, 64);
    }();
    for (std::int64_t target : targets) {
      ForcedTarget forced(target);
      const Framebuffer fb = render_shapes_msaa(model, 0, 64);
      ASSERT_EQ(fb.rgba8(), expected.rgba8())
          << to_string(model) << " on " << hwy::TargetName(target);
      ASSERT_EQ(fb.depth(), expected.depth())
          << to_string(model) << " on " << hwy::TargetName(target);
    }
  }
}

// Layers of small triangles (their pixels wait with their sample masks), a far one drawn first
// and hidden by a full near layer drawn last (occlusion skips it), at 4 samples: the same image
// and depths for any thread count, tile size and SIMD target.
Framebuffer render_small_layers_msaa(int threads, int tile_size) {
  RenderSettings settings;
  settings.threads = threads;
  settings.tile_size = tile_size;
  settings.msaa = 4;
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  Material material;
  material.shading = ShadingModel::lambert;
  material.cull = CullMode::none;
  const Mesh fine = sixteenth_grid(48, 36, 7);
  const Mesh coarse = sixteenth_grid(4, 3, 8);
  material.base_color = {0.8f, 0.3f, 0.2f, 1.0f};
  renderer.draw(fine, material, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -1.0f)));
  material.base_color = {0.2f, 0.7f, 0.3f, 1.0f};
  renderer.draw(fine, material);
  Mesh partial = coarse;  // the near layer's first half: not every tile hidden
  partial.indices.resize(partial.indices.size() / 2);
  material.base_color = {0.2f, 0.3f, 0.9f, 1.0f};
  renderer.draw(partial, material, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.5f)));
  renderer.finish(fb);
  return fb;
}

TEST(Msaa, SmallTrianglesAndOcclusionGiveOneImageForEveryThreadTileAndTarget) {
  const Framebuffer expected = render_small_layers_msaa(1, 64);
  for (int threads : {2, 3}) {
    for (int tile : {16, 32, 128}) {
      const Framebuffer fb = render_small_layers_msaa(threads, tile);
      ASSERT_EQ(fb.rgba8(), expected.rgba8()) << threads << " threads, tile " << tile;
      ASSERT_EQ(fb.depth(), expected.depth()) << threads << " threads, tile " << tile;
    }
  }
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const Framebuffer fb = render_small_layers_msaa(0, 64);
    ASSERT_EQ(fb.rgba8(), expected.rgba8()) << hwy::TargetName(target);
    ASSERT_EQ(fb.depth(), expected.depth()) << hwy::TargetName(target);
  }
}

// One draw of a fine near grid followed by the same grid farther away: the far triangles' pixels
// wait in the same batches as the near ones' that hide them, found before those were written,
// and must fail their samples' depth test when written. The image and depths are those of the
// near grid alone.
TEST(Msaa, WaitingPixelsBehindEarlierOnesOfTheirDrawAreNotWritten) {
  const Mesh near = sixteenth_grid(48, 36, 7);
  Mesh both = near;
  const auto count = static_cast<std::uint32_t>(near.positions.size());
  for (const glm::vec3& p : near.positions) both.positions.push_back(p * 1.5f);  // same pixels
  for (std::uint32_t i : near.indices) both.indices.push_back(i + count);
  for (int samples : kSampleCounts) {
    const auto render = [&](const Mesh& mesh) {
      RenderSettings settings;
      settings.msaa = samples;
      Renderer renderer(settings);
      Framebuffer fb(kWidth, kHeight);
      renderer.begin_frame(test_camera(kWidth, kHeight));
      Material material;
      material.shading = ShadingModel::lambert;
      material.cull = CullMode::none;
      renderer.draw(mesh, material);
      renderer.finish(fb);
      return fb;
    };
    const Framebuffer expected = render(near);
    const Framebuffer fb = render(both);
    ASSERT_EQ(fb.rgba8(), expected.rgba8()) << samples << " samples";
    ASSERT_EQ(fb.depth(), expected.depth()) << samples << " samples";
  }
}

// At msaa 1 the image is the one-sample pipeline's, whatever RenderSettings held before.
TEST(Msaa, OneSampleIsTheDefaultAndChangesNothing) {
  EXPECT_EQ(RenderSettings{}.msaa, 1);
  RenderSettings one;
  one.msaa = 1;
  EXPECT_EQ(render_shapes(ShadingModel::lambert, 160, 90, one).rgba8(),
            render_shapes(ShadingModel::lambert, 160, 90).rgba8());
}

// A crop of the shapes scene where the sphere's silhouette crosses the sky and the ground,
// rendered at `samples`.
Framebuffer shapes_crop(int samples) {
  Scene scene = make_shapes_scene();
  scene.lighting.environment.show_as_background = true;
  Camera camera = scene.camera;
  constexpr int kFullWidth = 400, kFullHeight = 225;
  camera.aspect = static_cast<float>(kFullWidth) / kFullHeight;
  RenderSettings settings;
  settings.msaa = samples;
  const Framebuffer full = render_scene_image(scene, camera, kFullWidth, kFullHeight, settings);
  constexpr int kX = 134, kY = 54, kCropW = 64, kCropH = 48;
  Framebuffer crop(kCropW, kCropH);
  for (int y = 0; y < kCropH; ++y) {
    std::copy_n(full.rgba8().data() + ((kY + y) * kFullWidth + kX) * 4, kCropW * 4,
                crop.rgba8().data() + y * kCropW * 4);
  }
  return crop;
}

TEST(Msaa, SceneEdgeAtFourSamplesMatchesGolden) {
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "msaa4_edge.png").string();
  write_image(shapes_crop(4), path);
  expect_matches_golden(path, "msaa4_edge");
}

// docs/pipeline/resolve_msaa.png: the same crop at 1 sample (left) and 4 (right), each pixel
// drawn as a 4x4 square so the steps show.
TEST(Msaa, DocsPictureOneAndFourSamples) {
  constexpr int kZoom = 4, kGap = 4;
  const Framebuffer one = shapes_crop(1), four = shapes_crop(4);
  const int w = one.width(), h = one.height();
  Framebuffer picture(2 * w * kZoom + kGap, h * kZoom);
  std::fill(picture.rgba8().begin(), picture.rgba8().end(), std::uint8_t{255});
  for (int side = 0; side < 2; ++side) {
    const Framebuffer& source = side == 0 ? one : four;
    for (int y = 0; y < h * kZoom; ++y) {
      for (int x = 0; x < w * kZoom; ++x) {
        const std::uint8_t* from = source.rgba8().data() + ((y / kZoom) * w + x / kZoom) * 4;
        std::uint8_t* to =
            picture.rgba8().data() + (y * picture.width() + side * (w * kZoom + kGap) + x) * 4;
        std::copy_n(from, 4, to);
      }
    }
  }
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "resolve_msaa.png").string();
  write_image(picture, path);
  expect_matches_golden_in(FACET_DOCS_PICTURE_DIR, path, "resolve_msaa");
}

}  // namespace
}  // namespace facet::test
