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

// Vertices snap to 1/256 pixel, as the main pipeline's do (pipeline/setup/fixed_point.hpp), so the
// edge functions below are exact integers: two triangles sharing an edge compute exactly
// opposite values on it. Triangles reaching beyond kLimit pixels (or NaN) are not UI and are
// skipped; within it, coordinates take 28 bits and edge products 58, inside int64.
constexpr int kSubpixel = 256;
constexpr float kLimit = 1 << 20;

struct Snapped {
  std::int64_t x, y;
};

bool snap(glm::vec2 p, Snapped& out) {
  if (!(std::abs(p.x) <= kLimit && std::abs(p.y) <= kLimit)) return false;  // NaN too
  out = {std::lrint(p.x * kSubpixel), std::lrint(p.y * kSubpixel)};
  return true;
}

// Edge a -> b of a triangle with positive area: E(p) > 0 inside (y down). A pixel centre
// exactly on an edge belongs to the triangle only for "owning" edges; two triangles sharing an
// edge walk it in opposite directions, so exactly one of them owns it (the top-left rule's
// purpose, D3D11 3.4.2.1).
struct Edge {
  Snapped a;
  std::int64_t dx, dy;
  bool owns_ties;
  Edge(Snapped from, Snapped to)
      : a(from), dx(to.x - from.x), dy(to.y - from.y), owns_ties(dy > 0 || (dy == 0 && dx > 0)) {}
  std::int64_t at(std::int64_t px, std::int64_t py) const {
    return dx * (py - a.y) - dy * (px - a.x);
  }
  bool inside(std::int64_t e) const { return e > 0 || (e == 0 && owns_ties); }
};

// floor(a / b) for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

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

// [0, 1], with NaN -> 0 (std::clamp would pass NaN on, and NaN to an integer is undefined).
float unit(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

void blend(std::uint8_t* out, glm::vec4 src) {
  float a = unit(src.a);
  for (int c = 0; c < 3; ++c) {
    float v = unit(src[c]) * a + out[c] / 255.0f * (1.0f - a);
    out[c] = static_cast<std::uint8_t>(v * 255.0f + 0.5f);
  }
  float alpha = a + out[3] / 255.0f * (1.0f - a);
  out[3] = static_cast<std::uint8_t>(alpha * 255.0f + 0.5f);
}

void draw_triangle(Framebuffer& target, const OverlayRect& clip, const Texture* texture,
                   OverlayVertex v0, OverlayVertex v1, OverlayVertex v2) {
  Snapped s0, s1, s2;
  if (!snap(v0.position, s0) || !snap(v1.position, s1) || !snap(v2.position, s2)) return;
  std::int64_t area = Edge(s0, s1).at(s2.x, s2.y);
  if (area == 0) return;  // degenerate
  if (area < 0) std::swap(v1, v2), std::swap(s1, s2), area = -area;
  const Edge e0(s1, s2), e1(s2, s0), e2(s0, s1);
  // Pixels whose centre (x + 0.5, in fixed point x * 256 + 128) lies within the bounds.
  const auto first = [](std::int64_t low) {
    return floor_div(low - kSubpixel / 2 + kSubpixel - 1, kSubpixel);
  };
  const auto last = [](std::int64_t high) { return floor_div(high - kSubpixel / 2, kSubpixel); };
  const int x0 =
      static_cast<int>(std::max<std::int64_t>(first(std::min({s0.x, s1.x, s2.x})), clip.x0));
  const int y0 =
      static_cast<int>(std::max<std::int64_t>(first(std::min({s0.y, s1.y, s2.y})), clip.y0));
  const int x1 =
      static_cast<int>(std::min<std::int64_t>(last(std::max({s0.x, s1.x, s2.x})), clip.x1 - 1));
  const int y1 =
      static_cast<int>(std::min<std::int64_t>(last(std::max({s0.y, s1.y, s2.y})), clip.y1 - 1));
  const double inv_area = 1.0 / static_cast<double>(area);
  for (int y = y0; y <= y1; ++y) {
    std::uint8_t* row = target.rgba8().data() + static_cast<std::size_t>(y) * target.width() * 4;
    const std::int64_t py = std::int64_t{y} * kSubpixel + kSubpixel / 2;
    for (int x = x0; x <= x1; ++x) {
      const std::int64_t px = std::int64_t{x} * kSubpixel + kSubpixel / 2;
      const std::int64_t w0 = e0.at(px, py), w1 = e1.at(px, py), w2 = e2.at(px, py);
      if (!e0.inside(w0) || !e1.inside(w1) || !e2.inside(w2)) continue;
      // Relative to v0, so an attribute equal at all three corners is exactly that value
      // (UI panels are mostly flat colors; a sum of three weights can miss 1 by a rounding).
      const float b1 = static_cast<float>(static_cast<double>(w1) * inv_area);
      const float b2 = static_cast<float>(static_cast<double>(w2) * inv_area);
      glm::vec2 uv = v0.uv + (v1.uv - v0.uv) * b1 + (v2.uv - v0.uv) * b2;
      glm::vec4 color = v0.color + (v1.color - v0.color) * b1 + (v2.color - v0.color) * b2;
      blend(row + static_cast<std::size_t>(x) * 4, color * texel(texture, uv));
    }
  }
}

}  // namespace

void draw_overlay(Framebuffer& target, const OverlayDraw& draw) {
  if (!target.has_color()) throw Error("overlay: the target is a depth-only framebuffer");
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
