// The pixels of a draw's small triangles wait to be shaded together
// (pipeline/raster/small_triangles.hpp) and are depth-tested again when written: the image, colors
// and depths, must be the one drawing the same triangles one draw each gives (a draw change writes
// what waits), for heavily overlapping triangles at random depths in random order, textured with
// trilinear filtering, lit and fogged, in every shading model whose pixels wait.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "facet/renderer.hpp"
#include "facet/texture.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 96, kHeight = 64;

// Triangles crowded into the middle of the view at random depths, with texture coordinates and
// normals that vary: small ones (a few pixels across), or with `spread` 0.3, boxes of up to a
// few hundred pixels, which wait a band of rows at a time (small_triangles.hpp).
Mesh crowded_triangles(std::mt19937& rng, int count, float spread = 0.08f) {
  std::uniform_real_distribution<float> centre(-0.3f, 0.3f), corner(-spread, spread),
      depth(-6.0f, -3.0f), any(-1.0f, 1.0f);
  Mesh mesh;
  for (int i = 0; i < count; ++i) {
    const float z = depth(rng), cx = centre(rng), cy = centre(rng) * 0.7f;
    for (int k = 0; k < 3; ++k) {
      mesh.positions.push_back({(cx + corner(rng)) * -z, (cy + corner(rng)) * -z, z});
      mesh.normals.push_back(glm::normalize(glm::vec3(any(rng), any(rng), 1.5f)));
      mesh.texcoords.push_back({any(rng) * 4.0f, any(rng) * 4.0f});
    }
  }
  return mesh;
}

// The mesh's triangle i alone.
Mesh triangle_of(const Mesh& mesh, int i) {
  Mesh one;
  for (int k = 3 * i; k < 3 * i + 3; ++k) {
    one.positions.push_back(mesh.positions[k]);
    one.normals.push_back(mesh.normals[k]);
    one.texcoords.push_back(mesh.texcoords[k]);
  }
  return one;
}

std::shared_ptr<const Texture> stripes() {
  std::vector<std::uint8_t> rgba(32 * 32 * 4);
  for (int i = 0; i < 32 * 32; ++i) {
    const int x = i % 32, y = i / 32;
    rgba[4 * i] = static_cast<std::uint8_t>(x * 8);
    rgba[4 * i + 1] = static_cast<std::uint8_t>((x + y) % 3 == 0 ? 255 : 40);
    rgba[4 * i + 2] = static_cast<std::uint8_t>(y * 8);
    rgba[4 * i + 3] = 255;
  }
  return Texture::from_rgba8(32, 32, rgba, true, "stripes");
}

// Draws the crowd all at once and one triangle a draw (a draw change writes what waits), in
// every shading model whose pixels wait: the same image, depths and pixel count.
void expect_one_by_one_image(const Mesh& mesh, int count) {
  std::vector<Mesh> singles;
  for (int i = 0; i < count; ++i) singles.push_back(triangle_of(mesh, i));
  Lighting lighting;
  lighting.fog.mode = FogMode::exponential;
  lighting.fog.density = 0.1f;
  const Camera camera = test_camera(kWidth, kHeight);
  for (ShadingModel model : {ShadingModel::lambert, ShadingModel::unlit, ShadingModel::phong,
                             ShadingModel::blinn_phong, ShadingModel::normals}) {
    Material material;
    material.shading = model;
    material.cull = CullMode::none;
    material.base_color_map.texture = stripes();
    Renderer renderer;
    Framebuffer together(kWidth, kHeight), one_by_one(kWidth, kHeight);
    renderer.begin_frame(camera, lighting);
    renderer.draw(mesh, material);
    renderer.finish(together);
    const std::uint64_t shaded_together = renderer.stats().pixels_shaded;
    renderer.begin_frame(camera, lighting);
    for (const Mesh& single : singles) renderer.draw(single, material);
    renderer.finish(one_by_one);
    EXPECT_EQ(renderer.stats().pixels_shaded, shaded_together) << static_cast<int>(model);
    EXPECT_EQ(together.depth(), one_by_one.depth()) << static_cast<int>(model);
    ASSERT_EQ(together.rgba8(), one_by_one.rgba8()) << static_cast<int>(model);
  }
}

TEST(WaitingPixels, GiveTheImageOfDrawingTrianglesOneByOne) {
  std::mt19937 rng(20261122);
  expect_one_by_one_image(crowded_triangles(rng, 400), 400);
}

TEST(WaitingPixels, GiveTheImageOfDrawingBiggerTrianglesOneByOne) {
  std::mt19937 rng(20261123);
  expect_one_by_one_image(crowded_triangles(rng, 150, 0.3f), 150);
}

// The test above is only worth something if triangles overlap, nearer ones after farther
// ones and the other way round: count how often a pixel is covered more than once.
TEST(WaitingPixels, TheirTestSceneOverlaps) {
  std::mt19937 rng(20261122);
  const Mesh mesh = crowded_triangles(rng, 400);
  const std::vector<int> counts =
      coverage_counts({&mesh}, test_camera(kWidth, kHeight), kWidth, kHeight);
  int overlapped = 0;
  for (int c : counts) overlapped += c >= 3;
  EXPECT_GT(overlapped, 300);
}

}  // namespace
}  // namespace facet::test
