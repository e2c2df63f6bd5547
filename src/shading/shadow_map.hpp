// Shadow maps as the lit models read them: a light's depth map, written by the frame's shadow
// passes (pipeline/shadow_passes.cpp) before the color pass, and the filtered lookup that says
// how much of a light reaches a surface point (shadow_visibility), read per pixel by the lit
// models (models.hpp, lit_models.hpp) through LightData::shadow.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace facet::shading {

// A light's map: the window depths of the light's view, size x size texels, top row first (a
// Framebuffer's depth image), 1 where nothing was drawn. The view is orthographic along a
// directional light, perspective from a spot light.
struct ShadowMap {
  // World position -> homogeneous (x, y, z, w), divided by w: x and y the continuous texel
  // coordinates (texel (i, j)'s centre at (i, j)), z the window depth as the depth pass
  // computed it. w is 1 for an orthographic view.
  glm::mat4 world_to_map{1.0f};
  const float* depth = nullptr;
  int size = 0;
};

// The receiver's depth slope across the map is at most this many times the depth of one texel
// of world distance along the light ray per texel: the slope of a surface within 6 degrees of
// grazing (tan 84 degrees), so the extrapolated depth stays bounded.
inline constexpr float kMaxSlopeTexels = 10.0f;
// The depth bias: this many texels of world distance along the light ray, plus this share of
// the receiver's depth slope per texel. The slope term absorbs the difference between the
// shading normal the slope is computed from and the triangles' own planes the map holds (smooth
// meshes); the constant, the map's rounding. Together under two texels on surfaces facing the
// light: no acne, and shadows that start within a texel or two of a contact.
inline constexpr float kConstantBiasTexels = 1.0f;
inline constexpr float kSlopeBiasScale = 0.5f;

// The share of the light reaching world position p whose unit normal is n: percentage-closer
// filtering over a 4 x 4 texel footprint, the separable tent weights (1 - fx, 1, 1, fx) of a
// 3 x 3 grid of bilinear compares, so the result moves smoothly as p moves. Each compare is
// against the receiver's own plane extended to that texel's centre (receiver-plane depth bias:
// the plane's depth slope across the map, from n and the map's local derivatives), so a plane
// never shadows itself however far the footprint reaches, plus the bias above. Outside the
// map, lit.
inline float shadow_visibility(const ShadowMap& map, glm::vec3 p, glm::vec3 n) {
  const glm::vec4 h = map.world_to_map * glm::vec4(p, 1.0f);
  if (!(h.w > 0.0f)) return 1.0f;  // behind a spot light
  const float inv_w = 1.0f / h.w;
  const glm::vec3 m = glm::vec3(h) * inv_w;
  // The derivatives of (x, y, z) with respect to world position: row k of the matrix, less
  // m_k times its w row, over w (the quotient rule; exact rows for an orthographic map).
  const glm::mat4& t = map.world_to_map;
  const glm::vec3 w_row(t[0][3], t[1][3], t[2][3]);
  const glm::vec3 grad_x = (glm::vec3(t[0][0], t[1][0], t[2][0]) - m.x * w_row) * inv_w;
  const glm::vec3 grad_y = (glm::vec3(t[0][1], t[1][1], t[2][1]) - m.y * w_row) * inv_w;
  const glm::vec3 grad_z = (glm::vec3(t[0][2], t[1][2], t[2][2]) - m.z * w_row) * inv_w;
  // Along the ray (x and y fixed: grad_x x grad_y), one texel of world distance (1 / |grad_x|),
  // in depth.
  const glm::vec3 ray = glm::cross(grad_x, grad_y);
  const float texel_depth =
      std::abs(glm::dot(grad_z, ray)) / (glm::length(ray) * glm::length(grad_x));
  // On the receiver's plane (n . e = 0) a step e of one texel in x (grad_x . e = 1,
  // grad_y . e = 0) changes z by grad_z . (grad_y x n) / det, one in y by
  // grad_z . (n x grad_x) / det (Cramer's rule).
  const float det = glm::dot(grad_x, glm::cross(grad_y, n));
  const float max_slope = kMaxSlopeTexels * texel_depth;
  float slope_x = 0.0f, slope_y = 0.0f;
  if (det != 0.0f) {
    slope_x = std::clamp(glm::dot(grad_z, glm::cross(grad_y, n)) / det, -max_slope, max_slope);
    slope_y = std::clamp(glm::dot(grad_z, glm::cross(n, grad_x)) / det, -max_slope, max_slope);
  }
  const float bias =
      texel_depth * kConstantBiasTexels + kSlopeBiasScale * (std::abs(slope_x) + std::abs(slope_y));
  const float z = m.z - bias;
  if (!(z < 1.0f)) return 1.0f;  // beyond the map's far plane (or not finite): nothing behind
  const float x0 = std::floor(m.x), y0 = std::floor(m.y);
  const float ax = m.x - x0, ay = m.y - y0;
  const float wx[4] = {1.0f - ax, 1.0f, 1.0f, ax};
  const float wy[4] = {1.0f - ay, 1.0f, 1.0f, ay};
  const int size = map.size;
  // Texel indices as floats first: a point far outside the map must not overflow an int.
  if (!(x0 >= 1.0f - static_cast<float>(size) && x0 < 2.0f * static_cast<float>(size) &&
        y0 >= 1.0f - static_cast<float>(size) && y0 < 2.0f * static_cast<float>(size))) {
    return 1.0f;
  }
  const int ix = static_cast<int>(x0) - 1, iy = static_cast<int>(y0) - 1;
  float lit = 0.0f;
  int seen = 0;  // compares that see the light: all 16 give exactly 1, none exactly 0
  for (int j = 0; j < 4; ++j) {
    const int y = iy + j;
    const float off_y = static_cast<float>(j - 1) - ay;
    float row = 0.0f;
    for (int i = 0; i < 4; ++i) {
      const int x = ix + i;
      bool sees = true;
      if (x >= 0 && x < size && y >= 0 && y < size) {
        const float off_x = static_cast<float>(i - 1) - ax;
        const float receiver = z + slope_x * off_x + slope_y * off_y;
        sees = receiver <= map.depth[static_cast<std::ptrdiff_t>(y) * size + x];
      }
      if (sees) row += wx[i], ++seen;
    }
    lit += row * wy[j];
  }
  if (seen == 16) return 1.0f;
  return seen == 0 ? 0.0f : lit * (1.0f / 9.0f);
}

}  // namespace facet::shading
