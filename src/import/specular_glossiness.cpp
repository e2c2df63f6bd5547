// KHR_materials_pbrSpecularGlossiness factors to the metallic-roughness Material facet shades
// (convert_specular_glossiness, import_internal.hpp). Runs once per material at load time, for
// glTF files whichever reader reads them.
#include <algorithm>
#include <cmath>

#include "import/import_internal.hpp"

namespace facet::io {
namespace {

// Perceived brightness, as used by the Khronos spec-gloss to metal-rough conversion.
float brightness(glm::vec3 c) {
  return std::sqrt(0.299f * c.r * c.r + 0.587f * c.g * c.g + 0.114f * c.b * c.b);
}

}  // namespace

// KHR_materials_pbrSpecularGlossiness to metallic-roughness, per material factor (textures are
// not re-baked): the approximation from the glTF sample models' conversion notes. Metallic is
// solved from how much brighter the specular is than a dielectric's (kDielectric); roughness =
// 1 - gloss.
void convert_specular_glossiness(glm::vec4 diffuse, glm::vec3 specular, float glossiness,
                                 Material& out) {
  constexpr float kDielectric = 0.04f;
  const float specular_strength = std::max({specular.r, specular.g, specular.b});
  const float one_minus = 1.0f - specular_strength;
  const float diffuse_brightness = brightness(glm::vec3(diffuse));
  const float specular_brightness = brightness(specular);
  float metallic = 0.0f;
  if (specular_brightness >= kDielectric) {
    float b = diffuse_brightness * one_minus / (1.0f - kDielectric) + specular_brightness -
              2.0f * kDielectric;
    float c = kDielectric - specular_brightness;
    float root = std::sqrt(std::max(b * b - 4.0f * kDielectric * c, 0.0f));
    metallic = std::clamp((-b + root) / (2.0f * kDielectric), 0.0f, 1.0f);
  }
  glm::vec3 from_diffuse =
      glm::vec3(diffuse) * one_minus / (1.0f - kDielectric) / std::max(1.0f - metallic, 1e-4f);
  glm::vec3 from_specular =
      (specular - glm::vec3(kDielectric * (1.0f - metallic))) / std::max(metallic, 1e-4f);
  glm::vec3 base = glm::mix(from_diffuse, from_specular, metallic * metallic);
  out.base_color = glm::vec4(glm::clamp(base, 0.0f, 1.0f), diffuse.a);
  out.metallic = metallic;
  out.roughness = std::clamp(1.0f - glossiness, 0.0f, 1.0f);
}

}  // namespace facet::io
