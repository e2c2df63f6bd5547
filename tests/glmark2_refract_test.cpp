// glmark2's refract shaders (bench/scenes/glmark2_shading.hpp, their kernel in glmark2_batch.cpp):
// the formula worked out per pixel against textures whose texels say where they were read, the
// same bits on every SIMD target, and the back faces' normals pass. The whole scene is checked
// against glmark2's own frame by glmark2_equivalence_test.cpp.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "scenes/glmark2_shading.hpp"
#include "shading/kernels.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using shading::kShadeBatch;
using Shading = bench::glmark2::RefractShading;

// An 8-bit texture (read as unorm) whose red and green are the texel's column and row from the
// bottom (v grows upward): a bilinear lookup's red and green then give back where it was read.
std::shared_ptr<const Texture> coordinate_image(int size) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * size * 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      std::uint8_t* texel = &rgba[(static_cast<std::size_t>(y) * size + x) * 4];
      texel[0] = static_cast<std::uint8_t>(x);
      texel[1] = static_cast<std::uint8_t>(size - 1 - y);  // rows are stored top first
      texel[2] = 40;
      texel[3] = 255;
    }
  }
  return Texture::from_rgba8(size, size, std::move(rgba), false, "coordinates");
}

// A one-float texture of `value` everywhere.
std::shared_ptr<const Texture> flat_depth(float value) {
  return Texture::from_r32f(4, 4, std::vector<float>(16, value), "depth");
}

// An 8-bit unorm texture of the normal (0, 0, 1) everywhere (codes as they are, not remapped).
std::shared_ptr<const Texture> flat_normals() {
  std::vector<std::uint8_t> rgba;
  for (int i = 0; i < 16; ++i) rgba.insert(rgba.end(), {0, 0, 255, 255});
  return Texture::from_rgba8(4, 4, std::move(rgba), false, "normals");
}

struct RefractDraw {
  Material material;
  Lighting lighting;
  shading::ShadingKernels kernels;
  shading::FrameUniforms frame;
  shading::DrawUniforms uniforms;

  RefractDraw() {
    const Sampler clamped{Filter::bilinear, Wrap::clamp_to_edge, Wrap::clamp_to_edge};
    material.base_color_map = {coordinate_image(256), clamped};
    material.normal_map = {flat_normals(), clamped};
    material.normal_map.sampler.filter = Filter::trilinear;
    material.occlusion_map = {flat_depth(0.5f), clamped};
    material.occlusion_map.sampler.filter = Filter::nearest;
    kernels = shading::shading_kernels(chosen_simd_target());
    frame.kernels = &kernels;
    frame.lighting = &lighting;
    frame.display_referred = true;  // colors are code / 255
    frame.width = 640;
    frame.height = 360;
    frame.projection = glm::perspective(glm::radians(48.0f), 640.0f / 360.0f, 2.0f, 5.2f);
    uniforms.material = &material;
    uniforms.frame = &frame;
  }
};

// GLSL's refract and reflect, written out in double.
glm::dvec3 refract(glm::dvec3 i, glm::dvec3 n, double e) {
  const double d = glm::dot(n, i), k = 1.0 - e * e * (1.0 - d * d);
  return k < 0.0 ? glm::dvec3(0.0) : e * i - (e * d + std::sqrt(k)) * n;
}

// One pixel: the eye normal n, eye position p and MapCoord (as the varyings are laid out).
struct Pixel {
  glm::dvec3 n, p;
  glm::dvec4 map_coord;
};

// What light-refract.frag gives for `pixel` with the maps of RefractDraw: the distance 0.5, the
// back normal (0, 0, 1) and the image whose texel (x, y) is (x, y, 40) / 255; then the codes.
glm::dvec3 expected_codes(const Pixel& pixel) {
  const glm::dvec3 eye = glm::normalize(-pixel.p), n = glm::normalize(pixel.n);
  const glm::dvec3 front = refract(eye, n, 1.2);
  const glm::dvec3 back = pixel.p + front * 0.5;
  const glm::dvec3 out = refract(back, {0.0, 0.0, 1.0}, 1.0 / 1.2);
  // The image is bilinear and clamped on 256 texels: red = u 256 - 0.5 clamped to [0, 255],
  // green the same of v.
  const glm::dvec2 uv = glm::dvec2(out) * 0.5 + 0.5;
  const glm::dvec2 read = glm::clamp(uv * 256.0 - 0.5, 0.0, 255.0);
  const glm::dvec3 light = glm::normalize(pixel.p - glm::dvec3(1.0, 1.0, 2.0));
  const double s = std::pow(std::max(glm::dot(glm::reflect(light, n), eye), 0.0), 100.0);
  const glm::dvec3 rgb = glm::dvec3(read.x, read.y, 40.0) / 255.0 + 0.8 * s;
  return glm::clamp(rgb, 0.0, 1.0) * 255.0;
}

