// Shadow maps as the lit models read them: a light's depth maps, written by the frame's shadow
// passes (pipeline/shadow/shadow_passes.cpp) before the color pass, and the filtered lookup that
// says how much of a light reaches a surface point (shadow_visibility), read per pixel by the lit
// models (models.hpp, lit_models.hpp) through LightData::shadow. The batch kernels repeat the
// lookup, a vector of points at once, bit for bit (shadow_batch-inl.h): a change here is a change
// there.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace facet::shading {

// What the receiver-plane bias needs of the map's local derivatives (grad_x, grad_y, grad_z:
// those of the texel coordinates and the window depth with respect to world position). On a
// plane of normal n, a step e of one texel in x (grad_x . e = 1, grad_y . e = 0, n . e = 0)
// changes the depth by grad_z . (grad_y x n) / grad_x . (grad_y x n) = n . slope_x / n . ray
// (Cramer's rule), one in y by n . slope_y / n . ray.
struct MapSlopes {
  glm::vec3 ray{0.0f};      // grad_x x grad_y: along the light ray (x and y fixed)
  glm::vec3 slope_x{0.0f};  // grad_z x grad_y
  glm::vec3 slope_y{0.0f};  // grad_x x grad_z
  // One texel of world distance (1 / |grad_x|) along the ray, in window depth.
  float texel_depth = 0.0f;
};
inline MapSlopes map_slopes(glm::vec3 grad_x, glm::vec3 grad_y, glm::vec3 grad_z) {
  MapSlopes m;
  m.ray = glm::cross(grad_x, grad_y);
  m.slope_x = glm::cross(grad_z, grad_y);
  m.slope_y = glm::cross(grad_x, grad_z);
  m.texel_depth = std::abs(glm::dot(grad_z, m.ray)) / (glm::length(m.ray) * glm::length(grad_x));
  return m;
}

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
  // An orthographic map's derivatives are its matrix's rows, the same everywhere: their slopes
  // are found once (make_shadow_map). A perspective map's are found per point.
  bool perspective = false;
  MapSlopes slopes;
};

inline ShadowMap make_shadow_map(const glm::mat4& world_to_map, const float* depth, int size,
                                 bool perspective) {
  ShadowMap map;
  map.world_to_map = world_to_map;
  map.depth = depth;
  map.size = size;
  map.perspective = perspective;
  const glm::mat4& t = world_to_map;
  map.slopes = map_slopes({t[0][0], t[1][0], t[2][0]}, {t[0][1], t[1][1], t[2][1]},
                          {t[0][2], t[1][2], t[2][2]});
  return map;
}

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
// MapSlopes), so a plane never shadows itself however far the footprint reaches, plus the bias
// above. Outside the map, lit.
inline float shadow_visibility(const ShadowMap& map, glm::vec3 p, glm::vec3 n) {
  const glm::vec4 h = map.world_to_map * glm::vec4(p, 1.0f);
  glm::vec3 m(h);
  MapSlopes local;
  const MapSlopes* slopes = &map.slopes;
  if (map.perspective) {
    if (!(h.w > 0.0f)) return 1.0f;  // behind the light
    const float inv_w = 1.0f / h.w;
    m *= inv_w;
    // The derivatives here: row k of the matrix less m_k times its w row, over w (the quotient
    // rule).
    const glm::mat4& t = map.world_to_map;
    const glm::vec3 w_row(t[0][3], t[1][3], t[2][3]);
    local = map_slopes((glm::vec3(t[0][0], t[1][0], t[2][0]) - m.x * w_row) * inv_w,
                       (glm::vec3(t[0][1], t[1][1], t[2][1]) - m.y * w_row) * inv_w,
                       (glm::vec3(t[0][2], t[1][2], t[2][2]) - m.z * w_row) * inv_w);
    slopes = &local;
  }
  const float det = glm::dot(n, slopes->ray);
  const float max_slope = kMaxSlopeTexels * slopes->texel_depth;
  float slope_x = 0.0f, slope_y = 0.0f;
  if (det != 0.0f) {
    const float inv_det = 1.0f / det;
    slope_x = std::clamp(glm::dot(n, slopes->slope_x) * inv_det, -max_slope, max_slope);
    slope_y = std::clamp(glm::dot(n, slopes->slope_y) * inv_det, -max_slope, max_slope);
  }
  const float bias = slopes->texel_depth * kConstantBiasTexels +
                     kSlopeBiasScale * (std::abs(slope_x) + std::abs(slope_y));
  const float z = m.z - bias;
  if (!(z < 1.0f)) return 1.0f;  // beyond the map's far plane (or not finite): nothing behind
  const float x0 = std::floor(m.x), y0 = std::floor(m.y);
  const float size = static_cast<float>(map.size);
  // Texel indices as floats first: a point far outside the map must not overflow an int.
  if (!(x0 >= 1.0f - size && x0 < 2.0f * size && y0 >= 1.0f - size && y0 < 2.0f * size)) {
    return 1.0f;
  }
  const float ax = m.x - x0, ay = m.y - y0;
  const float wx[4] = {1.0f - ax, 1.0f, 1.0f, ax};
  const float wy[4] = {1.0f - ay, 1.0f, 1.0f, ay};
  // The receiver's depth at the footprint's first texel centre, (x0 - 1, y0 - 1), less the bias.
  const float first = z - slope_x * (1.0f + ax) - slope_y * (1.0f + ay);
  const int ix = static_cast<int>(x0) - 1, iy = static_cast<int>(y0) - 1;
  const bool inside = ix >= 0 && iy >= 0 && ix + 4 <= map.size && iy + 4 <= map.size;
  float lit = 0.0f;
  int seen = 0;  // compares that see the light: all 16 give exactly 1, none exactly 0
  for (int j = 0; j < 4; ++j) {
    const int y = iy + j;
    const float row_start = first + slope_y * static_cast<float>(j);
    const std::ptrdiff_t row_index = static_cast<std::ptrdiff_t>(y) * map.size + ix;
    float row = 0.0f;
    for (int i = 0; i < 4; ++i) {
      const bool in_map = inside || (ix + i >= 0 && ix + i < map.size && y >= 0 && y < map.size);
      const bool sees =
          !in_map || row_start + slope_x * static_cast<float>(i) <= map.depth[row_index + i];
      if (sees) row += wx[i], ++seen;
    }
    lit += row * wy[j];
  }
  if (seen == 16) return 1.0f;
  return seen == 0 ? 0.0f : lit * (1.0f / 9.0f);
}

// A light's maps: one, or for a sun over a deep view a cascade of them, each fitted to a slice
// of the view's depths, nearest first, so texels near the camera are small.
inline constexpr int kMaxShadowCascades = 4;
struct ShadowMaps {
  int count = 0;
  ShadowMap maps[kMaxShadowCascades];
  // Map i serves view depths up to far_depth[i]; the last serves everything beyond too.
  float far_depth[kMaxShadowCascades] = {};
  glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};  // the view depth is (p - eye) . forward
};

// The share of the light reaching p (normal n) from the map that serves p's view depth.
inline float shadow_visibility(const ShadowMaps& maps, glm::vec3 p, glm::vec3 n) {
  const float depth = glm::dot(p - maps.eye, maps.forward);
  int i = 0;
  while (i + 1 < maps.count && depth > maps.far_depth[i]) ++i;
  return shadow_visibility(maps.maps[i], p, n);
}

}  // namespace facet::shading
