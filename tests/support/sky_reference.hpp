// The procedural sky's definition written out one direction at a time, as plainly as the formula
// reads, for tests: the radiance along a direction (sky_radiance) and through a pixel of the
// background (background_sky), which sky_row_test, shade_batch_test and environment_light_test
// compare the SIMD gradient (src/shading/sky_gradient-inl.h) with bit for bit. The renderer has
// the SIMD gradient alone.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "facet/light.hpp"
#include "pipeline/output/sky_row.hpp"

namespace facet::test {

// The sky's radiance along unit direction d: toward the zenith above the horizon, toward the
// ground below it (four times as steeply), square roots widening the bright band at the horizon.
inline glm::vec3 sky_radiance(const Environment& env, glm::vec3 d) {
  const glm::vec3 gradient =
      d.y >= 0.0f ? glm::mix(env.sky_horizon, env.sky_zenith, std::sqrt(d.y))
                  : glm::mix(env.sky_horizon, env.ground, std::sqrt(std::min(-d.y * 4.0f, 1.0f)));
  return gradient * env.intensity;
}

// The unit direction through pixel (x, y)'s centre: its point on the far plane, unprojected, seen
// from the eye.
inline glm::vec3 background_direction(const pipeline::SkyView& view, int x, int y) {
  const float ndc_x = (static_cast<float>(x) + 0.5f) / static_cast<float>(view.width) * 2.0f - 1.0f;
  const float ndc_y =
      1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(view.height) * 2.0f;
  const glm::vec4 far = view.inverse_view_projection * glm::vec4(ndc_x, ndc_y, 1.0f, 1.0f);
  return glm::normalize(glm::vec3(far) / far.w - view.eye);
}

// The sky seen through pixel (x, y).
inline glm::vec3 background_sky(const pipeline::SkyView& view, const Environment& env, int x,
                                int y) {
  return sky_radiance(env, background_direction(view, x, y));
}

}  // namespace facet::test