// Shades `pixels` with the refract kernel of the chosen target, returning their codes.
std::vector<glm::vec3> shade(const RefractDraw& draw, const std::vector<Pixel>& pixels) {
  alignas(64) float w[kShadeBatch] = {}, z[kShadeBatch] = {};
  alignas(64) float v[shading::kMaxVaryings][kShadeBatch] = {};
  const int count = static_cast<int>(pixels.size());
  for (int i = 0; i < count; ++i) {
    for (int k = 0; k < 3; ++k) {
      v[k][i] = static_cast<float>(pixels[i].n[k]);
      v[Shading::kPosition + k][i] = static_cast<float>(pixels[i].p[k]);
    }
    for (int k = 0; k < 4; ++k)
      v[Shading::kMapCoord + k][i] = static_cast<float>(pixels[i].map_coord[k]);
  }
  shading::ShadeInput input{count, w, z, v};
  alignas(64) float rgba[kShadeBatch][4];
  Shading::fragment_batch(draw.uniforms, input, rgba);
  std::vector<glm::vec3> codes;
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(rgba[i][3], 1.0f);
    codes.push_back(glm::vec3(rgba[i][0], rgba[i][1], rgba[i][2]) * 255.0f);
  }
  return codes;
}

// Surface points of the bunny's size seen from 3.6 away, their normals toward the viewer.
std::vector<Pixel> random_pixels(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> any(-1.0, 1.0), unit(0.0, 1.0);
  std::vector<Pixel> pixels;
  for (int i = 0; i < count; ++i) {
    Pixel pixel;
    pixel.p = {any(rng), any(rng), -3.6 + any(rng)};
    pixel.n = glm::normalize(glm::dvec3(any(rng), any(rng), 0.2 + unit(rng)));
    pixel.map_coord = {any(rng), any(rng), unit(rng), 1.0 + unit(rng)};
    pixels.push_back(pixel);
  }
  return pixels;
}

TEST(Glmark2Refract, ShowsTheImageWhereTheRayLeavesTheBackFace) {
  std::mt19937 rng(20261203);
  const RefractDraw draw;
  const std::vector<Pixel> pixels = random_pixels(rng, kShadeBatch);
  const std::vector<glm::vec3> codes = shade(draw, pixels);
  for (int i = 0; i < kShadeBatch; ++i) {
    const glm::dvec3 want = expected_codes(pixels[i]);
    for (int c = 0; c < 3; ++c) {
      // Half a code for rounding, and a little for the float steps the double ones stand for.
      EXPECT_NEAR(codes[i][c], want[c], 0.6) << "pixel " << i << " channel " << c;
    }
  }
}

// Where the front refraction meets the distance map: a map that is 0 on its left half and 2 on
// its right moves the exit point, and so the image read, only for pixels whose m.x is right of
// the middle.
TEST(Glmark2Refract, ReadsTheDistanceAtTheRefractedMapCoordinate) {
  RefractDraw draw;
  std::vector<float> halves(16);
  for (int i = 0; i < 16; ++i) halves[i] = i % 4 < 2 ? 0.0f : 2.0f;
  draw.material.occlusion_map.texture = Texture::from_r32f(4, 4, halves, "halves");
  // T1 is nearly (0, 0, -1), so m.x is about MapCoord.x / w, read at m.x 0.5 + 0.5 (the bias
  // twice): m.x < 0 reads the left half and m.x > 0 the right.
  Pixel left{{0, 0, 1}, {0.2, 0.1, -3.6}, {-0.5, 0, 0.5, 1}};
  Pixel right = left;
  right.map_coord.x = 0.5;
  const std::vector<glm::vec3> codes = shade(draw, {left, right});
  // The exit point P + T1 dist, refracted out through the back normal (0, 0, 1) onto the image.
  auto red_at = [&](double dist) {
    const glm::dvec3 front = refract(glm::normalize(-left.p), {0.0, 0.0, 1.0}, 1.2);
    const glm::dvec3 out = refract(left.p + front * dist, {0.0, 0.0, 1.0}, 1.0 / 1.2);
    return std::clamp((out.x * 0.5 + 0.5) * 256.0 - 0.5, 0.0, 255.0);
  };
  // Both pixels have the same highlight: their difference is the image's alone.
  EXPECT_NEAR(codes[0].r - codes[1].r, red_at(0.0) - red_at(2.0), 1.2);
  EXPECT_GT(std::abs(codes[0].r - codes[1].r), 5.0f);  // the two are told apart
}

