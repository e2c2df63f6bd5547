// What a fragment function sees: the pixel's interpolated varyings, its view depth, and the
// screen-space derivatives of any varying (for mip selection), computed exactly from the
// triangle's plane equations rather than from neighbouring pixels.
#pragma once

#include <glm/vec4.hpp>

#include "shading/varyings.hpp"

namespace facet::shading {

struct Fragment {
  float v[kMaxVaryings];          // perspective-correct varyings
  float w = 1.0f;                 // clip w (the view depth, in perspective)
  float z = 0.0f;                 // window depth, in [0, 1]
  const Plane* planes = nullptr;  // v / w planes
  const Plane* inv_w = nullptr;   // 1 / w plane
  // The base color map's texel here, when the raster loop sampled it ahead (base_color_texel).
  glm::vec4 base_texel{0.0f};

  // d v[k] / dx in pixels. With V = v/w and W = 1/w planes, v = V/W, so by the quotient rule
  // dv/dx = (V_x - v * W_x) / W = (V_x - v * W_x) * w.
  float ddx(int k) const { return (planes[k].dx - v[k] * inv_w->dx) * w; }
  float ddy(int k) const { return (planes[k].dy - v[k] * inv_w->dy) * w; }
};

}  // namespace facet::shading
