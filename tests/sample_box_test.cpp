// The MSAA box searches (find_box_samples for triangles whose edges fit 32 bits, and
// find_box_samples_wide, in doubles, for the others; block_raster.hpp) find, on every SIMD
// target, exactly the pixels with a sample the 64-bit edge functions put inside the triangle and
// whose depth passes the test, each with those samples' bits: for small triangles over their own
// box and for big ones (edges up to the guard band) over a box in them, at every sample count;
// and find_box_samples, asked to, writes the depths of the samples it finds and no other.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <tuple>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/raster/sample_steps.hpp"
#include "support/forced_target.hpp"
#include "support/setup_triangle.hpp"

namespace facet::test {
namespace {

using pipeline::SetupTriangle;

struct Found {
  int x, y;
  unsigned mask;
  bool operator==(const Found&) const = default;
  bool operator<(const Found& o) const { return std::tie(y, x) < std::tie(o.y, o.x); }
};

// The tile of the box (its own buffers): `samples` depth planes holding depths around the
// triangle's at each pixel centre, within its samples' spread, so that some of a pixel's samples
// pass the depth test and others do not.
struct Tile {
  static constexpr int kStride = 64;
  std::vector<float> depth;
  pipeline::TileContext context;
  Tile(const SetupTriangle& t, const pipeline::SampleSteps& steps, int x0, int y0, int width,
       int height, int samples, std::mt19937& rng) {
    const std::ptrdiff_t plane = static_cast<std::ptrdiff_t>(height) * kStride;
    depth.resize(plane * samples + pipeline::kDepthSlack, 1.0f);
    const float spread = std::max(-steps.depth.min, steps.depth.max) + 1e-6f;
    std::uniform_real_distribution<float> around(-spread, spread);
    for (int s = 0; s < samples; ++s) {
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          const float z = pipeline::evaluate(t.z, t.ref_x, t.ref_y, x0 + x + 0.5f, y0 + y + 0.5f);
          depth[s * plane + y * kStride + x] = z + around(rng);
        }
      }
    }
    context.x0 = x0, context.y0 = y0;
    context.stride = kStride;
    context.depth = depth.data();
    context.samples = samples;
    context.sample_plane = plane;
  }
};

// What the search must find, by definition, sample by sample.
std::vector<Found> expected(const SetupTriangle& t, const float* sample_z, const Tile& tile, int x0,
                            int y0, int width, int height) {
  std::vector<Found> out;
  for (int y = y0; y < y0 + height; ++y) {
    const float z_row = pipeline::evaluate_row(t.z, t.ref_y, static_cast<float>(y) + 0.5f);
    for (int x = x0; x < x0 + width; ++x) {
      const float z = pipeline::evaluate_in_row(z_row, t.z, t.ref_x, static_cast<float>(x) + 0.5f);
      unsigned mask = 0;
      for (int s = 0; s < tile.context.samples; ++s) {
        bool inside = true;
        // The sample's offset from the standard pattern, in fixed point.
        const pipeline::SampleOffset offset = pipeline::sample_pattern(tile.context.samples)[s];
        for (int i = 0; i < 3; ++i) {
          const std::int64_t step = std::int64_t{t.a[i]} * offset.x * pipeline::kSampleUnit +
                                    std::int64_t{t.b[i]} * offset.y * pipeline::kSampleUnit;
          inside &= pipeline::edge_at_centre(t, i, x, y) + step >= 0;
        }
        const float stored =
            tile.depth[s * tile.context.sample_plane + (y - y0) * Tile::kStride + (x - x0)];
        if (inside && z + sample_z[s] < stored) mask |= 1u << s;
      }
      if (mask != 0) out.push_back({x, y, mask});
    }
  }
  return out;
}

std::vector<Found> found(const SetupTriangle& t, const pipeline::SampleSteps& steps,
                         const float* sample_z, const Tile& tile, int x0, int y0, int width,
                         int height, bool write_depth = false) {
  pipeline::SampleBoxSearch search = pipeline::sample_box_search<true>(
      tile.context, t, steps, sample_z, x0, y0, x0 + width - 1, y0 + height - 1);
  search.write_depth = write_depth;
  constexpr int kRoom = pipeline::kBlockPixels + pipeline::kBoxSearchSlack;
  std::int16_t xs[kRoom] = {}, ys[kRoom] = {};
  std::uint16_t masks[kRoom] = {};
  const pipeline::RasterKernels kernels = pipeline::raster_kernels(chosen_simd_target());
  const int n = (steps.fits_32_bits ? kernels.find_box_samples : kernels.find_box_samples_wide)(
      search, xs, ys, masks);
  std::vector<Found> out;
  for (int k = 0; k < n; ++k) out.push_back({xs[k], ys[k], masks[k]});
  std::sort(out.begin(), out.end());  // boxes over a vector wide come a vector of columns at a time
  return out;
}

