// Shadow maps as the lit models read them: a light's depth maps, written by the frame's shadow
// passes (pipeline/shadow/shadow_passes.cpp) before the color pass, and read through
// LightData::shadow by the filtered lookup of shadow_batch-inl.h, which says how much of the
// light reaches a surface point.
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

// A light's maps: one, or for a sun over a deep view a cascade of them, each fitted to a slice
// of the view's depths, nearest first, so texels near the camera are small.
inline constexpr int kMaxShadowCascades = 4;
struct ShadowMaps {
  int count = 0;
  ShadowMap maps[kMaxShadowCascades];
  // Map i serves view depths up to far_depth[i]; the last serves everything beyond too.
  float far_depth[kMaxShadowCascades] = {};
  // Map i's blend band, from view depth blend_from[i] to far_depth[i]: there a point's
  // visibility is map i's moved toward map i + 1's by t = min((depth - blend_from[i]) *
  // blend_rate[i], 1), v + (v_next - v) * t (equal visibilities stay exactly theirs), so it
  // does not jump where the slices meet. blend_rate[i] = 0: no band (the last map's).
  float blend_from[kMaxShadowCascades] = {};
  float blend_rate[kMaxShadowCascades] = {};
  glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};  // the view depth is (p - eye) . forward
};

}  // namespace facet::shading
