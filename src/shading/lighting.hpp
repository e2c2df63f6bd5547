// Lights as the shading kernels read them (LightData, uniforms.hpp): directions normalized, cone
// angles as cosines. What reaches a surface point, with distance attenuation, spot cones and
// shadows, is light_batch-inl.h's.
#pragma once

#include "shading/uniforms.hpp"

namespace facet::shading {

LightData prepare_light(const Light& light);

}  // namespace facet::shading
