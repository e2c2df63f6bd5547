// Distance fog (the classic darkening with distance), applied by the raster loop
// (pipeline/raster.hpp) to every shaded color before it is written.
#pragma once

#include <glm/vec4.hpp>

#include "facet/light.hpp"

namespace facet::shading {

// The fogged color; out of line, so the raster loop stays small for the common no-fog case.
glm::vec4 fogged(glm::vec4 color, float view_depth, const Fog& fog);

// A per-draw constant decides the mode, so this branch is perfectly predicted; a template
// flag would double every raster loop.
inline glm::vec4 apply_fog(glm::vec4 color, float view_depth, const Fog& fog) {
  return fog.mode == FogMode::none ? color : fogged(color, view_depth, fog);
}

}  // namespace facet::shading
