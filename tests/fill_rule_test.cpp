// Fill rule: shared edges are covered exactly once — no gaps, no double hits — checked by
// counting how many triangles cover each pixel centre.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "facet/procedural.hpp"
#include "support/geometry.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr double kDistance = 2.0;

// A grid of quads spanning more than the screen, interior vertices jittered so edges run at
// every slope and sub-pixel offset. Vertices are shared (indexed), as in a real mesh.
Mesh jittered_grid(int cells_x, int cells_y, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);  // small enough never to fold
  Mesh mesh;
  double cell_w = (kWidth + 20.0) / cells_x, cell_h = (kHeight + 20.0) / cells_y;
  for (int j = 0; j <= cells_y; ++j) {
    for (int i = 0; i <= cells_x; ++i) {
      bool interior = i > 0 && j > 0 && i < cells_x && j < cells_y;
      double sx = -10.0 + (i + (interior ? jitter(rng) : 0.0)) * cell_w;
      double sy = -10.0 + (j + (interior ? jitter(rng) : 0.0)) * cell_h;
      mesh.positions.push_back(at_pixel(sx, sy, kWidth, kHeight, kDistance));
    }
  }
  for (int j = 0; j < cells_y; ++j) {
    for (int i = 0; i < cells_x; ++i) {
      std::uint32_t a = j * (cells_x + 1) + i, b = a + 1, c = a + cells_x + 1, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  }
  return mesh;
}

TEST(FillRule, TessellatedGridCoversEveryPixelExactlyOnce) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    Mesh grid = jittered_grid(17 + seed, 11 + seed, seed);
    auto counts =
        coverage_counts({&grid}, test_camera(kWidth, kHeight), kWidth, kHeight, CullMode::back);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        ASSERT_EQ(counts[y * kWidth + x], 1) << "pixel " << x << "," << y << " seed " << seed;
      }
    }
  }
}

// A fan of 64 triangles around (cx, cy) with the rim on a circle of radius r (pixels).
Mesh fan(double cx, double cy, double r, double phase) {
  Mesh mesh;
  mesh.positions.push_back(at_pixel(cx, cy, kWidth, kHeight, kDistance));
  for (int k = 0; k < 64; ++k) {
    double angle = phase + k * 2.0 * 3.14159265358979323846 / 64.0;
    mesh.positions.push_back(
        at_pixel(cx + r * std::cos(angle), cy + r * std::sin(angle), kWidth, kHeight, kDistance));
  }
  for (std::uint32_t k = 0; k < 64; ++k) {
    mesh.indices.insert(mesh.indices.end(), {0, 1 + (k + 1) % 64, 1 + k});
  }
  return mesh;
}

TEST(FillRule, FanAroundOnePointCoversInsideOnceAndOutsideNever) {
  // Centres on a pixel centre, a pixel corner and arbitrary positions; phase 0 puts spokes
  // exactly along pixel rows and columns, the hardest case for the tie rule.
  const double centres[][2] = {{80.5, 60.5}, {80.0, 60.0}, {63.37, 41.81}, {100.5, 70.0}};
  for (const auto& c : centres) {
    for (double phase : {0.0, 0.1234}) {
      const double r = 40.0;
      Mesh mesh = fan(c[0], c[1], r, phase);
      for (CullMode cull : {CullMode::none, CullMode::back}) {
        auto counts = coverage_counts({&mesh}, test_camera(kWidth, kHeight), kWidth, kHeight, cull);
        int inside = 0;
        for (int y = 0; y < kHeight; ++y) {
          for (int x = 0; x < kWidth; ++x) {
            double d = std::hypot(x + 0.5 - c[0], y + 0.5 - c[1]);
            int n = counts[y * kWidth + x];
            ASSERT_LE(n, 1) << "double hit at " << x << "," << y;
            if (d < r - 1.0) {
              ASSERT_EQ(n, 1) << "gap at " << x << "," << y;
            }
            if (d > r + 1.0) {
              ASSERT_EQ(n, 0) << "stray pixel at " << x << "," << y;
            }
            inside += n;
          }
        }
        EXPECT_NEAR(inside, 3.14159 * r * r, 2 * 3.14159 * r);
      }
    }
  }
}

TEST(FillRule, CountingOutputSeesDoubleHits) {
  // The same triangle drawn twice must count 2: the counter can fail.
  Mesh mesh = fan(80.5, 60.5, 20.0, 0.0);
  auto counts = coverage_counts({&mesh, &mesh}, test_camera(kWidth, kHeight), kWidth, kHeight);
  EXPECT_EQ(counts[60 * kWidth + 80], 2);
}

}  // namespace
}  // namespace facet::test
