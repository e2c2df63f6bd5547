// The SIMD culling of triangle runs (cull_batch.hpp) keeps, on every SIMD target, exactly the
// triangles the definition keeps, in order: finite positions, not all three vertices outside
// one frustum plane, non-zero orientation in homogeneous coordinates (homogeneous_orientation,
// in double), and a facing the draw does not cull.
#include "pipeline/geometry/cull_batch.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/primitive.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

constexpr unsigned kFrustumCodes = (1u << pipeline::kClipPlaneCount) - 1;

struct Survivor {
  std::uint32_t i0, i1, i2, codes;
  bool front_facing;
  bool operator==(const Survivor&) const = default;
};

std::vector<Survivor> expected(const std::vector<pipeline::ProjectedVertex>& p,
                               const std::uint32_t* indices, int count, bool culls_front,
                               bool culls_back) {
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
    out.push_back({i[0], i[1], i[2], any, front});
  }
  return out;
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
        ASSERT_EQ(got.count, static_cast<int>(want.size()));
        for (int k = 0; k < got.count; ++k) {
          EXPECT_EQ(
              (Survivor{got.i0[k], got.i1[k], got.i2[k], got.codes[k], got.front_facing[k] != 0}),
              want[k])
              << "survivor " << k;
        }
        if (count == pipeline::kCullBatch && mode == 2) {
          EXPECT_GT(got.count, count / 4);  // the run has both survivors
          EXPECT_LT(got.count, count);      // and culled triangles
        }
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
