// The tile clear's fill kernels (fill_float_row, fill_color_row: fill_row.hpp) on every SIMD
// target: every count from none to past several vectors, at every offset of a vector, writes
// exactly its entries and nothing around them.
#include "pipeline/output/fill_row.hpp"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "core/simd_target.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

constexpr int kMaxCount = 70;
constexpr int kMaxOffset = 17;

TEST(FillRow, FillsExactlyItsEntriesOnEveryTarget) {
  const float untouched = -7.0f, value = 0.625f;
  const glm::vec4 color(0.1f, -0.2f, 3.0f, 1.0f);
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::FillFloatRowKernel fill_floats =
        pipeline::fill_float_row_kernel(chosen_simd_target());
    const pipeline::FillColorRowKernel fill_colors =
        pipeline::fill_color_row_kernel(chosen_simd_target());
    for (int offset = 0; offset < kMaxOffset; ++offset) {
      for (int count = 0; count <= kMaxCount; ++count) {
        std::vector<float> floats(kMaxOffset + kMaxCount + 1, untouched);
        fill_floats(floats.data() + offset, count, value);
        std::vector<glm::vec4> colors(kMaxOffset + kMaxCount + 1, glm::vec4(untouched));
        fill_colors(colors.data() + offset, count, color);
        for (int i = 0; i < static_cast<int>(floats.size()); ++i) {
          const bool inside = i >= offset && i < offset + count;
          ASSERT_EQ(floats[i], inside ? value : untouched)
              << hwy::TargetName(target) << ": " << count << " from " << offset << ", entry " << i;
          ASSERT_EQ(colors[i], inside ? color : glm::vec4(untouched))
              << hwy::TargetName(target) << ": " << count << " from " << offset << ", entry " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
