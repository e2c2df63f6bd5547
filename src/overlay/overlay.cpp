// Overlay: 2D triangles in pixel space over a finished frame (see facet/overlay.hpp). A plain
// scalar rasterizer: UI triangles are few and small, so the tiled pipeline would cost more in
// setup than it saves, and UI needs strict submission order with blending, which this gives.
#include "facet/overlay.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <string>

#include "facet/error.hpp"

namespace facet {
namespace {

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// Edge a -> b of a triangle with positive area. A pixel centre exactly on an edge belongs to
// the triangle only for "owning" edges; two triangles sharing an edge walk it in opposite
// directions, so exactly one of them owns it (the top-left rule's purpose, D3D11 3.4.2.1).
struct Edge {
  glm::vec2 a, d;
  bool owns_ties;
  Edge(glm::vec2 from, glm::vec2 to)
      : a(from), d(to - from), owns_ties(d.y > 0.0f || (d.y == 0.0f && d.x > 0.0f)) {}
  float at(glm::vec2 p) const { return cross(d, p - a); }
  bool inside(float e) const { return e > 0.0f || (e == 0.0f && owns_ties); }
};

// Texel index for a coordinate in [0, 1), clamped to the edge; compared as floats before the
// conversion, so huge or NaN coordinates (NaN fails every comparison) cannot overflow an int.
int texel_index(float coordinate, int size) {
  float t = coordinate * static_cast<float>(size);
  if (!(t >= 0.0f)) return 0;
  return t < static_cast<float>(size) ? static_cast<int>(t) : size - 1;
}

glm::vec4 texel(const Texture* texture, glm::vec2 uv) {
  if (!texture) return glm::vec4(1.0f);
  const Texture::Level& level = texture->level(0);
  int x = texel_index(uv.x, level.width);
  int y = texel_index(uv.y, level.height);
  const std::uint8_t* t = level.rgba8.data() + (static_cast<std::size_t>(y) * level.width + x) * 4;
  return glm::vec4(t[0], t[1], t[2], t[3]) / 255.0f;
}

void blend(std::uint8_t* out, glm::vec4 src) {
  float a = std::clamp(src.a, 0.0f, 1.0f);
  for (int c = 0; c < 3; ++c) {
    float v = std::clamp(src[c], 0.0f, 1.0f) * a + out[c] / 255.0f * (1.0f - a);
    out[c] = static_cast<std::uint8_t>(v * 255.0f + 0.5f);
  }
  float alpha = a + out[3] / 255.0f * (1.0f - a);
  out[3] = static_cast<std::uint8_t>(alpha * 255.0f + 0.5f);
}

void draw_triangle(Framebuffer& target, const OverlayRect& clip, const Texture* texture,
                   OverlayVertex v0, OverlayVertex v1, OverlayVertex v2) {
  float area = cross(v1.position - v0.position, v2.position - v0.position);
  if (!(std::abs(area) > 0.0f)) return;  // degenerate (or NaN)
  if (area < 0.0f) std::swap(v1, v2), area = -area;
  const Edge e0(v1.position, v2.position), e1(v2.position, v0.position),
      e2(v0.position, v1.position);
  glm::vec2 low = glm::min(v0.position, glm::min(v1.position, v2.position));
  glm::vec2 high = glm::max(v0.position, glm::max(v1.position, v2.position));
  // Pixels whose centre (x + 0.5) lies within the bounds, inside the clip rectangle; clamped
  // as floats first, so vertices far off screen cannot overflow the conversion to int.
  float fx0 = std::max(std::ceil(low.x - 0.5f), static_cast<float>(clip.x0));
  float fy0 = std::max(std::ceil(low.y - 0.5f), static_cast<float>(clip.y0));
  float fx1 = std::min(std::floor(high.x - 0.5f), static_cast<float>(clip.x1 - 1));
  float fy1 = std::min(std::floor(high.y - 0.5f), static_cast<float>(clip.y1 - 1));
  if (!(fx0 <= fx1 && fy0 <= fy1)) return;
  const int x0 = static_cast<int>(fx0), y0 = static_cast<int>(fy0);
  const int x1 = static_cast<int>(fx1), y1 = static_cast<int>(fy1);
  for (int y = y0; y <= y1; ++y) {
    std::uint8_t* row = target.rgba8().data() + static_cast<std::size_t>(y) * target.width() * 4;
    for (int x = x0; x <= x1; ++x) {
      glm::vec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      float w0 = e0.at(p), w1 = e1.at(p), w2 = e2.at(p);
      if (!e0.inside(w0) || !e1.inside(w1) || !e2.inside(w2)) continue;
      // Relative to v0, so an attribute equal at all three corners is exactly that value
      // (UI panels are mostly flat colors; a sum of three weights can miss 1 by a rounding).
      w1 /= area, w2 /= area;
      glm::vec2 uv = v0.uv + (v1.uv - v0.uv) * w1 + (v2.uv - v0.uv) * w2;
      glm::vec4 color = v0.color + (v1.color - v0.color) * w1 + (v2.color - v0.color) * w2;
      blend(row + static_cast<std::size_t>(x) * 4, color * texel(texture, uv));
    }
  }
}

}  // namespace

void draw_overlay(Framebuffer& target, const OverlayDraw& draw) {
  if (target.format() != ColorFormat::rgba8_srgb) {
    throw Error("overlay: the target must be an rgba8_srgb framebuffer");
  }
  if (draw.texture && draw.texture->format() != Texture::Format::rgba8) {
    throw Error("overlay: the texture must be rgba8");
  }
  OverlayRect clip = draw.scissor;
  clip.x0 = std::max(clip.x0, 0), clip.y0 = std::max(clip.y0, 0);
  clip.x1 = std::min(clip.x1, target.width()), clip.y1 = std::min(clip.y1, target.height());
  if (clip.x0 >= clip.x1 || clip.y0 >= clip.y1) return;
  const std::size_t count = draw.vertices.size();
  for (std::size_t i = 0; i + 2 < draw.indices.size(); i += 3) {
    std::uint32_t a = draw.indices[i], b = draw.indices[i + 1], c = draw.indices[i + 2];
    if (a >= count || b >= count || c >= count) {
      std::string message = "overlay: index ";
      message += std::to_string(std::max({a, b, c})) + " at position " + std::to_string(i);
      message += " is out of range (" + std::to_string(count) + " vertices)";
      throw Error(message);
    }
    draw_triangle(target, clip, draw.texture, draw.vertices[a], draw.vertices[b], draw.vertices[c]);
  }
}

}  // namespace facet
