// The SIMD culling of triangle runs (cull_batch.hpp) keeps, on every SIMD target, exactly the
// triangles the definition keeps, in order: finite positions, not all three vertices outside
// one frustum plane, non-zero orientation in homogeneous coordinates (homogeneous_orientation,
// in double), and a facing the draw does not cull; and, when asked, not an empty pixel box among
// the triangles that need no clipping, as setup would find it.
#include "pipeline/geometry/cull_batch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/primitive.hpp"
#include "pipeline/setup/sample_positions.hpp"
#include "pipeline/setup/setup.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using pipeline::kFrustumCodes;

struct Survivor {
  std::uint32_t i0, i1, i2, codes;
  bool front_facing;
  bool operator==(const Survivor&) const = default;
};

// Setup's pixel box of the triangle's screen vertices (setup_batch.cpp), in a frame of
// width x height whose samples reach `reach` from a pixel's centre, holds no pixel.
bool empty_box(const pipeline::ScreenVertex* v[3], int width, int height, std::int32_t reach) {
  const std::int64_t low_x = std::min({v[0]->x, v[1]->x, v[2]->x}) - std::int64_t{reach};
  const std::int64_t high_x = std::max({v[0]->x, v[1]->x, v[2]->x}) + std::int64_t{reach};
  const std::int64_t low_y = std::min({v[0]->y, v[1]->y, v[2]->y}) - std::int64_t{reach};
  const std::int64_t high_y = std::max({v[0]->y, v[1]->y, v[2]->y}) + std::int64_t{reach};
  const int x0 = std::max(0, pipeline::first_centre_at_or_after(low_x));
  const int x1 = std::min(width - 1, pipeline::last_centre_at_or_before(high_x));
  const int y0 = std::max(0, pipeline::first_centre_at_or_after(low_y));
  const int y1 = std::min(height - 1, pipeline::last_centre_at_or_before(high_y));
  return x0 > x1 || y0 > y1;
}

// The frame whose empty pixel boxes the kernel drops (CullInput::drops_empty_boxes).
struct Boxes {
  int width = 0, height = 0;
  std::int32_t reach = 0;
};

// What the kernel keeps of `count` triangles; with boxes, setup's empty boxes are dropped too.
std::vector<Survivor> expected(const std::vector<pipeline::ProjectedVertex>& p,
                               const std::uint32_t* indices, int count, bool culls_front,
                               bool culls_back, const Boxes* boxes = nullptr) {
  std::vector<Survivor> out;
  for (int t = 0; t < count; ++t) {
    const std::uint32_t* i = indices + 3 * t;
    const unsigned any = p[i[0]].codes | p[i[1]].codes | p[i[2]].codes;
    const unsigned all = p[i[0]].codes & p[i[1]].codes & p[i[2]].codes;
    const double orientation = pipeline::homogeneous_orientation(p[i[0]], p[i[1]], p[i[2]]);
    const bool front = orientation > 0.0;
    if ((any & pipeline::kNotFinite) || (all & kFrustumCodes) || orientation == 0.0 ||
        (front ? culls_front : culls_back)) {
      continue;
    }
    const pipeline::ScreenVertex* screen[3] = {&p[i[0]].screen, &p[i[1]].screen, &p[i[2]].screen};
    if (boxes && pipeline::planes_to_clip(any) == 0 &&
        empty_box(screen, boxes->width, boxes->height, boxes->reach)) {
      continue;
    }
    out.push_back({i[0], i[1], i[2], any, front});
  }
  return out;
}

// The kernel's survivors are `want`, in order.
void expect_survivors(const pipeline::CullSurvivors& got, const std::vector<Survivor>& want) {
  ASSERT_EQ(got.count, static_cast<int>(want.size()));
  for (int k = 0; k < got.count; ++k) {
    EXPECT_EQ((Survivor{got.i0[k], got.i1[k], got.i2[k], got.codes[k], got.front_facing[k] != 0}),
              want[k])
        << "survivor " << k;
  }
}

