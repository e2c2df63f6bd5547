// The SIMD batch sampler (shading/texel_batch.cpp) gives sample_map's bits on every SIMD target,
// for every filter, wrap mode, texture shape and transform, for pixels of one triangle and of
// several (each with its own plane slopes).
#include "shading/texel_batch.hpp"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "core/simd_target.hpp"
#include "shading/surface.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

std::shared_ptr<const Texture> random_texture(std::mt19937& rng, int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (auto& byte : rgba) byte = static_cast<std::uint8_t>(rng());
  return Texture::from_rgba8(width, height, std::move(rgba), true);
}

// A batch of random texture coordinates (some far outside [0, 1], some not finite) with the
// planes they came from: one triangle's, or (pixels of several triangles) each pixel's own
// slopes.
struct Case {
  float u[shading::kTexelBatch] = {}, v[shading::kTexelBatch] = {}, w[shading::kTexelBatch] = {};
  shading::TexelBatch batch;
  shading::Plane planes[2];
  shading::Plane inv_w;
  float slopes[shading::TexelBatch::kSlopes][shading::kTexelBatch] = {};
};
Case random_case(std::mt19937& rng, int count) {
  std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f), slope(-0.05f, 0.05f),
      depth(0.2f, 60.0f);
  Case c;
  c.batch.count = count;
  for (int j = 0; j < count; ++j) {
    c.u[j] = coordinate(rng);
    c.v[j] = coordinate(rng);
    c.w[j] = depth(rng);
  }
  if (count > 2) {
    c.u[0] = std::numeric_limits<float>::quiet_NaN();
    c.v[1] = 1e30f;
  }
  for (shading::Plane* p : {&c.planes[0], &c.planes[1], &c.inv_w}) {
    p->dx = slope(rng);
    p->dy = slope(rng);
  }
  c.inv_w.dx *= 0.01f;
  c.inv_w.dy *= 0.01f;
  using S = shading::TexelBatch;
  for (int j = 0; j < count; ++j) {
    for (int k = 0; k < S::kSlopes; ++k) {
      c.slopes[k][j] = slope(rng) * (k == S::inv_w_dx || k == S::inv_w_dy ? 0.01f : 1.0f);
    }
  }
  return c;
}

// What sample_map gives for pixel j of the batch (its derivatives as Fragment computes them,
// from its triangle's planes).
glm::vec4 scalar_sample(const TextureMap& map, const Case& c, int j) {
  shading::Fragment f;
  f.v[0] = c.batch.u[j];
  f.v[1] = c.batch.v[j];
  f.w = c.batch.w[j];
  shading::Plane planes[2] = {c.planes[0], c.planes[1]};
  shading::Plane inv_w = c.inv_w;
  if (c.batch.slopes != nullptr) {
    using S = shading::TexelBatch;
    planes[0].dx = c.slopes[S::u_dx][j], planes[0].dy = c.slopes[S::u_dy][j];
    planes[1].dx = c.slopes[S::v_dx][j], planes[1].dy = c.slopes[S::v_dy][j];
    inv_w.dx = c.slopes[S::inv_w_dx][j], inv_w.dy = c.slopes[S::inv_w_dy][j];
  }
  f.planes = planes;
  f.inv_w = &inv_w;
  return shading::sample_map(map, f, 0);
}

TEST(TexelBatch, GivesSampleMapsBitsOnEveryTarget) {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  std::mt19937 rng(20261122);
  const std::shared_ptr<const Texture> textures[] = {
      random_texture(rng, 64, 32), random_texture(rng, 24, 40), random_texture(rng, 1, 1),
      random_texture(rng, 1024, 2),  // 11 levels: more than one vector of the level table
      Texture::from_rgba32f(8, 8, std::vector<float>(8 * 8 * 4, 0.25f))};
  const glm::mat3 transforms[] = {
      glm::mat3(1.0f), glm::mat3(2.0f, 0.5f, 0.0f, -0.25f, 3.0f, 0.0f, 0.1f, 0.7f, 1.0f)};
  int compared = 0;
  for (std::int64_t target : targets) {
    ForcedTarget forced(target);
    for (const auto& texture : textures) {
      for (Filter filter : {Filter::nearest, Filter::bilinear, Filter::trilinear}) {
        for (Wrap wrap_u : {Wrap::repeat, Wrap::clamp_to_edge, Wrap::mirrored_repeat}) {
          for (Wrap wrap_v : {Wrap::repeat, Wrap::clamp_to_edge, Wrap::mirrored_repeat}) {
            for (const glm::mat3& transform : transforms) {
              TextureMap map{texture, Sampler{filter, wrap_u, wrap_v}, transform};
              Case c = random_case(rng, 1 + static_cast<int>(rng() % shading::kTexelBatch));
              c.batch.u = c.u;  // (set here: a copy of the Case would point into the old one)
              c.batch.v = c.v;
              c.batch.w = c.w;
              if (rng() % 2 == 0) c.batch.slopes = c.slopes;  // pixels of several triangles
              c.batch.planes = c.planes;
              c.batch.inv_w = &c.inv_w;
              shading::sample_batch(shading::sample_batch_kernel(chosen_simd_target()), map,
                                    c.batch);
              for (int j = 0; j < c.batch.count; ++j) {
                const glm::vec4 expected = scalar_sample(map, c, j);
                const float* texel = c.batch.rgba[j];
                const glm::vec4 got{texel[0], texel[1], texel[2], texel[3]};
                ASSERT_EQ(std::memcmp(&expected, &got, sizeof got), 0)
                    << hwy::TargetName(target) << ", " << texture->width() << "x"
                    << texture->height() << ", filter " << static_cast<int>(filter) << ", wrap "
                    << static_cast<int>(wrap_u) << "/" << static_cast<int>(wrap_v) << ", pixel "
                    << j << " at (" << c.batch.u[j] << ", " << c.batch.v[j] << ")"
                    << (c.batch.slopes ? ", own slopes" : "");
                ++compared;
              }
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace facet::test
