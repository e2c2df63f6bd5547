// The SIMD samplers give the scalar reference sampler's bits (support/texture_reference.hpp) on
// every SIMD target, for every filter, wrap mode, texture shape and storage (8-bit with and
// without the linear copy, float): the batch sampler of the shading stage
// (shading/texel_batch.cpp) for every transform, for pixels of one triangle and of several (each
// with its own plane slopes); and the lookups at given levels of detail (Texture::sample,
// core/texture_sampler.cpp).
#include "shading/texel_batch.hpp"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/simd_target.hpp"
#include "core/texture_sampler.hpp"
#include "support/forced_target.hpp"
#include "support/texture_reference.hpp"

namespace facet::test {
namespace {

std::shared_ptr<const Texture> random_texture(std::mt19937& rng, int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (auto& byte : rgba) byte = static_cast<std::uint8_t>(rng());
  return Texture::from_rgba8(width, height, std::move(rgba), true);
}

// A texture coordinate: mostly within a few repeats of the texture, one in four up to where
// texel coordinates reach 2^23 (where a repeat's remainder is hardest to get right).
float any_coordinate(std::mt19937& rng) {
  std::uniform_real_distribution<float> near(-3.0f, 3.0f), far(-9000.0f, 9000.0f);
  return rng() % 4 == 0 ? far(rng) : near(rng);
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
  std::uniform_real_distribution<float> slope(-0.05f, 0.05f), depth(0.2f, 60.0f);
  Case c;
  c.batch.count = count;
  for (int j = 0; j < count; ++j) {
    c.u[j] = any_coordinate(rng);
    c.v[j] = any_coordinate(rng);
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

// What the reference gives for pixel j of the batch: its derivatives as Fragment::ddx/ddy
// compute them, (V_x - value * W_x) * w, from its triangle's planes or its own slopes.
glm::vec4 reference_pixel(const TextureMap& map, const shading::TexelBatch& batch, int j) {
  using S = shading::TexelBatch;
  const float u = batch.u[j], v = batch.v[j], w = batch.w[j];
  float s[S::kSlopes];
  for (int k = 0; k < S::kSlopes; ++k) s[k] = batch.slope(k, j);
  const glm::vec2 dx{(s[S::u_dx] - u * s[S::inv_w_dx]) * w, (s[S::v_dx] - v * s[S::inv_w_dx]) * w};
  const glm::vec2 dy{(s[S::u_dy] - u * s[S::inv_w_dy]) * w, (s[S::v_dy] - v * s[S::inv_w_dy]) * w};
  return reference_sample_map(map, {u, v}, dx, dy);
}

// Points the case's batch at its own arrays (after any copy of the Case, whose pointers would
// lead into the old one).
void aim(Case& c) {
  c.batch.u = c.u;
  c.batch.v = c.v;
  c.batch.w = c.w;
  c.batch.planes = c.planes;
  c.batch.inv_w = &c.inv_w;
}

// The first pixel of a sampled batch whose texel is not the reference's, bit for bit, or -1.
int first_difference(const TextureMap& map, const shading::TexelBatch& batch) {
  for (int j = 0; j < batch.count; ++j) {
    const glm::vec4 expected = reference_pixel(map, batch, j);
    const float* texel = batch.rgba[j];
    const glm::vec4 got{texel[0], texel[1], texel[2], texel[3]};
    if (std::memcmp(&expected, &got, sizeof got) != 0) return j;
  }
  return -1;
}

// Textures of every shape and storage: power-of-two sides and not, one texel, more levels
// than a vector of the level table holds, levels one texel wide (a row start shifted by 0),
// float texels (HDR), one float a texel (depth), and 8-bit ones too large for the linear copy.
std::vector<std::shared_ptr<const Texture>> sample_textures(std::mt19937& rng) {
  std::vector<float> hdr(40 * 24 * 4), depth(33 * 17);
  std::uniform_real_distribution<float> radiance(0.0f, 8.0f);
  for (float& value : hdr) value = radiance(rng);
  for (float& value : depth) value = radiance(rng) / 8.0f;
  return {random_texture(rng, 64, 32),
          random_texture(rng, 24, 40),
          random_texture(rng, 1, 1),
          random_texture(rng, 3, 5),
          random_texture(rng, 1024, 2),  // 11 levels: more than one vector of the level table
          random_texture(rng, 2, 64),    // power-of-two sides, levels one texel wide and taller
          Texture::from_rgba32f(40, 24, std::move(hdr)),
          Texture::from_r32f(33, 17, std::move(depth)),
          random_texture(rng, 1030, 1020)};  // over 2^20 texels: no linear copy
}

TEST(TexelBatch, GivesTheReferencesBitsOnEveryTarget) {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  std::mt19937 rng(20261122);
  const auto textures = sample_textures(rng);
  ASSERT_EQ(textures.back()->linear_levels().texels, nullptr);
  ASSERT_NE(textures.front()->linear_levels().texels, nullptr);
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
              aim(c);
              if (rng() % 2 == 0) c.batch.slopes = c.slopes;  // pixels of several triangles
              shading::sample_batch_kernel(chosen_simd_target())(map, c.batch);
              const int j = first_difference(map, c.batch);
              ASSERT_EQ(j, -1) << hwy::TargetName(target) << ", " << texture->width() << "x"
                               << texture->height() << ", filter " << static_cast<int>(filter)
                               << ", wrap " << static_cast<int>(wrap_u) << "/"
                               << static_cast<int>(wrap_v) << ", pixel " << j << " at ("
                               << c.batch.u[j] << ", " << c.batch.v[j] << ")"
                               << (c.batch.slopes ? ", own slopes" : "");
              compared += c.batch.count;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

// Trilinear batches of one triangle whose footprints are all at most a texel skip the levels of
// detail (texel_batch.cpp's MagnifiedEverywhere): footprints of s texels along both axes, for s
// on both sides of the bound and of 1, with the texture coordinates and w varying across the
// batch as in a perspective view. A bound that let a footprint above one texel through would
// give its pixels the base level alone where the reference blends toward the next.
TEST(TexelBatch, TrilinearBatchesAtAndAroundMagnificationGiveTheReferencesBits) {
  std::mt19937 rng(20261204);
  const auto texture = random_texture(rng, 64, 32);
  ASSERT_GT(texture->level_count(), 1);
  std::uniform_real_distribution<float> coordinate(0.0f, 1.0f), spread(0.97f, 1.0f);
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (float side : {0.5f, 0.95f, 0.985f, 0.99f, 0.995f, 1.002f, 1.01f, 1.5f}) {
      for (float tilt : {0.0f, 1e-4f}) {  // 1 / w constant across the triangle, or not
        TextureMap map{texture, Sampler{Filter::trilinear, Wrap::repeat, Wrap::repeat},
                       glm::mat3(1.0f)};
        Case c;
        c.batch.count = shading::kTexelBatch;
        const float w = 2.0f;
        for (int j = 0; j < c.batch.count; ++j) {
          c.u[j] = coordinate(rng);
          c.v[j] = coordinate(rng);
          c.w[j] = w * spread(rng);  // the largest w gives the largest footprint
        }
        c.w[7] = w;
        // (U_x - u W_x) w texels at the largest w: side along x, and along y.
        c.planes[0] = {0.0f, side / (w * static_cast<float>(texture->width())), 0.0f};
        c.planes[1] = {0.0f, 0.0f, side / (w * static_cast<float>(texture->height()))};
        c.inv_w = {0.0f, tilt, -tilt};
        aim(c);
        shading::sample_batch_kernel(chosen_simd_target())(map, c.batch);
        const int j = first_difference(map, c.batch);
        ASSERT_EQ(j, -1) << hwy::TargetName(target) << ", footprint " << side << ", tilt " << tilt
                         << ", pixel " << j;
        compared += c.batch.count;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(TextureSampler, GivesTheReferencesBitsOnEveryTarget) {
  std::mt19937 rng(20261203);
  const auto textures = sample_textures(rng);
  std::uniform_real_distribution<float> level(-2.0f, 14.0f);
  constexpr int kCount = 150;  // more than one call's worth of pixels
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (const auto& texture : textures) {
      for (Filter filter : {Filter::nearest, Filter::bilinear, Filter::trilinear}) {
        for (Wrap wrap_u : {Wrap::repeat, Wrap::clamp_to_edge, Wrap::mirrored_repeat}) {
          for (Wrap wrap_v : {Wrap::repeat, Wrap::clamp_to_edge, Wrap::mirrored_repeat}) {
            const Sampler sampler{filter, wrap_u, wrap_v};
            std::vector<float> u(kCount), v(kCount), lod(kCount);
            for (int i = 0; i < kCount; ++i) {
              u[i] = any_coordinate(rng), v[i] = any_coordinate(rng), lod[i] = level(rng);
            }
            u[0] = std::numeric_limits<float>::quiet_NaN();
            v[1] = -1e30f;
            lod[2] = std::numeric_limits<float>::quiet_NaN();
            lod[3] = std::numeric_limits<float>::infinity();
            const int count = 1 + static_cast<int>(rng() % kCount);
            std::vector<float> rgba(4 * kCount, -1.0f);
            sample_at_kernel(chosen_simd_target())(*texture, sampler, u.data(), v.data(),
                                                   lod.data(), count,
                                                   reinterpret_cast<float(*)[4]>(rgba.data()));
            for (int i = 0; i < kCount; ++i) {
              const glm::vec4 expected =
                  i < count ? reference_sample(*texture, sampler, {u[i], v[i]}, lod[i])
                            : glm::vec4(-1.0f);  // past count: untouched
              const glm::vec4 got{rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]};
              ASSERT_EQ(std::memcmp(&expected, &got, sizeof got), 0)
                  << hwy::TargetName(target) << ", " << texture->width() << "x" << texture->height()
                  << ", filter " << static_cast<int>(filter) << ", wrap "
                  << static_cast<int>(wrap_u) << "/" << static_cast<int>(wrap_v) << ", lookup " << i
                  << " at (" << u[i] << ", " << v[i] << ") lod " << lod[i];
              ++compared;
            }
            {  // the public form, one lookup
              const glm::vec4 one = texture->sample(sampler, {u[5], v[5]}, lod[5]);
              const glm::vec4 expected = reference_sample(*texture, sampler, {u[5], v[5]}, lod[5]);
              ASSERT_EQ(std::memcmp(&expected, &one, sizeof one), 0);
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

}  // namespace
}  // namespace facet::test
