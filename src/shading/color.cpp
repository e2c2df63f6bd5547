// sRGB tables (see color.hpp).
#include "shading/color.hpp"

#include <algorithm>

namespace facet::shading {

SrgbTables::SrgbTables() {
  for (int i = 0; i < 256; ++i) {
    decode[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
    thresholds[i] = i == 0 ? 0.0f : srgb_to_linear((static_cast<float>(i) - 0.5f) / 255.0f);
  }
  thresholds[256] = 2.0f;
  for (int b = 0; b < kBuckets; ++b) {
    float start = static_cast<float>(b) / kBuckets;
    auto it = std::upper_bound(thresholds.begin(), thresholds.begin() + 256, start);
    bucket_code[b] = static_cast<std::uint8_t>((it - thresholds.begin()) - 1);
  }
  bucket_code[kBuckets] = 255;
}

const SrgbTables kSrgbTables;

}  // namespace facet::shading
