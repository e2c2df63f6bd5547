// sRGB tables (see color.hpp) and the public conversions (facet/color.hpp; encode_srgb8 is in
// srgb_row.cpp, with the encoder).
#include "core/color.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "facet/color.hpp"

namespace facet::shading {

namespace {

// 255 * linear_to_srgb(x), in double.
double exact_code(double x) {
  return 255.0 * (x <= 0.0031308 ? x * 12.92 : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055);
}

}  // namespace

SrgbTables::SrgbTables() {
  for (int i = 0; i < 256; ++i) {
    decode[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
    thresholds[i] = i == 0 ? 0.0f : srgb_to_linear((static_cast<float>(i) - 0.5f) / 255.0f);
  }
  thresholds[256] = 2.0f;
  encode_lines.fill(0);
  for (int line = 0; line < kEncodeLines; ++line) {
    // The exact curve at the middle of each t's floats, the chord from the first t to the last,
    // and the line: the chord moved to halve the largest distances above and below it.
    double curve[256];
    for (int t = 0; t < 256; ++t) {
      const std::uint32_t first = kEncodeBase +
                                  (static_cast<std::uint32_t>(line) << kEncodeLineShift) +
                                  (static_cast<std::uint32_t>(t) << kEncodePointShift);
      const double low = std::bit_cast<float>(first);
      const double high = std::bit_cast<float>(first + (1u << kEncodePointShift) - 1);
      curve[t] = exact_code(0.5 * (low + high));
    }
    const double slope = (curve[255] - curve[0]) / 255.0;
    double above = 0.0, below = 0.0;
    for (int t = 0; t < 256; ++t) {
      const double distance = curve[t] - (curve[0] + slope * t);
      above = std::max(above, distance), below = std::min(below, distance);
    }
    const double start = curve[0] + 0.5 * (above + below);
    const auto bias = static_cast<std::uint32_t>(std::lround((start + 0.5) * 128.0));
    const auto scale = static_cast<std::uint32_t>(std::lround(slope * 65536.0));
    encode_lines[kEncodeFirstEntry + line] = bias << 16 | scale;
  }
}

const SrgbTables kSrgbTables;

}  // namespace facet::shading

namespace facet {

glm::vec3 srgb_to_linear(glm::vec3 srgb) {
  return {shading::srgb_to_linear(srgb.r), shading::srgb_to_linear(srgb.g),
          shading::srgb_to_linear(srgb.b)};
}

glm::vec3 linear_to_srgb(glm::vec3 linear) {
  return {shading::linear_to_srgb(linear.r), shading::linear_to_srgb(linear.g),
          shading::linear_to_srgb(linear.b)};
}

}  // namespace facet
