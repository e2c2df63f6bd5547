// The tiled fast path against the scalar reference rasterizer (src/pipeline/reference.cpp):
// identical coverage and identical depth on random triangle soups; on random Lambert-lit,
// textured scenes also colors within a stated tolerance.
#include "pipeline/reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "support/random_soup.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 67;  // odd sizes: partial tiles on both edges
constexpr int kHeight = 43;

TEST(ReferenceEquality, RandomSoupsGiveIdenticalCoverageAndDepth) {
  std::mt19937 rng(20261121);
  Camera camera = test_camera(kWidth, kHeight, 70.0f, 0.5f, 40.0f);
  RenderSettings settings;
  settings.tile_size = 16;
  for (int soup_index = 0; soup_index < 1000; ++soup_index) {
    std::vector<glm::vec3> positions = random_soup(rng);
    Mesh mesh = soup(positions);
    CullMode cull = soup_index % 3 == 0 ? CullMode::back : CullMode::none;
    pipeline::ReferenceImage expected =
        pipeline::reference_rasterize(positions, camera.view_projection(), cull, kWidth, kHeight);
    std::vector<int> counts = coverage_counts({&mesh}, camera, kWidth, kHeight, cull, settings);
    Framebuffer fb = render_unlit({&mesh}, camera, kWidth, kHeight, cull, settings);
    for (int i = 0; i < kWidth * kHeight; ++i) {
      ASSERT_EQ(counts[i], expected.coverage[i]) << "coverage differs at pixel " << i % kWidth
                                                 << "," << i / kWidth << " in soup " << soup_index;
      // Bitwise: the same plane evaluated the same way must give the same float.
      ASSERT_EQ(std::memcmp(&fb.depth()[i], &expected.depth[i], sizeof(float)), 0)
          << "depth differs at pixel " << i % kWidth << "," << i / kWidth << " in soup "
          << soup_index << ": " << fb.depth()[i] << " vs " << expected.depth[i];
    }
  }
}

// Setup drops small triangles that cover no pixel centre (setup.hpp's kProbedBoxSide), and only
// those: of tiny triangles, the renderer draws exactly the ones the reference covers a pixel
// with.
TEST(ReferenceEquality, TinyTrianglesAreDrawnExactlyWhenTheyCoverAPixelCentre) {
  std::mt19937 rng(20261123);
  const Camera camera = test_camera(kWidth, kHeight, 70.0f, 0.5f, 40.0f);
  // At 3 units from the eye a pixel is about 0.1 units: vertices within 0.12 of a point are
  // a few pixels apart, their boxes at most 3 pixel centres a side.
  std::uniform_real_distribution<float> across(-2.5f, 2.5f), up(-1.6f, 1.6f), near(-0.12f, 0.12f);
  std::vector<glm::vec3> positions;
  std::uint64_t covering = 0;
  constexpr int kTriangles = 2000;
  for (int i = 0; i < kTriangles; ++i) {
    const glm::vec3 centre{across(rng), up(rng), -3.0f};
    std::vector<glm::vec3> triangle;
    for (int v = 0; v < 3; ++v) triangle.push_back(centre + glm::vec3(near(rng), near(rng), 0.0f));
    const pipeline::ReferenceImage alone = pipeline::reference_rasterize(
        triangle, camera.view_projection(), CullMode::none, kWidth, kHeight);
    covering += std::count_if(alone.coverage.begin(), alone.coverage.end(),
                              [](int n) { return n > 0; }) > 0;
    positions.insert(positions.end(), triangle.begin(), triangle.end());
  }
  // Both kinds are there.
  ASSERT_GT(covering, 200u);
  ASSERT_LT(covering, kTriangles - 200u);
  const Mesh mesh = soup(positions);
  Renderer renderer;
  Material material;
  material.shading = ShadingModel::unlit;
  material.cull = CullMode::none;
  renderer.begin_frame(camera);
  renderer.draw(mesh, material);
  Framebuffer fb(kWidth, kHeight);
  renderer.finish(fb);
  EXPECT_EQ(renderer.stats().drawn, covering);
}

