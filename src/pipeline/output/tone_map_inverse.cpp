// facet::inverse_tone_map (facet/color.hpp): the tone mapping curves run backwards, in double
// precision, each step of tone_map_row.cpp's curves undone in reverse order.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "facet/color.hpp"

namespace facet {
namespace {

using DVec3 = glm::dvec3;

double max_of(DVec3 c) { return std::max(c.r, std::max(c.g, c.b)); }
double min_of(DVec3 c) { return std::min(c.r, std::min(c.g, c.b)); }

DVec3 inverse_pbr_neutral(DVec3 o) {
  const double start = 0.8 - 0.04, desaturation = 0.15, d = 1.0 - start;
  o = glm::clamp(o, 0.0, 0.9999);
  DVec3 c = o;  // below the knee: the color less the offset
  const double shown_peak = max_of(o);
  if (shown_peak >= start) {
    // The mix toward grey keeps the brightest channel at the new peak: it names the old one.
    const double peak = d * d / (1.0 - shown_peak) - d + start;
    const double g = 1.0 - 1.0 / (desaturation * (peak - shown_peak) + 1.0);
    c = (o - shown_peak * g) / (1.0 - g) * (peak / shown_peak);
    // A color brighter and more saturated than the curve shows any (it desaturates what it
    // compresses): the brightest of its hue that passes below the knee instead.
    if (min_of(c) < 0.0) c = o * (start / shown_peak);
  }
  // The offset from the darkest channel after it was taken: 0.04 from 0.08 up, below that x
  // - 6.25 x^2 of the channel x before, which left 6.25 x^2.
  const double lowest = std::max(min_of(c), 0.0);
  const double offset = lowest >= 0.04 ? 0.04 : std::sqrt(lowest / 6.25) - lowest;
  return c + offset;
}

DVec3 inverse_aces(DVec3 o) {
  // glm matrices are column-major: these are the transposes of the rows written out.
  const glm::dmat3 in = glm::transpose(
      glm::dmat3(0.59719, 0.35458, 0.04823, 0.07600, 0.90834, 0.01566, 0.02840, 0.13383, 0.83777));
  const glm::dmat3 out = glm::transpose(glm::dmat3(1.60475, -0.53108, -0.07367, -0.10208, 1.10813,
                                                   -0.00605, -0.00327, -0.07276, 1.07602));
  const DVec3 fitted = glm::inverse(out) * glm::clamp(o, 0.0, 1.0);
  // Each channel's fit a / b = f solved for v: (1 - f C) v^2 + (A - f D) v - (B + f E) = 0,
  // its positive root; f stays under 1 / C, which the fit reaches only at infinity.
  constexpr double kA = 0.0245786, kB = 0.000090537, kC = 0.983729, kD = 0.4329510, kE = 0.238081;
  DVec3 v;
  for (int k = 0; k < 3; ++k) {
    const double f = std::clamp(fitted[k], 0.0, 0.9999 / kC);
    const double a = 1.0 - f * kC, b = kA - f * kD, c = -(kB + f * kE);
    v[k] = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  }
  return glm::max(glm::inverse(in) * v * 0.6, 0.0);
}

}  // namespace

glm::vec3 inverse_tone_map(ToneMapping curve, glm::vec3 display) {
  switch (curve) {
    case ToneMapping::pbr_neutral:
      return glm::vec3(inverse_pbr_neutral(DVec3(display)));
    case ToneMapping::aces:
      return glm::vec3(inverse_aces(DVec3(display)));
    default:
      return display;
  }
}

glm::vec3 fog_color_under(ToneMapping curve, glm::vec3 fog_color, float exposure_scale) {
  if (curve == ToneMapping::none) return fog_color;
  const glm::vec3 shown = glm::min(fog_color * exposure_scale, glm::vec3(1.0f));
  return inverse_tone_map(curve, shown) / exposure_scale;
}

}  // namespace facet
