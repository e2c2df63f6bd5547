// The vertex stage's per-vertex stores (vertex_rows.hpp) write, on every SIMD target, what
// storing element by element writes, and nothing past the rows they were given: for every
// varying count and for runs that are not whole groups of eight.
#include "pipeline/geometry/vertex_rows.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using pipeline::kVertexPass;

constexpr float kCanary = -12345.0f;

TEST(VertexRows, ProjectedVerticesAreThePassesValuesOnEveryTarget) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(-100.0f, 100.0f);
  pipeline::VertexPass pass;
  for (std::size_t j = 0; j < kVertexPass; ++j) {
    pass.x[j] = value(rng), pass.y[j] = value(rng), pass.z[j] = value(rng);
    pass.w[j] = value(rng), pass.depth[j] = value(rng), pass.inv_w[j] = value(rng);
    pass.sx[j] = static_cast<std::int32_t>(rng()), pass.sy[j] = static_cast<std::int32_t>(rng());
    pass.codes[j] = static_cast<std::uint32_t>(rng()) & (pipeline::kScalarScreen | 0x1ffff);
  }
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (std::size_t count : {std::size_t{1}, std::size_t{8}, std::size_t{13}, kVertexPass}) {
      SCOPED_TRACE(hwy::TargetName(target) + std::string(", count ") + std::to_string(count));
      std::vector<pipeline::ProjectedVertex> got(count + 1);
      std::memset(got.data(), 0x5a, got.size() * sizeof(got[0]));
      const std::vector<pipeline::ProjectedVertex> untouched(got);
      pipeline::store_projected_kernel(chosen_simd_target())(pass, count, got.data());
      for (std::size_t j = 0; j < count; ++j) {
        pipeline::ProjectedVertex expected;
        expected.clip_x = pass.x[j], expected.clip_y = pass.y[j], expected.clip_w = pass.w[j];
        expected.codes = pass.codes[j] & ~pipeline::kScalarScreen;
        expected.screen = {pass.sx[j], pass.sy[j], pass.depth[j], pass.inv_w[j]};
        ASSERT_EQ(std::memcmp(&got[j], &expected, sizeof expected), 0) << "vertex " << j;
      }
      EXPECT_EQ(std::memcmp(&got[count], &untouched[count], sizeof got[count]), 0);
    }
  }
}

TEST(VertexRows, VaryingsOverWAreTheScalarProductsOnEveryTarget) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> value(-3.0f, 3.0f);
  alignas(64) float values[pipeline::kMaxVaryings][kVertexPass];
  alignas(64) float inv_w[kVertexPass];
  for (auto& row : values) {
    for (float& v : row) v = value(rng);
  }
  for (float& v : inv_w) v = value(rng);
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int varyings = 0; varyings <= pipeline::kMaxVaryings; ++varyings) {
      for (std::size_t count : {std::size_t{3}, std::size_t{8}, std::size_t{17}, kVertexPass}) {
        SCOPED_TRACE(hwy::TargetName(target) + std::string(", varyings ") +
                     std::to_string(varyings) + ", count " + std::to_string(count));
        const std::size_t floats = count * static_cast<std::size_t>(varyings);
        // Room past the rows: what the next run of vertices owns, which must stay as it is.
        std::vector<float> got(floats + 16, kCanary);
        pipeline::store_over_w_kernel(chosen_simd_target())(values, inv_w, count, varyings,
                                                            got.data());
        for (std::size_t j = 0; j < count; ++j) {
          for (int k = 0; k < varyings; ++k) {
            const float expected = values[k][j] * inv_w[j];
            ASSERT_EQ(std::memcmp(&got[j * varyings + k], &expected, sizeof expected), 0)
                << "vertex " << j << ", varying " << k;
          }
        }
        for (std::size_t i = floats; i < got.size(); ++i) ASSERT_EQ(got[i], kCanary) << i;
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
