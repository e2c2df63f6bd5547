// The small-triangle path's SIMD pixel search (find_box_pixels, block_raster.hpp) finds, on every
// SIMD target, exactly the pixels of a box whose centres the 64-bit edge functions put inside
// the triangle and whose depth passes the test, and interpolate_pixels then gives them the
// depths evaluate() gives (the depths the search tested, computed again): for small
// triangles over their own box, and for big ones over a small box (as when a big triangle's box
// in a tile is a few pixels at the tile's corner), where the 32-bit edge values are clamped.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <tuple>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/raster/block_raster.hpp"
#include "pipeline/setup/setup.hpp"
#include "support/forced_target.hpp"
#include "support/setup_triangle.hpp"

namespace facet::test {
namespace {

using pipeline::SetupTriangle;

struct Found {
  int x, y;
  float z;
  bool operator==(const Found&) const = default;
  bool operator<(const Found& o) const { return std::tie(y, x) < std::tie(o.y, o.x); }
};

// What find_box_pixels must find, by definition, pixel by pixel.
std::vector<Found> expected(const SetupTriangle& t, int x0, int y0, int width, int height,
                            const std::vector<float>& depth, int stride) {
  std::vector<Found> out;
  for (int y = y0; y < y0 + height; ++y) {
    for (int x = x0; x < x0 + width; ++x) {
      bool inside = true;
      for (int i = 0; i < 3; ++i) inside &= pipeline::edge_at_centre(t, i, x, y) >= 0;
      const float z = pipeline::evaluate(t.z, t.ref_x, t.ref_y, static_cast<float>(x) + 0.5f,
                                         static_cast<float>(y) + 0.5f);
      if (inside && z < depth[(y - y0) * stride + (x - x0)]) out.push_back({x, y, z});
    }
  }
  return out;
}

std::vector<Found> found(const SetupTriangle& t, int x0, int y0, int width, int height,
                         const std::vector<float>& depth, int stride) {
  constexpr int kRoom = pipeline::kBlockPixels + pipeline::kBoxSearchSlack;
  std::int16_t xs[kRoom] = {}, ys[kRoom] = {};
  alignas(64) float zs[pipeline::kBlockPixels], ws[pipeline::kBlockPixels];
  const pipeline::RasterKernels kernels = pipeline::raster_kernels(chosen_simd_target());
  const int n =
      kernels.find_box_pixels(t, x0, y0, width, height, depth.data(), stride, true, xs, ys);
  kernels.interpolate_pixels(t, nullptr, 0, 0, n, xs, ys, zs, ws, nullptr);
  std::vector<Found> out;
  for (int k = 0; k < n; ++k) out.push_back({xs[k], ys[k], zs[k]});
  std::sort(out.begin(), out.end());  // rows of boxes over eight wide come a vector at a time
  return out;
}

TEST(SmallBoxes, FindExactlyThePixelsTheEdgeFunctionsCover) {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int tried = 0, with_pixels = 0, clamped = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int n = 0; n < 3000; ++n) {
      // Half small triangles (a few pixels), half big ones (up to the guard band).
      const float size = n % 2 == 0 ? 12.0f : 12000.0f;
      float cx, cy;
      SetupTriangle t;
      if (!random_triangle(rng, size, cx, cy, t)) continue;
      // A box of at most 64 pixels: the triangle's own (cut down), or one around its centre.
      std::uniform_int_distribution<int> side(1, 16);
      int width = side(rng), height = std::min(side(rng), 64 / width);
      int x0 = static_cast<int>(cx) - width / 2, y0 = static_cast<int>(cy) - height / 2;
      if (n % 2 == 0) {
        x0 = t.min_x, y0 = t.min_y;
        width = std::min(t.max_x - t.min_x + 1, 8);
        height = std::min(t.max_y - t.min_y + 1, 64 / width);
      }
      for (int i = 0; i < 3; ++i) {  // an edge value beyond 32 bits' reach: clamped
        const std::int64_t e = pipeline::edge_at_centre(t, i, x0, y0) >> pipeline::kSubpixelBits;
        clamped += e > (std::int64_t{1} << 30) || e < -(std::int64_t{1} << 30);
      }
      // A depth buffer in which some pixels are nearer than the triangle, with room for the
      // whole vectors find_box_pixels reads past each row.
      const int stride = 64;
      std::vector<float> depth(static_cast<std::size_t>(height) * stride + pipeline::kDepthSlack);
      for (float& d : depth) d = unit(rng) < 0.2f ? 0.0f : 1.0f;
      const std::vector<Found> want = expected(t, x0, y0, width, height, depth, stride);
      ASSERT_EQ(found(t, x0, y0, width, height, depth, stride), want)
          << hwy::TargetName(target) << ", triangle " << n;
      ++tried;
      with_pixels += !want.empty();
    }
  }
  // The cases above must have happened (and often found pixels), or the test proves nothing.
  EXPECT_GT(tried, 3000);
  EXPECT_GT(with_pixels, tried / 4);
  EXPECT_GT(clamped, 500);
}

