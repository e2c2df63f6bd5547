// sRGB tables (see color.hpp).
#include "shading/color.hpp"

#include <algorithm>
#include <bit>

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
