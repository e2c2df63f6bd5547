// The light and shadow kernels' definitions written out one point at a time, as plainly as the
// formulas read, for tests: the light arriving at a point (incident), which tests use to tell
// which points a light reaches, and the filtered shadow lookup (shadow_visibility), which
// shadow_batch_test compares the SIMD lookup (src/shading/shadow_batch-inl.h) with bit for bit.
// The renderer has the SIMD kernels alone.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "shading/shadow_map.hpp"
#include "shading/uniforms.hpp"

namespace facet::test {

using shading::kConstantBiasTexels;
using shading::kMaxSlopeTexels;
using shading::kSlopeBiasScale;
using shading::LightData;
using shading::map_slopes;
using shading::MapSlopes;
using shading::ShadowMap;
using shading::ShadowMaps;

// Direction toward the light (unit) and the radiance arriving at world position p.
struct IncidentLight {
  glm::vec3 direction;
  glm::vec3 radiance;
};

inline IncidentLight incident(const LightData& light, glm::vec3 p) {
  if (light.type == LightType::directional) return {light.to_light, light.radiance};
  glm::vec3 to_light = light.position - p;
  float distance_squared = std::max(glm::dot(to_light, to_light), 1e-8f);
  glm::vec3 direction = to_light * (1.0f / std::sqrt(distance_squared));
  // Inverse-square falloff, windowed to reach zero at the range (glTF KHR_lights_punctual).
  float attenuation = 1.0f / distance_squared;
  if (light.inv_range_squared > 0.0f) {
    float ratio = distance_squared * light.inv_range_squared;
    float window = std::clamp(1.0f - ratio * ratio, 0.0f, 1.0f);
    attenuation *= window * window;
  }
  if (light.type == LightType::spot) {
    float cos_angle = glm::dot(-direction, light.spot_direction);
    float t = (cos_angle - light.cos_outer) / std::max(light.cos_inner - light.cos_outer, 1e-4f);
    t = std::clamp(t, 0.0f, 1.0f);
    attenuation *= t * t;
  }
  return {direction, light.radiance * attenuation};
}

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

// The share of the light reaching p (normal n) from the map that serves p's view depth, in
// that map's blend band moved toward the next map's by how far into the band p is.
inline float shadow_visibility(const ShadowMaps& maps, glm::vec3 p, glm::vec3 n) {
  const float depth = glm::dot(p - maps.eye, maps.forward);
  int i = 0;
  while (i + 1 < maps.count && depth > maps.far_depth[i]) ++i;
  const float v = shadow_visibility(maps.maps[i], p, n);
  if (i + 1 == maps.count || !(maps.blend_rate[i] > 0.0f)) return v;
  const float t = std::min((depth - maps.blend_from[i]) * maps.blend_rate[i], 1.0f);
  if (!(t > 0.0f)) return v;
  return v + (shadow_visibility(maps.maps[i + 1], p, n) - v) * t;
}

}  // namespace facet::test