TEST(CullBatch, KeepsWhatTheDefinitionKeepsOnEveryTarget) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
  const float specials[] = {0.0f,
                            -0.0f,
                            1e-30f,
                            1e30f,
                            std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
  // Vertices, some repeated and some on one line (zero orientation), some outside planes.
  std::vector<pipeline::ProjectedVertex> vertices(300);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    pipeline::ProjectedVertex& p = vertices[v];
    p.clip_x = coordinate(rng), p.clip_y = coordinate(rng), p.clip_w = coordinate(rng);
    if (rng() % 16 == 0) p.clip_x = specials[rng() % std::size(specials)];
    if (v % 10 == 9) p.clip_y = p.clip_x, p.clip_w = p.clip_x;  // on a line through the origin
    p.codes = rng() % 4 == 0 ? (1u << (rng() % pipeline::kClipPlaneCount)) : 0u;
    if (rng() % 32 == 0) p.codes |= pipeline::kNotFinite;
    p.screen = {static_cast<std::int32_t>(rng()), 0, 0.0f, 1.0f};
  }
  std::vector<std::uint32_t> indices(3 * pipeline::kCullBatch);
  for (std::uint32_t& i : indices) i = static_cast<std::uint32_t>(rng() % vertices.size());
  for (std::size_t t = 0; t < 6; ++t) indices[3 * t + 2] = indices[3 * t];  // repeated vertices
  for (std::size_t t = 6; t < 12; ++t) {  // three of the collinear vertices
    for (int k = 0; k < 3; ++k) indices[3 * t + k] = static_cast<std::uint32_t>(10 * (t + k) + 9);
  }
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::CullKernel cull = pipeline::cull_kernel(chosen_simd_target());
    for (int mode = 0; mode < 3; ++mode) {
      const bool culls_front = mode == 1, culls_back = mode == 0;
      for (int count : {1, 7, 8, 9, 100, pipeline::kCullBatch}) {
        SCOPED_TRACE(hwy::TargetName(target) + std::string(", mode ") + std::to_string(mode) +
                     ", count " + std::to_string(count));
        const std::vector<Survivor> want =
            expected(vertices, indices.data(), count, culls_front, culls_back);
        pipeline::CullSurvivors got;
        cull({indices.data(), count, vertices.data(), culls_front, culls_back}, got);
        expect_survivors(got, want);
        if (count == pipeline::kCullBatch && mode == 2) {
          EXPECT_GT(got.count, count / 4);  // the run has both survivors
          EXPECT_LT(got.count, count);      // and culled triangles
        }
      }
    }
  }
}

TEST(CullBatch, DropsWhatSetupWouldForAnEmptyPixelBox) {
  // Small triangles around a 40x30 frame, most covering no pixel centre; some vertices beyond a
  // frustum side (inside the guard band or not) or near plane, whose triangles are left to
  // clipping and setup.
  constexpr int kWidth = 40, kHeight = 30;
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::int32_t> x_at(-3 * 256, (kWidth + 3) * 256);
  std::uniform_int_distribution<std::int32_t> y_at(-3 * 256, (kHeight + 3) * 256);
  std::uniform_int_distribution<std::int32_t> jitter(-300, 300);
  std::vector<pipeline::ProjectedVertex> vertices(3 * pipeline::kCullBatch);
  for (std::size_t t = 0; t < vertices.size() / 3; ++t) {
    const std::int32_t x = x_at(rng), y = y_at(rng);
    for (std::size_t k = 0; k < 3; ++k) {
      pipeline::ProjectedVertex& p = vertices[3 * t + k];
      p.clip_x = static_cast<float>(k == 1), p.clip_y = static_cast<float>(k == 2), p.clip_w = 1;
      p.screen = {x + jitter(rng), y + jitter(rng), 0.5f, 1.0f};
      const unsigned side = 1u << (2 + rng() % 4);  // left, right, bottom or top
      switch (rng() % 16) {
        case 0:
          p.codes = side;
          break;  // inside the band
        case 1:
          p.codes = side | side << pipeline::kGuardCodeShift;
          break;  // beyond it
        case 2:
          p.codes = pipeline::kClipNear;
          break;
        default:
          p.codes = 0;
      }
    }
  }
  std::vector<std::uint32_t> indices(vertices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::CullKernel cull = pipeline::cull_kernel(chosen_simd_target());
    for (std::int32_t reach : {0, pipeline::kSampleReach}) {
      for (int count : {1, 9, pipeline::kCullBatch}) {
        SCOPED_TRACE(hwy::TargetName(target) + std::string(", reach ") + std::to_string(reach) +
                     ", count " + std::to_string(count));
        const Boxes boxes{kWidth, kHeight, reach};
        const std::vector<Survivor> want =
            expected(vertices, indices.data(), count, false, false, &boxes);
        pipeline::CullSurvivors got;
        cull({indices.data(), count, vertices.data(), false, false, false, true, kWidth, kHeight,
              reach},
             got);
        expect_survivors(got, want);
        if (count == pipeline::kCullBatch) {
          // Both kinds in the run: dropped for their box, and kept (a box with a pixel, or left
          // to clipping).
          const std::size_t unboxed =
              expected(vertices, indices.data(), count, false, false).size();
          EXPECT_LT(want.size() + 10, unboxed);
          EXPECT_GT(want.size(), unboxed / 8);
        }
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
