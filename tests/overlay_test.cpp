// The 2D overlay (facet/overlay.hpp): pixel-space triangles with vertex colors, a texture,
// "over" blending in the stored encoding, scissor rectangles, and shared edges drawn once.
#include "facet/overlay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "facet/error.hpp"

namespace facet::test {
namespace {

// A w x h rectangle at (x, y) as two triangles sharing the diagonal.
struct Quad {
  std::vector<OverlayVertex> vertices;
  std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
  Quad(float x, float y, float w, float h, glm::vec4 color) {
    vertices = {{{x, y}, {0, 0}, color},
                {{x + w, y}, {1, 0}, color},
                {{x + w, y + h}, {1, 1}, color},
                {{x, y + h}, {0, 1}, color}};
  }
  OverlayDraw draw() const {
    OverlayDraw d;
    d.vertices = vertices;
    d.indices = indices;
    return d;
  }
};

Framebuffer grey_image(int w, int h) {
  Framebuffer fb(w, h);
  for (std::size_t i = 0; i < fb.rgba8().size(); i += 4) {
    fb.rgba8()[i] = fb.rgba8()[i + 1] = fb.rgba8()[i + 2] = 100;
    fb.rgba8()[i + 3] = 255;
  }
  return fb;
}

int channel(const Framebuffer& fb, int x, int y, int c) {
  return fb.rgba8()[(static_cast<std::size_t>(y) * fb.width() + x) * 4 + c];
}

TEST(Overlay, HalfTransparentQuadBlendsEveryPixelOnceIncludingTheDiagonal) {
  Framebuffer fb = grey_image(32, 32);
  Quad quad(4, 4, 20, 20, {1.0f, 0.0f, 0.0f, 0.5f});
  draw_overlay(fb, quad.draw());
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      bool inside = x >= 4 && x < 24 && y >= 4 && y < 24;
      // 255 * 0.5 + 100 * 0.5 = 177.5 -> 178 (blended twice on the diagonal it would be 216).
      ASSERT_EQ(channel(fb, x, y, 0), inside ? 178 : 100) << x << "," << y;
      ASSERT_EQ(channel(fb, x, y, 1), inside ? 50 : 100) << x << "," << y;
    }
  }
}

TEST(Overlay, ScissorLimitsThePixelsWritten) {
  Framebuffer fb = grey_image(32, 32);
  Quad quad(0, 0, 32, 32, {0.0f, 0.0f, 1.0f, 1.0f});
  OverlayDraw draw = quad.draw();
  draw.scissor = {8, 10, 16, 20};
  draw_overlay(fb, draw);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      bool inside = x >= 8 && x < 16 && y >= 10 && y < 20;
      ASSERT_EQ(channel(fb, x, y, 2), inside ? 255 : 100) << x << "," << y;
    }
  }
}

TEST(Overlay, TextureIsModulatedByVertexColorAndItsAlphaBlends) {
  // 2x1 texture: an opaque white texel and a fully transparent one (like a font atlas).
  auto texture = Texture::from_rgba8(2, 1, {255, 255, 255, 255, 255, 255, 255, 0}, false);
  Framebuffer fb = grey_image(8, 4);
  Quad quad(0, 0, 8, 4, {0.0f, 1.0f, 0.0f, 1.0f});
  OverlayDraw draw = quad.draw();
  draw.texture = texture.get();
  draw_overlay(fb, draw);
  EXPECT_EQ(channel(fb, 1, 1, 1), 255);  // left half: the white texel, tinted green
  EXPECT_EQ(channel(fb, 1, 1, 0), 0);
  EXPECT_EQ(channel(fb, 6, 1, 1), 100);  // right half: transparent, the image shows through
  EXPECT_EQ(channel(fb, 6, 1, 0), 100);
}

TEST(Overlay, FractionalQuadsBlendEveryPixelOnceAlongTheDiagonal) {
  // Vertices between pixel centres: the diagonal's edge functions must still be exact
  // opposites in the two triangles, or pixels on it would blend twice (216) or not at all.
  for (float shift : {0.0f, 0.13f, 0.37f, 0.5f, 0.71f}) {
    Framebuffer fb = grey_image(40, 32);
    const float x = 3.3f + shift, y = 4.7f - shift, w = 27.13f + shift, h = 21.91f;
    Quad quad(x, y, w, h, {1.0f, 0.0f, 0.0f, 0.5f});
    draw_overlay(fb, quad.draw());
    for (int py = 0; py < 32; ++py) {
      for (int px = 0; px < 40; ++px) {
        const float cx = px + 0.5f, cy = py + 0.5f;
        const bool inside = cx > x && cx < x + w && cy > y && cy < y + h;
        ASSERT_EQ(channel(fb, px, py, 0), inside ? 178 : 100) << px << "," << py << " " << shift;
      }
    }
  }
}

TEST(Overlay, HugeAndNanInputIsSkippedNotUndefined) {
  // Beyond a million pixels (not a user interface) and NaN: the triangles are skipped.
  Framebuffer fb = grey_image(16, 16);
  Quad huge(-1e10f, -1e10f, 3e10f, 3e10f, {1.0f, 1.0f, 1.0f, 1.0f});
  draw_overlay(fb, huge.draw());
  Quad overflowing(-1e30f, -1e30f, 3e30f, 3e30f, {1.0f, 1.0f, 1.0f, 1.0f});
  draw_overlay(fb, overflowing.draw());
  Quad nan(std::nanf(""), 0, 8, 8, {0.0f, 0.0f, 0.0f, 1.0f});
  draw_overlay(fb, nan.draw());
  EXPECT_EQ(channel(fb, 4, 4, 0), 100);
  EXPECT_EQ(channel(fb, 15, 15, 0), 100);
  // A NaN color blends as 0 (black, transparent alpha 0 leaves the image).
  Quad nan_color(0, 0, 16, 16, {std::nanf(""), 0.0f, 0.0f, 1.0f});
  draw_overlay(fb, nan_color.draw());
  EXPECT_EQ(channel(fb, 4, 4, 0), 0);
  EXPECT_EQ(channel(fb, 4, 4, 1), 0);
}

TEST(Overlay, RejectsBadIndicesAndFloatTargets) {
  Framebuffer fb = grey_image(8, 8);
  Quad quad(0, 0, 8, 8, glm::vec4(1.0f));
  quad.indices = {0, 1, 7};
  EXPECT_THROW(draw_overlay(fb, quad.draw()), Error);
  Framebuffer hdr(8, 8, ColorFormat::rgba32f);
  Quad ok(0, 0, 8, 8, glm::vec4(1.0f));
  EXPECT_THROW(draw_overlay(hdr, ok.draw()), Error);
  Framebuffer depth = Framebuffer::depth_only(8, 8);  // no color image to draw onto
  EXPECT_THROW(draw_overlay(depth, ok.draw()), Error);
}

}  // namespace
}  // namespace facet::test