TEST(ReferenceEquality, ReferenceSeesADifference) {
  // Guard against a comparison that cannot fail: a soup and the same soup shifted by a pixel.
  Camera camera = test_camera(kWidth, kHeight);
  std::vector<glm::vec3> a = {{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
  std::vector<glm::vec3> b = a;
  for (auto& p : b) p.x += 0.05f;
  auto ra =
      pipeline::reference_rasterize(a, camera.view_projection(), CullMode::none, kWidth, kHeight);
  auto rb =
      pipeline::reference_rasterize(b, camera.view_projection(), CullMode::none, kWidth, kHeight);
  EXPECT_NE(ra.coverage, rb.coverage);
}

// --- Lambert with a texture ---------------------------------------------------------------

// How close the fast path's float colors must be to the reference's, per linear channel. The
// two compute the same formulas with floats rounded in different places. The reference weighs
// the vertices by exact edge functions in double; the fast path evaluates float planes of v/w
// and 1/w from the triangle's first vertex (setup.hpp's evaluate), whose rounding grows with a
// plane's slope times the distance from that vertex. For most pixels that is a few float ulps
// of the texture coordinate and the normal; in slivers (steep across them) and in triangles
// clipped at the near plane (whose first vertex may lie thousands of pixels away) it reaches
// several 1e-4 of the texture coordinate, which bilinear sampling of 8 texels per unit, across
// alpha's jump of 0.5 at the texture's seam, turns into color differences of a few 1e-3. Hence
// two bounds: every channel within kColorTolerance, and all but kOutlierFraction of the shaded
// pixels within kTypicalTolerance (most differ by less than 1e-6), which a systematic error
// (affine interpolation, a different light or texel formula) breaks.
constexpr float kColorTolerance = 5e-3f;
constexpr float kTypicalTolerance = 1e-4f;
constexpr double kOutlierFraction = 1e-3;

// The comparison of one or more images with the reference's.
struct ColorComparison {
  float largest = 0.0f;
  std::uint64_t shaded = 0;    // pixels the reference drew
  std::uint64_t atypical = 0;  // of those, how many differ by more than kTypicalTolerance

  // Largest difference over the channels of pixel i, which is counted.
  float add(const Framebuffer& fb, const pipeline::ReferenceImage& expected, int i) {
    float difference = 0.0f;
    for (int c = 0; c < 4; ++c) {
      difference = std::max(difference, std::abs(fb.rgba32f()[i * 4 + c] - expected.color[i][c]));
    }
    largest = std::max(largest, difference);
    if (expected.depth[i] < 1.0f) {
      ++shaded;
      atypical += difference > kTypicalTolerance;
    }
    return difference;
  }
  bool atypical_within_bound() const {
    return static_cast<double>(atypical) <= kOutlierFraction * static_cast<double>(shaded);
  }
};

// 8x8 sRGB texels: a checker of two colors under a gradient, alpha from 0.5 to 1. Sampled
// bilinear (the reference samples the base level: no mip selection).
std::shared_ptr<const Texture> gradient_checker() {
  constexpr int kSize = 8;
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const bool dark = (x + y) % 2 == 1;
      rgba.push_back(static_cast<std::uint8_t>(dark ? 40 + 20 * x : 255 - 10 * y));
      rgba.push_back(static_cast<std::uint8_t>(dark ? 90 : 200 + 7 * x));
      rgba.push_back(static_cast<std::uint8_t>(dark ? 200 - 15 * y : 120));
      rgba.push_back(static_cast<std::uint8_t>(128 + 18 * x));
    }
  }
  return Texture::from_rgba8(kSize, kSize, std::move(rgba), true, "gradient checker");
}

glm::vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> gauss;
  glm::vec3 v;
  do {
    v = {gauss(rng), gauss(rng), gauss(rng)};
  } while (glm::dot(v, v) < 1e-4f);
  return glm::normalize(v);
}

