// Distance fog (the classic darkening with distance), applied by the raster loop
// (pipeline/raster/raster.hpp) to every shaded color before it is written.
#pragma once

#include <glm/glm.hpp>

#include "facet/light.hpp"

namespace facet::shading {

// How much of the surface's color survives at this view depth, in [0, 1]. Out of line (its
// exponential is a polynomial, portable_math.hpp, shared with the SIMD batch shader). It returns a
// float rather than the fogged color: a glm::vec4 returned by value comes back in two 8-byte
// halves, and the raster loop's 16-byte reload of them would stall on store forwarding.
float fog_keep(float view_depth, const Fog& fog);

// Runtime branch on a per-frame constant (the fog mode): every pixel takes it the same way, so
// a template flag, which would double every raster loop, gains nothing (BENCHMARKS.md,
// "Per-draw constants").
inline void apply_fog(glm::vec4& color, float view_depth, const Fog& fog) {
  if (fog.mode == FogMode::none) return;
  color = {glm::mix(fog.color, glm::vec3(color), fog_keep(view_depth, fog)), color.a};
}

}  // namespace facet::shading
