// facet::tone_map (facet/color.hpp): the resolve's tone mapping kernel on the caller's colors.
#include <algorithm>
#include <cmath>

#include "core/simd_target.hpp"
#include "facet/color.hpp"
#include "pipeline/output/tone_map_row.hpp"

namespace facet {

void tone_map(ToneMapping curve, std::span<glm::vec4> colors, float exposure) {
  const float scale = std::exp2(exposure);
  if (curve == ToneMapping::none) {
    for (glm::vec4& c : colors) c = glm::vec4(glm::vec3(c) * scale, c.a);
    return;
  }
  const pipeline::ToneMapRowKernel kernel = pipeline::tone_map_row_kernel(chosen_simd_target());
  // In runs, so a count beyond int's range is fine.
  constexpr std::size_t kRun = 1 << 20;
  for (std::size_t first = 0; first < colors.size(); first += kRun) {
    const int count = static_cast<int>(std::min(kRun, colors.size() - first));
    kernel(curve, colors.data() + first, nullptr, 0.0f, count, scale, colors.data() + first);
  }
}

}  // namespace facet