// A normal per vertex: each triangle's three within 37 degrees of a random direction d (d
// plus a vector at most 0.6 long), so any blend of them, once made unit, has a component of at
// least cos 37 degrees = 0.8 along d (a little less after the model's non-uniform scale): the
// interpolated normal is long enough for renormalising it to be well conditioned. (Normals
// pointing apart would blend to near zero somewhere, whose direction no float computation
// pins down.)
std::vector<glm::vec3> random_normals(std::mt19937& rng, std::size_t count) {
  std::uniform_real_distribution<float> length(0.0f, 0.6f);
  std::vector<glm::vec3> normals;
  for (std::size_t t = 0; t < count; t += 3) {
    const glm::vec3 d = random_unit(rng);
    for (int i = 0; i < 3; ++i) normals.push_back(d + random_unit(rng) * length(rng));
  }
  return normals;
}

// A random soup with random normals and texture coordinates (wrapping several times), placed
// by a random rotation, non-uniform scale and shift, seen by a camera near the origin looking
// down -Z, lit by 1-3 directional lights and an ambient term; cull back, front or none.
pipeline::ReferenceScene random_scene(std::mt19937& rng,
                                      const std::shared_ptr<const Texture>& texture) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), part(0.0f, 1.0f);
  std::uniform_int_distribution<int> lights(1, 3), three(0, 2);
  pipeline::ReferenceScene scene;
  scene.mesh = soup(random_soup(rng));
  scene.mesh.normals = random_normals(rng, scene.mesh.positions.size());
  for (std::size_t i = 0; i < scene.mesh.positions.size(); ++i) {
    scene.mesh.texcoords.push_back({1.5f * unit(rng) + 0.5f, 1.5f * unit(rng) + 0.5f});
  }
  const glm::vec3 pivot(0.0f, 0.0f, -10.0f),
      scale(1.0f + 0.25f * unit(rng), 1.0f + 0.25f * unit(rng), 1.0f + 0.25f * unit(rng));
  scene.model = glm::translate(glm::mat4(1.0f), pivot + glm::vec3(unit(rng), unit(rng), unit(rng)));
  scene.model = glm::rotate(scene.model, 0.35f * unit(rng), random_unit(rng));
  scene.model = glm::translate(glm::scale(scene.model, scale), -pivot);
  scene.camera = Camera::look_at(
      {0.5f * unit(rng), 0.5f * unit(rng), 0.5f * unit(rng)}, {unit(rng), unit(rng), -10.0f},
      {0, 1, 0}, 65.0f + 15.0f * unit(rng), static_cast<float>(kWidth) / kHeight, 0.5f, 40.0f);
  Material& m = scene.material;
  m.shading = ShadingModel::lambert;
  m.base_color = {0.4f + 0.6f * part(rng), 0.4f + 0.6f * part(rng), 0.4f + 0.6f * part(rng),
                  0.5f + 0.5f * part(rng)};
  const Wrap wraps[3] = {Wrap::repeat, Wrap::clamp_to_edge, Wrap::mirrored_repeat};
  m.base_color_map.texture = texture;
  m.base_color_map.sampler = {Filter::bilinear, wraps[three(rng)], wraps[three(rng)]};
  const CullMode culls[3] = {CullMode::back, CullMode::none, CullMode::front};
  m.cull = culls[three(rng)];
  scene.lighting.lights.clear();
  for (int i = lights(rng); i > 0; --i) {
    scene.lighting.lights.push_back(Light::directional(
        random_unit(rng),
        {0.2f + 0.8f * part(rng), 0.2f + 0.8f * part(rng), 0.2f + 0.8f * part(rng)},
        0.3f + 1.2f * part(rng)));
  }
  scene.lighting.ambient = {0.3f * part(rng), 0.3f * part(rng), 0.3f * part(rng)};
  scene.clear_color = {part(rng), part(rng), part(rng), 1.0f};
  return scene;
}

