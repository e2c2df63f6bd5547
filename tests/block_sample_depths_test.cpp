// The MSAA whole-block depth kernels against their definitions, on every SIMD target:
// block_samples_in_front (every sample of the block in front of the tile's depth there, NaN
// failing) and write_block_sample_depths (each sample takes the centre's depth plus its step),
// block_raster.hpp. Blocks at random places of a tile of every sample count, in front, behind
// by one sample, level with one sample, and NaN.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/raster/block_raster.hpp"
#include "pipeline/setup/setup.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

constexpr int kSide = 32;  // a 32x32 tile: the block lands at several offsets
constexpr std::ptrdiff_t kPlane = kSide * kSide;
constexpr int kBlock = pipeline::kBlockSize;

struct Case {
  int samples;
  std::vector<float> depth;  // the tile's planes
  float z[kBlock * kBlock];  // the block's depths at the pixel centres
  float sample_z[16];
  std::ptrdiff_t first;  // the block's first pixel in the tile
};

// Depths of the tile in [0.5, 1), of the block in [0, 0.25), steps within +-0.01: in front.
Case random_case(std::mt19937& rng, int samples) {
  std::uniform_real_distribution<float> far(0.5f, 1.0f), near(0.0f, 0.25f), step(-0.01f, 0.01f);
  Case c{samples, std::vector<float>(kPlane * samples), {}, {}, 0};
  for (float& d : c.depth) d = far(rng);
  for (float& z : c.z) z = near(rng);
  for (int s = 0; s < samples; ++s) c.sample_z[s] = step(rng);
  const int x = static_cast<int>(rng() % (kSide - kBlock + 1));
  const int y = static_cast<int>(rng() % (kSide - kBlock + 1));
  c.first = static_cast<std::ptrdiff_t>(y) * kSide + x;
  return c;
}

float& tile_depth(Case& c, int s, int pixel) {
  return c.depth[s * kPlane + c.first + (pixel / kBlock) * kSide + pixel % kBlock];
}

// block_samples_in_front's definition.
bool in_front_reference(Case& c) {
  for (int s = 0; s < c.samples; ++s) {
    for (int pixel = 0; pixel < kBlock * kBlock; ++pixel) {
      if (!(c.z[pixel] + c.sample_z[s] < tile_depth(c, s, pixel))) return false;
    }
  }
  return true;
}

TEST(BlockSampleDepths, TestedAndWrittenAsDefinedOnEveryTarget) {
  int in_front = 0, behind = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::RasterKernels kernels = pipeline::raster_kernels(chosen_simd_target());
    std::mt19937 rng(20261203);
    for (const int samples : {2, 4, 8, 16}) {
      for (int trial = 0; trial < 24; ++trial) {
        Case c = random_case(rng, samples);
        // One sample of one pixel behind, level, or NaN in some trials; in front in the others.
        const int s = static_cast<int>(rng() % samples);
        const int pixel = static_cast<int>(rng() % (kBlock * kBlock));
        const float in_place = c.z[pixel] + c.sample_z[s];
        switch (trial % 4) {
          case 1:
            tile_depth(c, s, pixel) = in_place - 0.001f;
            break;
          case 2:
            tile_depth(c, s, pixel) = in_place;
            break;
          case 3:
            c.z[pixel] = std::numeric_limits<float>::quiet_NaN();
            break;
        }
        const bool want = in_front_reference(c);
        ASSERT_EQ(kernels.block_samples_in_front(c.z, c.sample_z, samples, c.depth.data() + c.first,
                                                 kSide, kPlane),
                  want)
            << hwy::TargetName(target) << ", " << samples << " samples, trial " << trial;
        (want ? in_front : behind) += 1;

        std::vector<float> expected = c.depth;
        for (int k = 0; k < samples; ++k) {
          for (int p = 0; p < kBlock * kBlock; ++p) {
            expected[k * kPlane + c.first + (p / kBlock) * kSide + p % kBlock] =
                c.z[p] + c.sample_z[k];
          }
        }
        kernels.write_block_sample_depths(c.z, c.sample_z, samples, c.depth.data() + c.first, kSide,
                                          kPlane);
        for (std::size_t i = 0; i < expected.size(); ++i) {
          // Bits, so that the NaN written compares equal to the NaN expected.
          ASSERT_EQ(std::bit_cast<std::uint32_t>(c.depth[i]),
                    std::bit_cast<std::uint32_t>(expected[i]))
              << hwy::TargetName(target) << ", " << samples << " samples, entry " << i;
        }
      }
    }
  }
  EXPECT_GT(in_front, 0);
  EXPECT_GT(behind, 0);
}

}  // namespace
}  // namespace facet::test