TEST(SampleBoxes, FindExactlyTheSamplesTheEdgeFunctionsCover) {
  std::mt19937 rng(20261203);
  int tried = 0, with_pixels = 0, wide = 0, partly_in_front = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int n = 0; n < 2000; ++n) {
      const int samples = 2 << (n % 4);  // 2, 4, 8, 16
      // Small triangles (a few pixels), and big ones (edges up to the guard band).
      const float size = n % 3 == 0 ? 12.0f : (n % 3 == 1 ? 900.0f : 12000.0f);
      float cx, cy;
      SetupTriangle t;
      if (!random_triangle(rng, size, cx, cy, t)) continue;
      std::uniform_int_distribution<int> side(1, 16);
      const int width = side(rng), height = std::min(side(rng), 64 / width);
      const int x0 = static_cast<int>(cx) - width / 2, y0 = static_cast<int>(cy) - height / 2;
      float sample_z[pipeline::kMaxSamples];
      const pipeline::SampleSteps steps(t, samples, sample_z);
      const Tile tile(t, steps, x0, y0, width, height, samples, rng);
      const std::vector<Found> want = expected(t, sample_z, tile, x0, y0, width, height);
      ASSERT_EQ(found(t, steps, sample_z, tile, x0, y0, width, height), want)
          << hwy::TargetName(target) << ", triangle " << n << ", " << samples << " samples"
          << (steps.fits_32_bits ? "" : ", wide");
      ++tried;
      with_pixels += !want.empty();
      for (const Found& f : want) partly_in_front += f.mask != (1u << samples) - 1;
      wide += !steps.fits_32_bits;
    }
  }
  // The cases above must have happened (and often found pixels), or the test proves nothing.
  EXPECT_GT(tried, 2000);
  EXPECT_GT(with_pixels, tried / 4);
  EXPECT_GT(partly_in_front, tried);  // pixels with samples on both sides of the depth test
  EXPECT_GT(wide, tried / 4);
  EXPECT_LT(wide, tried * 3 / 4);
}

TEST(SampleBoxes, WriteTheDepthsOfTheSamplesFoundOnly) {
  std::mt19937 rng(20261204);
  int tried = 0, written = 0, partly_in_front = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int n = 0; n < 1000; ++n) {
      const int samples = 2 << (n % 4);  // 2, 4, 8, 16
      float cx, cy;
      SetupTriangle t;
      if (!random_triangle(rng, n % 2 == 0 ? 12.0f : 900.0f, cx, cy, t)) continue;
      std::uniform_int_distribution<int> side(1, 16);
      const int width = side(rng), height = std::min(side(rng), 64 / width);
      const int x0 = static_cast<int>(cx) - width / 2, y0 = static_cast<int>(cy) - height / 2;
      float sample_z[pipeline::kMaxSamples];
      const pipeline::SampleSteps steps(t, samples, sample_z);
      if (!steps.fits_32_bits) continue;  // only find_box_samples writes depths
      Tile tile(t, steps, x0, y0, width, height, samples, rng);
      const std::vector<Found> want = expected(t, sample_z, tile, x0, y0, width, height);
      std::vector<float> depth = tile.depth;  // what the search must leave
      const std::ptrdiff_t plane = tile.context.sample_plane;
      for (const Found& f : want) {
        const float z_row = pipeline::evaluate_row(t.z, t.ref_y, static_cast<float>(f.y) + 0.5f);
        const float z =
            pipeline::evaluate_in_row(z_row, t.z, t.ref_x, static_cast<float>(f.x) + 0.5f);
        for (int s = 0; s < samples; ++s) {
          if ((f.mask >> s & 1u) == 0) continue;
          depth[s * plane + (f.y - y0) * Tile::kStride + (f.x - x0)] = z + sample_z[s];
          ++written;
        }
        partly_in_front += f.mask != (1u << samples) - 1;
      }
      ASSERT_EQ(found(t, steps, sample_z, tile, x0, y0, width, height, true), want)
          << hwy::TargetName(target) << ", triangle " << n << ", " << samples << " samples";
      ASSERT_EQ(tile.depth, depth)
          << hwy::TargetName(target) << ", triangle " << n << ", " << samples << " samples";
      ++tried;
    }
  }
  EXPECT_GT(tried, 1000);
  EXPECT_GT(written, tried);
  EXPECT_GT(partly_in_front, tried / 4);  // samples left as they were beside samples written
}

}  // namespace
}  // namespace facet::test
