// Color spaces: facet works in linear light inside (materials, lights, clear colors are linear
// RGB); colors people pick or read off the screen are sRGB. These convert (IEC 61966-2-1).
#pragma once

#include <glm/vec3.hpp>

namespace facet {

// An sRGB color with components in [0, 1] as linear RGB, and back.
glm::vec3 srgb_to_linear(glm::vec3 srgb);
glm::vec3 linear_to_srgb(glm::vec3 linear);

}  // namespace facet
