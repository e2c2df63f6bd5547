// sRGB tables (see color.hpp) and the public conversions (facet/color.hpp).
#include "core/color.hpp"

#include <algorithm>
#include <bit>

#include "facet/color.hpp"

namespace facet::shading {

SrgbTables::SrgbTables() {
  for (int i = 0; i < 256; ++i) {
    decode[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
    thresholds[i] = i == 0 ? 0.0f : srgb_to_linear((static_cast<float>(i) - 0.5f) / 255.0f);
  }
  thresholds[256] = 2.0f;
  for (int r = 0; r < kRuns; ++r) {
    const std::uint32_t start = kRunBase + (static_cast<std::uint32_t>(r) << kRunBits);
    const float* next = std::upper_bound(thresholds.begin() + 1, thresholds.begin() + 256,
                                         std::bit_cast<float>(start));
    const auto code = static_cast<std::uint32_t>(next - thresholds.begin() - 1);
    // thresholds[256] (2.0) lies beyond every run: the last code's run holds none.
    const std::uint32_t offset =
        std::min(std::bit_cast<std::uint32_t>(*next) - start, kRunMask + 1);
    run_code[r] = code << kRunCodeShift | offset;
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
