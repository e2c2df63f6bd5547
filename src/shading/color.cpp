// sRGB encode/decode tables (see color.hpp).
#include "shading/color.hpp"

#include <algorithm>
#include <array>

namespace facet::shading {
namespace {

// thresholds[i] = linear value at which code i begins (midpoint between codes i-1 and i in
// sRGB space, decoded). Encoding is then "the largest i with thresholds[i] <= linear",
// which equals round(linear_to_srgb(linear) * 255) without calling pow per pixel.
struct SrgbTables {
  std::array<float, 256> thresholds;
  std::array<float, 256> decode;
  SrgbTables() {
    for (int i = 0; i < 256; ++i) {
      decode[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
      thresholds[i] = i == 0 ? 0.0f : srgb_to_linear((static_cast<float>(i) - 0.5f) / 255.0f);
    }
  }
};

const SrgbTables& tables() {
  static const SrgbTables kTables;
  return kTables;
}

}  // namespace

std::uint8_t encode_srgb8(float linear) {
  if (!(linear > 0.0f)) return 0;  // also catches NaN
  if (linear >= 1.0f) return 255;
  const auto& t = tables().thresholds;
  auto it = std::upper_bound(t.begin(), t.end(), linear);
  return static_cast<std::uint8_t>((it - t.begin()) - 1);
}

float decode_srgb8(std::uint8_t code) { return tables().decode[code]; }

}  // namespace facet::shading