// The depth-only form of the search (write_box_depths, for the shadow passes' casters) writes
// each pixel find_box_pixels would find its depth, evaluate()'s, and leaves every other entry
// of the buffer as it was (the lanes past the box, the rows' padding), on every target; over the
// box shapes the depth-only raster hands it: up to kMaxWaitingBox pixels, one row or column too.
TEST(SmallBoxes, DepthOnlySearchWritesTheDepthsOfThePixelsItFinds) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int tried = 0, written = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::RasterKernels kernels = pipeline::raster_kernels(chosen_simd_target());
    for (int n = 0; n < 2000; ++n) {
      const float size = n % 2 == 0 ? 12.0f : 12000.0f;
      float cx, cy;
      SetupTriangle t;
      if (!random_triangle(rng, size, cx, cy, t)) continue;
      std::uniform_int_distribution<int> side(1, 16);
      int width = side(rng), height = std::min(side(rng), 56 / width);
      if (n % 7 == 0) width = 56, height = 1;
      if (n % 7 == 1) width = 1, height = 56;
      const int x0 = static_cast<int>(cx) - width / 2, y0 = static_cast<int>(cy) - height / 2;
      const int stride = 64;
      std::vector<float> depth(static_cast<std::size_t>(height) * stride + pipeline::kDepthSlack);
      for (float& d : depth) d = unit(rng) < 0.2f ? 0.0f : 1.0f;
      const std::vector<Found> pixels = expected(t, x0, y0, width, height, depth, stride);
      std::vector<float> want = depth;
      for (const Found& f : pixels) want[(f.y - y0) * stride + (f.x - x0)] = f.z;
      const int count = kernels.write_box_depths(t, x0, y0, width, height, depth.data(), stride);
      ASSERT_EQ(depth, want) << hwy::TargetName(target) << ", triangle " << n;
      ASSERT_EQ(count, static_cast<int>(pixels.size())) << hwy::TargetName(target);
      ++tried;
      written += count > 0;
    }
  }
  EXPECT_GT(tried, 2000);
  EXPECT_GT(written, tried / 4);
}

// interpolate_runs (the waiting pixels' interpolation, one call a batch) gives each run's pixels
// what interpolate_pixels gives them run by run, bits and all, on every target: small triangles'
// pixels packed one run after another, with varying planes of their own.
TEST(SmallBoxes, InterpolatingRunsIsInterpolatingEachRun) {
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<float> any(-4.0f, 4.0f);
  constexpr int kVaryings = 5, kRoom = pipeline::kBlockPixels + pipeline::kBoxSearchSlack;
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::RasterKernels kernels = pipeline::raster_kernels(chosen_simd_target());
    for (int batch = 0; batch < 200; ++batch) {
      std::vector<SetupTriangle> triangles;
      std::vector<pipeline::Plane> planes;
      std::vector<pipeline::InterpolationRun> runs;
      std::int16_t xs[kRoom] = {}, ys[kRoom] = {};
      int count = 0;
      triangles.reserve(pipeline::kBlockPixels);  // runs point into it
      while (count < pipeline::kBlockPixels - 16) {
        float cx, cy;
        SetupTriangle t;
        if (!random_triangle(rng, 12.0f, cx, cy, t)) continue;
        t.varying_planes = static_cast<std::uint32_t>(planes.size());
        for (int k = 0; k < kVaryings; ++k) planes.push_back({any(rng), any(rng), any(rng)});
        const int width = std::min(t.max_x - t.min_x + 1, 4);
        const int height = std::min(t.max_y - t.min_y + 1, 4);
        const int n = std::min(width * height, pipeline::kBlockPixels - 16 - count);
        for (int k = 0; k < n; ++k) {
          xs[count + k] = static_cast<std::int16_t>(t.min_x + k % width);
          ys[count + k] = static_cast<std::int16_t>(t.min_y + k / width);
        }
        triangles.push_back(t);
        runs.push_back({&triangles.back(), n});
        count += n;
      }
      alignas(64) float z[pipeline::kBlockPixels], w[pipeline::kBlockPixels];
      alignas(64) float v[kVaryings][pipeline::kBlockPixels];
      alignas(64) float want_z[pipeline::kBlockPixels], want_w[pipeline::kBlockPixels];
      alignas(64) float want_v[kVaryings][pipeline::kBlockPixels];
      kernels.interpolate_runs(runs.data(), static_cast<int>(runs.size()), planes.data(), kVaryings,
                               xs, ys, z, w, v);
      int first = 0;
      for (const pipeline::InterpolationRun& run : runs) {
        kernels.interpolate_pixels(*run.triangle, planes.data() + run.triangle->varying_planes,
                                   kVaryings, first, run.count, xs, ys, want_z, want_w, want_v);
        first += run.count;
      }
      for (int n = 0; n < count; ++n) {
        ASSERT_EQ(std::memcmp(&z[n], &want_z[n], 4), 0) << hwy::TargetName(target) << " " << n;
        ASSERT_EQ(std::memcmp(&w[n], &want_w[n], 4), 0) << hwy::TargetName(target) << " " << n;
        for (int k = 0; k < kVaryings; ++k) {
          ASSERT_EQ(std::memcmp(&v[k][n], &want_v[k][n], 4), 0) << hwy::TargetName(target);
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 200 * 40);
}

// The raster loops call the kernels through pointers fetched per tile (RasterKernels): each
// forced target gets its own, so the image tests that force every target run every target's
// kernels.
TEST(SmallBoxes, KernelPointersFollowTheChosenTarget) {
  std::vector<const void*> seen;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const auto kernel = reinterpret_cast<const void*>(
        pipeline::raster_kernels(chosen_simd_target()).find_box_pixels);
    EXPECT_EQ(std::find(seen.begin(), seen.end(), kernel), seen.end()) << hwy::TargetName(target);
    seen.push_back(kernel);
  }
  EXPECT_GT(seen.size(), 1u);
}

}  // namespace
}  // namespace facet::test
