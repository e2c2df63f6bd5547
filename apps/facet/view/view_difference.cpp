// The difference view (see view_difference.hpp).
#include "view_difference.hpp"

#include <algorithm>
#include <cstdlib>

namespace facet::cli {

void show_difference(Framebuffer& shown, const Framebuffer& other, int gain) {
  std::vector<std::uint8_t>& a = shown.rgba8();
  const std::vector<std::uint8_t>& b = other.rgba8();
  for (std::size_t i = 0; i < a.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      a[i + c] = static_cast<std::uint8_t>(std::min(255, std::abs(a[i + c] - b[i + c]) * gain));
    }
    a[i + 3] = 255;
  }
}

}  // namespace facet::cli
