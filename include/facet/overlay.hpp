// Overlay: 2D triangles in pixel space drawn over a finished frame, for user interfaces (the
// viewer's Dear ImGui panels), text and HUDs — textured, vertex-colored, alpha blended, clipped.
#pragma once

#include <climits>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <span>

#include "facet/framebuffer.hpp"
#include "facet/texture.hpp"

namespace facet {

struct OverlayVertex {
  glm::vec2 position;  // pixels: (0, 0) is the image's top-left corner, y grows down
  glm::vec2 uv;        // (0, 0) is the texture's top-left texel corner, (1, 1) its bottom-right
  glm::vec4 color;     // display RGBA in [0, 1]: sRGB-encoded color, straight alpha
};

// Pixels [x0, x1) x [y0, y1); the default is the whole image.
struct OverlayRect {
  int x0 = 0, y0 = 0;
  int x1 = INT_MAX, y1 = INT_MAX;
};

// One batch of triangles sharing a texture and a clip rectangle (a UI toolkit's draw command).
struct OverlayDraw {
  std::span<const OverlayVertex> vertices;
  std::span<const std::uint32_t> indices;  // a triangle list; either winding is drawn
  const Texture* texture = nullptr;        // rgba8, sampled nearest from level 0; null: white
  OverlayRect scissor;                     // only pixels inside it are written
};

// Draws `draw` over an rgba8_srgb framebuffer in submission order: a pixel is covered when its
// centre is inside a triangle (edges shared by two triangles belong to exactly one), its color
// is vertex color x texel, blended "over" with straight alpha in the stored (sRGB) encoding —
// as UI toolkits expect, so colors match what they were designed on. Depth is neither tested
// nor written. Vertices snap to 1/256 pixel; a triangle with a vertex more than a million
// pixels from the origin, or NaN, is skipped. One thread, no allocation. Throws facet::Error
// for an rgba32f target, an rgba32f texture or an index out of range.
void draw_overlay(Framebuffer& target, const OverlayDraw& draw);

}  // namespace facet
