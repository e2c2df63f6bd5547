// Distance fog (see fog.hpp).
#include "shading/fog.hpp"

#include <algorithm>

#include "core/portable_math.hpp"

namespace facet::shading {

float fog_keep(float view_depth, const Fog& fog) {
  const float keep = fog.mode == FogMode::linear
                         ? (fog.end - view_depth) / std::max(fog.end - fog.start, 1e-6f)
                         : portable_exp(-fog.density * view_depth);
  return std::clamp(keep, 0.0f, 1.0f);
}

}  // namespace facet::shading
