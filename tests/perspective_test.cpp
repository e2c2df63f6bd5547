// Perspective-correct interpolation: a checker computed from interpolated texture
// coordinates on a receding floor matches the analytic (ray-cast) checker within one pixel.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "support/geometry.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 200;
constexpr int kHeight = 150;
constexpr float kCell = 0.5f;  // checker cell size in world units

bool checker(double u, double v) {
  return (static_cast<long>(std::floor(u / kCell)) + static_cast<long>(std::floor(v / kCell))) %
             2 !=
         0;
}

// A test shading model: passes world x/z as texture coordinates, shades the checker.
struct CheckerShading {
  static constexpr int kVaryings = 2;
  static constexpr int kNormalSlot = -1;
  static void vertex(const shading::VertexInput& in, const shading::DrawUniforms&, float* out) {
    out[0] = in.texcoord.x;
    out[1] = in.texcoord.y;
  }
  static glm::vec4 fragment(const shading::Fragment& f, const shading::DrawUniforms&) {
    return checker(f.v[0], f.v[1]) ? glm::vec4(1.0f) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  }
};

TEST(PerspectiveCorrect, CheckerOnARecedingPlaneMatchesRayCasting) {
  // Two huge triangles: floor at y = -1 from z = -1 to z = -60, texcoords = world (x, z).
  const float x0 = -40, x1 = 40, z0 = -1, z1 = -60;
  Mesh floor;
  floor.positions = {{x0, -1, z0}, {x1, -1, z0}, {x1, -1, z1}, {x0, -1, z1}};
  for (const auto& p : floor.positions) floor.texcoords.push_back({p.x, p.z});
  floor.indices = {0, 1, 2, 0, 2, 3};
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight, 60.0f, 0.1f, 100.0f));
  Material material;
  material.cull = CullMode::none;
  pipeline::draw_with_pipeline(renderer, floor, material, glm::mat4(1.0f),
                               pipeline::make_pipeline<CheckerShading>());
  renderer.finish(fb);

  auto analytic = [&](int x, int y, bool& hit) {
    glm::dvec3 dir = pixel_ray(x, y, kWidth, kHeight);
    hit = dir.y < 0;
    double t = -1.0 / dir.y;  // reach y = -1
    glm::dvec3 p = dir * t;
    hit = hit && p.z <= z0 && p.z >= z1 && p.x >= x0 && p.x <= x1;
    return checker(p.x, p.z);
  };
  int checked = 0;
  for (int y = 1; y < kHeight - 1; ++y) {
    // Only rows where a checker cell spans at least 3 pixels: beyond that it aliases.
    glm::dvec3 dir = pixel_ray(kWidth / 2, y, kWidth, kHeight);
    if (dir.y >= 0) continue;
    double depth = -1.0 / dir.y;
    double pixels_per_cell = kCell / (2.0 * depth * std::tan(3.14159265 / 6.0) / kHeight) *
                             (1.0 / depth);  // foreshortened along z
    if (pixels_per_cell < 3.0 || depth > 55.0) continue;
    for (int x = 1; x < kWidth - 1; ++x) {
      bool hit;
      bool expected = analytic(x, y, hit);
      if (!hit) continue;
      bool rendered = fb.pixel(x, y).r > 0.5f;
      bool near_match = false;
      for (int dy = -1; dy <= 1 && !near_match; ++dy) {
        for (int dx = -1; dx <= 1 && !near_match; ++dx) {
          bool h;
          near_match = analytic(x + dx, y + dy, h) == rendered && h;
        }
      }
      ASSERT_TRUE(near_match) << "pixel " << x << "," << y << " rendered " << rendered
                              << " analytic " << expected;
      ++checked;
    }
  }
  EXPECT_GT(checked, kWidth * kHeight / 4);
}

}  // namespace
}  // namespace facet::test