// The scene through the renderer into a linear float target (no sRGB rounding to hide errors).
Framebuffer render_scene(const pipeline::ReferenceScene& scene, RenderSettings settings) {
  settings.clear_color = scene.clear_color;
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight, ColorFormat::rgba32f);
  renderer.begin_frame(scene.camera, scene.lighting);
  renderer.draw(scene.mesh, scene.material, scene.model);
  renderer.finish(fb);
  return fb;
}

TEST(ReferenceEquality, RandomLambertScenesGiveIdenticalCoverageAndDepthAndCloseColor) {
  std::mt19937 rng(20261205);
  const std::shared_ptr<const Texture> texture = gradient_checker();
  RenderSettings settings;
  settings.tile_size = 16;
  ColorComparison colors;
  constexpr int kScenes = 1000;
  for (int scene_index = 0; scene_index < kScenes; ++scene_index) {
    const pipeline::ReferenceScene scene = random_scene(rng, texture);
    const pipeline::ReferenceImage expected = pipeline::reference_render(scene, kWidth, kHeight);
    const std::vector<int> counts = coverage_counts({&scene.mesh}, scene.camera, kWidth, kHeight,
                                                    scene.material.cull, settings, scene.model);
    const Framebuffer fb = render_scene(scene, settings);
    for (int i = 0; i < kWidth * kHeight; ++i) {
      const int x = i % kWidth, y = i / kWidth;
      ASSERT_EQ(counts[i], expected.coverage[i])
          << "coverage differs at pixel " << x << "," << y << " in scene " << scene_index;
      ASSERT_EQ(std::memcmp(&fb.depth()[i], &expected.depth[i], sizeof(float)), 0)
          << "depth differs at pixel " << x << "," << y << " in scene " << scene_index << ": "
          << fb.depth()[i] << " vs " << expected.depth[i];
      ASSERT_LE(colors.add(fb, expected, i), kColorTolerance)
          << "color differs at pixel " << x << "," << y << " in scene " << scene_index;
    }
  }
  // Enough shaded pixels for the color comparison to mean something.
  EXPECT_GT(colors.shaded, std::uint64_t{kScenes} * 100);
  EXPECT_TRUE(colors.atypical_within_bound()) << colors.atypical << " of " << colors.shaded;
  std::printf(
      "[ reference] %d scenes, %llu shaded pixels, %llu differ by more than %g; "
      "largest color difference %.3g\n",
      kScenes, static_cast<unsigned long long>(colors.shaded),
      static_cast<unsigned long long>(colors.atypical), kTypicalTolerance, colors.largest);
}

// Guard against a color comparison that cannot fail: the same scenes with every light turned
// by 2 degrees for the renderer break both bounds.
TEST(ReferenceEquality, ReferenceColorSeesADifference) {
  std::mt19937 rng(20261206);
  const std::shared_ptr<const Texture> texture = gradient_checker();
  const glm::mat3 turn(glm::rotate(glm::mat4(1.0f), glm::radians(2.0f), glm::vec3(0, 1, 0)));
  ColorComparison colors;
  for (int scene_index = 0; scene_index < 20; ++scene_index) {
    const pipeline::ReferenceScene scene = random_scene(rng, texture);
    const pipeline::ReferenceImage expected = pipeline::reference_render(scene, kWidth, kHeight);
    pipeline::ReferenceScene turned = scene;
    for (Light& light : turned.lighting.lights) light.direction = turn * light.direction;
    const Framebuffer fb = render_scene(turned, {});
    for (int i = 0; i < kWidth * kHeight; ++i) colors.add(fb, expected, i);
  }
  std::printf(
      "[ reference] turned lights: %llu of %llu shaded pixels differ by more than %g; "
      "largest color difference %.3g\n",
      static_cast<unsigned long long>(colors.atypical),
      static_cast<unsigned long long>(colors.shaded), kTypicalTolerance, colors.largest);
  EXPECT_GT(colors.largest, kColorTolerance);
  EXPECT_FALSE(colors.atypical_within_bound());
}

}  // namespace
}  // namespace facet::test
