// Display values (shading/models.hpp: what the debug views and glmark2's shaders store) written
// out one pixel at a time, for tests that compare the SIMD kernels with them.
#pragma once

#include <glm/glm.hpp>

#include "core/color.hpp"
#include "shading/uniforms.hpp"
#include "support/srgb_reference.hpp"

namespace facet::test {

// The value each channel of `shown` stores as: the value clamped to [0, 1] in a float target
// (display_exact), else its 8-bit code as code / 255 (display-referred frames) or decoded.
inline glm::vec4 reference_display_value(glm::vec3 shown, const shading::DrawUniforms& u) {
  glm::vec4 out{0.0f, 0.0f, 0.0f, 1.0f};
  for (int c = 0; c < 3; ++c) {
    if (u.frame->display_exact) {
      out[c] = shown[c] > 0.0f ? std::min(shown[c], 1.0f) : 0.0f;
      continue;
    }
    const std::uint8_t code = encode_unorm8(shown[c]);
    out[c] = u.frame->display_referred ? static_cast<float>(code) * shading::kInverse255
                                       : shading::decode_srgb8(code);
  }
  return out;
}

}  // namespace facet::test
