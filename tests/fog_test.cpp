// Fog (Lighting::fog) fades every surface toward the fog color by its view distance, once: for
// the models shaded a batch at a time, for those shaded a pixel at a time (vertex colors, flat,
// the texture-coordinate and depth views), for the wire overlay's wires and for cut-outs, at one
// sample and at four. (The fog's own formula is checked by hand in shade_batch_test.)
#include <gtest/gtest.h>

#include <string>

#include "facet/framebuffer.hpp"
#include "facet/material.hpp"
#include "facet/renderer.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 48, kHeight = 32;

// A wall facing the camera `distance` away, covering the frame, drawn with `model` into a float
// target (linear values as shaded, no tone mapping).
Framebuffer wall(ShadingModel model, float distance, const Lighting& lighting, int samples) {
  Material material;
  material.shading = model;
  material.base_color = {0.8f, 0.6f, 0.4f, 1.0f};
  material.wire_color = {0.1f, 0.9f, 0.3f, 1.0f};
  material.alpha_mode = AlphaMode::mask;  // a cut-out whose every pixel passes
  material.alpha_cutoff = 0.5f;
  const Mesh quad = soup_quad(-10.0f, -10.0f, 10.0f, 10.0f, -distance);
  RenderSettings settings;
  settings.msaa = samples;
  Renderer renderer(settings);
  Framebuffer image(kWidth, kHeight, ColorFormat::rgba32f);
  renderer.begin_frame(test_camera(kWidth, kHeight), lighting);
  renderer.draw(quad, material);
  renderer.finish(image);
  return image;
}

TEST(Fog, FadesEveryModelTowardTheFogColorOnceByDistance) {
  Lighting clear;
  clear.fog.mode = FogMode::none;
  Lighting fogged = clear;
  fogged.fog.mode = FogMode::linear;
  fogged.fog.start = 0.0f;
  fogged.fog.end = 20.0f;
  fogged.fog.color = glm::vec3(0.0f);  // black: the fogged color is the color times what is kept
  for (ShadingModel model :
       {ShadingModel::unlit, ShadingModel::lambert, ShadingModel::phong, ShadingModel::vertex_color,
        ShadingModel::flat, ShadingModel::texcoords, ShadingModel::depth,
        ShadingModel::wire_overlay}) {
    for (int samples : {1, 4}) {
      const float distance = 5.0f, kept = 1.0f - distance / 20.0f;
      const Framebuffer plain = wall(model, distance, clear, samples);
      const Framebuffer faded = wall(model, distance, fogged, samples);
      int wires = 0;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          const glm::vec4 a = plain.pixel(x, y), b = faded.pixel(x, y);
          for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(b[c], a[c] * kept, 1e-5f)
                << to_string(model) << ", " << samples << " samples, pixel " << x << "," << y
                << " channel " << c;
          }
          ASSERT_EQ(b.a, a.a);
          wires += a.g == 0.9f;
        }
      }
      if (model == ShadingModel::wire_overlay) {
        EXPECT_GT(wires, 10) << samples;
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