// The same bits on every target, with textures of random texels (a mip chain for the normals)
// and pixels anywhere, MapCoord.w near 0 included.
TEST(Glmark2Refract, IsAlikeOnEveryTarget) {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  const std::int64_t portable = portable_simd_target();
  std::mt19937 rng(7);
  std::vector<std::uint8_t> noise(std::size_t{64} * 64 * 4);
  for (auto& value : noise) value = static_cast<std::uint8_t>(rng());
  std::vector<float> depths(64 * 64);
  for (float& depth : depths) depth = static_cast<float>(rng() % 1000) / 500.0f;
  RefractDraw draw;
  draw.material.normal_map.texture = Texture::from_rgba8(64, 64, noise, false, "noise");
  draw.material.occlusion_map.texture = Texture::from_r32f(64, 64, depths, "depths");
  std::vector<Pixel> pixels = random_pixels(rng, kShadeBatch);
  pixels[3].map_coord.w = 1e-30;
  pixels[4].n = {0.0, 0.0, 0.0};
  std::vector<glm::vec3> expected;
  {
    ForcedTarget forced(portable);
    draw.kernels = shading::shading_kernels(chosen_simd_target());
    expected = shade(draw, pixels);
  }
  for (std::int64_t target : targets) {
    ForcedTarget forced(target);
    draw.kernels = shading::shading_kernels(chosen_simd_target());
    const std::vector<glm::vec3> codes = shade(draw, pixels);
    for (int i = 0; i < kShadeBatch; ++i) {
      ASSERT_EQ(std::memcmp(&codes[i], &expected[i], sizeof(glm::vec3)), 0)
          << hwy::TargetName(target) << ", pixel " << i;
    }
  }
}

// The back faces' pass stores the object-space normal: the world normal turned back by the
// model's rotation, each channel clamped to [0, 1] as an 8-bit code.
TEST(Glmark2Refract, BackFacesStoreTheObjectNormalClamped) {
  using BackNormal = bench::glmark2::RefractBackNormalShading;
  RefractDraw draw;
  const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, {0, 1, 0}));
  draw.uniforms.normal_matrix = turn;
  const glm::vec3 object_normal = glm::normalize(glm::vec3(0.6f, -0.3f, 0.74f));
  shading::VertexInput vertex{};
  vertex.normal = turn * object_normal;
  float out[BackNormal::kVaryings];
  BackNormal::vertex(vertex, draw.uniforms, out);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], object_normal[k], 1e-6f);
  alignas(64) float w[kShadeBatch] = {}, z[kShadeBatch] = {};
  alignas(64) float v[shading::kMaxVaryings][kShadeBatch] = {};
  for (int k = 0; k < 3; ++k) v[k][0] = out[k];
  alignas(64) float rgba[kShadeBatch][4];
  BackNormal::fragment_batch(draw.uniforms, {1, w, z, v}, rgba);
  EXPECT_EQ(rgba[0][0] * 255.0f, std::floor(object_normal.x * 255.0f + 0.5f));
  EXPECT_EQ(rgba[0][1], 0.0f);  // negative: clamped to 0
  EXPECT_EQ(rgba[0][2] * 255.0f, std::floor(object_normal.z * 255.0f + 0.5f));
  EXPECT_EQ(rgba[0][3], 1.0f);
}

}  // namespace
}  // namespace facet::test
