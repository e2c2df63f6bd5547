// The geometry stage's SIMD kernels (vertex_pass.cpp, setup_planes.cpp) give the scalar code's
// values bit for bit on every SIMD target, including the awkward inputs: snapping ties and
// near-ties, zero and non-finite normals and positions, vertices far outside the guard band.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/vertex_pass.hpp"
#include "pipeline/reference.hpp"
#include "pipeline/setup/setup.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using pipeline::kScalarScreen;

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Random positions and normals with some special values mixed in.
std::vector<glm::vec3> awkward_vectors(std::mt19937& rng, std::size_t n) {
  std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f);
  const float specials[] = {0.0f,
                            -0.0f,
                            1e-30f,
                            1e30f,
                            -1e30f,
                            std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(),
                            0.49999997f,
                            0.5f,
                            2.5f};
  std::vector<glm::vec3> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      v[i][k] = rng() % 16 == 0 ? specials[rng() % std::size(specials)] : coordinate(rng);
    }
  }
  return v;
}

TEST(GeometrySimd, VertexPassMatchesTheScalarCodeOnEveryTarget) {
  std::mt19937 rng(7);
  const std::size_t n = 1000;
  std::vector<glm::vec3> positions = awkward_vectors(rng, n);
  std::vector<glm::vec3> normals = awkward_vectors(rng, n);
  // Screen points landing on and next to snapping ties: x such that the pixel coordinate
  // times 256 is k + 0.5 or a float step away.
  // Pixels next to the left edge (x * 256 below 1, where rounding by adding 0.5 goes wrong) and
  // a run of consecutive floats there, through snapping ties and near-ties.
  for (std::size_t i = 0; i < 128; ++i) {
    positions[i] = {std::nextafter(-2.2233334f, 0.0f) + static_cast<float>(i) * 2e-7f, 0.0f, 0.0f};
  }
  positions[200] = {0.0f, 0.0f, 2.0f};  // w = 0
  glm::mat4 mvp = glm::mat4(1.0f);
  mvp[0][0] = 0.9f, mvp[1][1] = 1.3f, mvp[2][2] = -1.02f, mvp[2][3] = -1.0f, mvp[3][2] = -0.2f;
  mvp[3][3] = 2.0f, mvp[3][0] = 0.001f;
  glm::mat3 normal_matrix(0.8f, 0.1f, -0.2f, 0.3f, 1.1f, 0.05f, -0.4f, 0.2f, 0.9f);
  const int width = 641, height = 479;
  pipeline::VertexPassInput in{positions.data(),
                               normals.data(),
                               mvp,
                               normal_matrix,
                               width,
                               height,
                               {1.0f, 1.0f},
                               pipeline::guard_band_bounds(width, height)};

  // Without and with a user clip plane (a reflection pass's), tilted so it cuts the vertices.
  for (const bool user_plane : {false, true}) {
    in.frustum.clips_user_plane = in.guard.clips_user_plane = user_plane;
    in.frustum.user_plane = in.guard.user_plane = {0.3f, -0.7f, 0.2f, 0.1f};
    for (std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
      hwy::SetSupportedTargetsForTest(target);
      for (std::size_t first = 0; first < n; first += pipeline::kVertexPass) {
        const std::size_t count = std::min(pipeline::kVertexPass, n - first);
        pipeline::VertexPass pass;
        pipeline::vertex_pass_kernel(chosen_simd_target())(in, first, count, pass);
        for (std::size_t j = 0; j < count; ++j) {
          const std::size_t i = first + j;
          const glm::vec4 clip = mvp * glm::vec4(positions[i], 1.0f);
          glm::vec3 normal = normal_matrix * normals[i];
          const float length = glm::length(normal);
          if (length > 0.0f) normal /= length;
          const std::string where = std::string(hwy::TargetName(target)) + " vertex " +
                                    std::to_string(i) + (user_plane ? ", user plane" : "");
          const float simd_normal[3] = {pass.nx[j], pass.ny[j], pass.nz[j]};
          for (int k = 0; k < 3; ++k) {
            ASSERT_TRUE(same_bits(simd_normal[k], normal[k]) ||
                        (std::isnan(simd_normal[k]) && std::isnan(normal[k])))
                << where << " normal " << k;
          }
          ASSERT_TRUE(same_bits(pass.x[j], clip.x) && same_bits(pass.y[j], clip.y) &&
                      same_bits(pass.z[j], clip.z) && same_bits(pass.w[j], clip.w))
              << where;
          const std::uint32_t codes = pipeline::outcode(clip, in.frustum) |
                                      pipeline::outcode(clip, in.guard)
                                          << pipeline::kGuardCodeShift |
                                      (std::isfinite(clip.x) && std::isfinite(clip.y) &&
                                               std::isfinite(clip.z) && std::isfinite(clip.w)
                                           ? 0u
                                           : pipeline::kNotFinite);
          ASSERT_EQ(pass.codes[j] & ~kScalarScreen, codes) << where;
          if (pass.codes[j] & kScalarScreen) continue;  // beyond the integers: never read
          const pipeline::ScreenVertex s = pipeline::to_screen(clip, width, height);
          ASSERT_EQ(pass.sx[j], s.x) << where;
          ASSERT_EQ(pass.sy[j], s.y) << where;
          ASSERT_TRUE(same_bits(pass.depth[j], s.z) || std::isnan(s.z)) << where;
          ASSERT_TRUE(same_bits(pass.inv_w[j], s.inv_w)) << where;
        }
      }
    }
  }
  hwy::SetSupportedTargetsForTest(0);
}

// The projection of clipped vertices and line ends (project_to_screen) is to_screen's on every
// target: positions across and just inside the guard band (as clipping leaves them, up to the
// largest frame) and some beyond it, in runs of every length.
TEST(GeometrySimd, ProjectionOfClippedVerticesMatchesTheDefinitionOnEveryTarget) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), depth(0.05f, 40.0f);
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (const auto& [width, height] : {std::pair{641, 479}, std::pair{8192, 8192}}) {
      const pipeline::ClipBounds guard = pipeline::guard_band_bounds(width, height);
      for (int count = 1; count <= 40; ++count) {
        std::vector<glm::vec4> clip(count);
        for (glm::vec4& c : clip) {
          const float w = depth(rng);
          // Mostly inside the guard band, some on its planes exactly.
          c = {unit(rng) * guard.gx * w, unit(rng) * guard.gy * w, unit(rng) * w, w};
          if (rng() % 8 == 0) c.x = (rng() % 2 ? guard.gx : -guard.gx) * w;
          if (rng() % 8 == 0) c.y = (rng() % 2 ? guard.gy : -guard.gy) * w;
          if (rng() % 16 == 0) c.x *= 3.0f;  // beyond the band: past 2^22 sub-pixels at 8192
        }
        std::vector<pipeline::ScreenVertex> out(count);
        pipeline::project_to_screen_kernel(chosen_simd_target())(clip.data(), count, width, height,
                                                                 out.data());
        for (int i = 0; i < count; ++i) {
          const pipeline::ScreenVertex s = pipeline::to_screen(clip[i], width, height);
          ASSERT_EQ(out[i].x, s.x) << hwy::TargetName(target) << " " << width << ", vertex " << i;
          ASSERT_EQ(out[i].y, s.y) << hwy::TargetName(target) << " " << width << ", vertex " << i;
          ASSERT_TRUE(same_bits(out[i].z, s.z)) << hwy::TargetName(target);
          ASSERT_TRUE(same_bits(out[i].inv_w, s.inv_w)) << hwy::TargetName(target);
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace facet::test
