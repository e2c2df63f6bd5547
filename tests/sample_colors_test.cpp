// The MSAA color kernels against their definitions, on every SIMD target: the waiting pixels'
// color writes (write_sample_colors, block_raster.hpp) and the resolve's average
// (average_samples_row, sample_average_row.hpp). Random tiles of every sample count: split and
// whole pixels, pixels written several times in one batch, partial and full coverage.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>
#include <glm/vec4.hpp>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/output/sample_average_row.hpp"
#include "pipeline/raster/block_raster.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

constexpr int kSide = 16;  // a 16x16 tile
constexpr int kPixels = kSide * kSide;

struct Tile {
  int samples;
  std::vector<glm::vec4> color;   // sample 0 of each pixel
  std::vector<glm::vec4> others;  // samples 1 ... samples - 1, pixel by pixel
  std::vector<std::uint8_t> split;
  glm::vec4& sample(int pixel, int s) {
    return s == 0 ? color[pixel] : others[pixel * (samples - 1) + s - 1];
  }
};

Tile random_tile(std::mt19937& rng, int samples) {
  std::uniform_real_distribution<float> value(-1.0f, 2.0f);
  Tile tile{samples, std::vector<glm::vec4>(kPixels),
            std::vector<glm::vec4>(static_cast<std::size_t>(kPixels) * (samples - 1)),
            std::vector<std::uint8_t>(kPixels)};
  for (glm::vec4& c : tile.color) c = {value(rng), value(rng), value(rng), value(rng)};
  for (glm::vec4& c : tile.others) c = {value(rng), value(rng), value(rng), value(rng)};
  for (std::uint8_t& s : tile.split) s = rng() % 2;
  return tile;
}

// write_sample_colors' definition, a pixel at a time in order.
void write_reference(Tile& tile, const std::vector<glm::vec4>& colors,
                     const std::vector<std::int16_t>& xs, const std::vector<std::int16_t>& ys,
                     const std::vector<std::uint16_t>& masks) {
  const unsigned all = (1u << tile.samples) - 1;
  for (std::size_t n = 0; n < colors.size(); ++n) {
    const int pixel = ys[n] * kSide + xs[n];
    const glm::vec4 first = tile.color[pixel];
    const glm::vec4 value(colors[n].r, colors[n].g, colors[n].b, 1.0f);  // opaque surfaces
    for (int s = 0; s < tile.samples; ++s) {
      if (masks[n] >> s & 1u) {
        tile.sample(pixel, s) = value;
      } else if (!tile.split[pixel]) {
        tile.sample(pixel, s) = first;
      }
    }
    tile.split[pixel] = masks[n] != all;
  }
}

// average_samples_row's definition.
std::vector<glm::vec4> average_reference(Tile& tile, int row) {
  std::vector<glm::vec4> out(kSide);
  const float inverse = 1.0f / static_cast<float>(tile.samples);
  for (int x = 0; x < kSide; ++x) {
    const int pixel = row * kSide + x;
    glm::vec4 sum = tile.color[pixel];
    for (int s = 1; s < tile.samples; ++s) sum += tile.sample(pixel, s);
    out[x] = tile.split[pixel] ? sum * inverse : tile.color[pixel];
  }
  return out;
}

TEST(SampleColors, WrittenAsDefinedOnEveryTarget) {
  int tried = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::RasterKernels kernels = pipeline::raster_kernels(chosen_simd_target());
    std::mt19937 rng(20261203);
    for (const int samples : {2, 4, 8, 16}) {
      for (int trial = 0; trial < 20; ++trial) {
        Tile tile = random_tile(rng, samples);
        Tile want = tile;
        const int count = 1 + static_cast<int>(rng() % 64);
        std::vector<glm::vec4> colors(count);
        std::vector<std::int16_t> xs(count), ys(count);
        std::vector<std::uint16_t> masks(count);
        for (int n = 0; n < count; ++n) {
          colors[n] = {float(rng() % 7), float(rng() % 5), float(rng() % 3), 0.25f};
          xs[n] = static_cast<std::int16_t>(rng() % 4);  // few pixels: written several times
          ys[n] = static_cast<std::int16_t>(rng() % 4);
          const unsigned all = (1u << samples) - 1;
          masks[n] = static_cast<std::uint16_t>(rng() % 3 == 0 ? all : 1 + rng() % all);
        }
        write_reference(want, colors, xs, ys, masks);
        const pipeline::SampleColorWrite to{
            &tile.color[0].x, &tile.others[0].x, tile.split.data(), kSide, 0, 0, samples};
        kernels.write_sample_colors(to, reinterpret_cast<const float(*)[4]>(colors.data()),
                                    xs.data(), ys.data(), masks.data(), count);
        ASSERT_EQ(tile.color, want.color) << hwy::TargetName(target) << ", " << samples;
        ASSERT_EQ(tile.others, want.others) << hwy::TargetName(target) << ", " << samples;
        ASSERT_EQ(tile.split, want.split) << hwy::TargetName(target) << ", " << samples;
        ++tried;
      }
    }
  }
  EXPECT_GE(tried, 80);
}

TEST(SampleColors, AveragedAsDefinedOnEveryTarget) {
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::AverageSamplesRowKernel average =
        pipeline::average_samples_row_kernel(chosen_simd_target());
    std::mt19937 rng(20261204);
    for (const int samples : {2, 4, 8, 16}) {
      Tile tile = random_tile(rng, samples);
      // Rows with no split pixel, and with one (the kernel copies runs of unsplit pixels).
      for (int x = 0; x < kSide; ++x) tile.split[x] = 0, tile.split[kSide + x] = x == 11;
      for (int row = 0; row < kSide; ++row) {
        std::vector<glm::vec4> out(kSide);
        const int first = row * kSide;
        average(&tile.color[first], &tile.others[static_cast<std::size_t>(first) * (samples - 1)],
                samples, &tile.split[first], kSide, out.data());
        ASSERT_EQ(out, average_reference(tile, row)) << hwy::TargetName(target) << ", " << samples;
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
