// Texture maps derived at import from kinds the shaders do not sample themselves (see
// import_assimp.hpp): a height (bump) map becomes a tangent-space normal map, and separate grey
// roughness, metalness and gloss maps become the packed metallic-roughness map. Runs once per
// material at load time; the renderer sees only the derived maps.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <vector>

#include "import/import_assimp.hpp"

namespace facet::io {
namespace {

// A texel index past an edge, as the map's sampler would wrap it.
int wrapped(int i, int size, Wrap wrap) {
  if (wrap == Wrap::clamp_to_edge) return std::clamp(i, 0, size - 1);
  if (wrap == Wrap::mirrored_repeat) {
    if (i < 0) return std::min(-i - 1, size - 1);
    if (i >= size) return std::max(2 * size - i - 1, 0);
    return i;
  }
  return ((i % size) + size) % size;
}

// The grey value of a texel of level 0 (the mean of its color channels: grey maps are often
// stored as RGB). Data maps are loaded linear, so their bytes are read directly: texel()'s
// checks and decoding, four times a texel, would make a large height map slow to load.
float grey(const Texture& texture, int x, int y) {
  if (texture.format() == Texture::Format::rgba8 && !texture.srgb()) {
    const std::uint8_t* p =
        &texture.level(0).rgba8[(static_cast<std::size_t>(y) * texture.width() + x) * 4];
    return static_cast<float>(p[0] + p[1] + p[2]) * (1.0f / (3.0f * 255.0f));
  }
  const glm::vec4 t = texture.texel(0, x, y);
  return (t.r + t.g + t.b) / 3.0f;
}

// The grey value of `texture` at the texel of a width x height image at (x, y) (nearest texel,
// so that maps of different sizes can be combined), or `absent` for no texture.
float grey_at(const Texture* texture, int x, int y, int width, int height, float absent) {
  if (!texture) return absent;
  const int tx = static_cast<int>((static_cast<long long>(x) * texture->width()) / width);
  const int ty = static_cast<int>((static_cast<long long>(y) * texture->height()) / height);
  return grey(*texture, tx, ty);
}

std::uint8_t unorm8(float v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

}  // namespace

std::shared_ptr<const Texture> normal_map_from_heights(const Texture& heights, float strength,
                                                       const Sampler& sampler) {
  const int width = heights.width(), height = heights.height();
  const float depth = kBumpDepthTexels * strength;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    const int up = wrapped(y - 1, height, sampler.wrap_v);  // rows are stored top first: +v
    const int down = wrapped(y + 1, height, sampler.wrap_v);
    for (int x = 0; x < width; ++x) {
      const int left = wrapped(x - 1, width, sampler.wrap_u);
      const int right = wrapped(x + 1, width, sampler.wrap_u);
      // Central differences, in texel widths of height per texel.
      const float du = depth * 0.5f * (grey(heights, right, y) - grey(heights, left, y));
      const float dv = depth * 0.5f * (grey(heights, x, up) - grey(heights, x, down));
      const glm::vec3 n = glm::normalize(glm::vec3(-du, -dv, 1.0f));
      std::uint8_t* out = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      out[0] = unorm8(n.x * 0.5f + 0.5f);
      out[1] = unorm8(n.y * 0.5f + 0.5f);
      out[2] = unorm8(n.z * 0.5f + 0.5f);
      out[3] = 255;
    }
  }
  return Texture::from_rgba8(width, height, std::move(rgba), /*srgb=*/false,
                             heights.name() + " (normals from heights)");
}

float roughness_from_shininess(float exponent) {
  // Walter et al. 2007, "Microfacet Models for Refraction", eq. 33: the Blinn-Phong exponent n
  // matches a microfacet distribution of width alpha = sqrt(2 / (n + 2)); facet's GGX takes
  // alpha = roughness^2 (shading/shade_batch.cpp), so roughness = alpha^(1/2).
  const float alpha = std::sqrt(2.0f / (std::max(exponent, 0.0f) + 2.0f));
  return std::sqrt(alpha);
}

std::shared_ptr<const Texture> packed_metallic_roughness(const Texture* roughness,
                                                         const Texture* metalness,
                                                         const Texture* gloss,
                                                         float gloss_exponent) {
  const Texture* sized[] = {roughness, metalness, gloss};
  int width = 1, height = 1;
  for (const Texture* t : sized) {
    if (t) width = std::max(width, t->width()), height = std::max(height, t->height());
  }
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float rough = grey_at(roughness, x, y, width, height, 1.0f);
      if (!roughness && gloss) {
        rough = roughness_from_shininess(gloss_exponent * grey_at(gloss, x, y, width, height, 1));
      }
      std::uint8_t* out = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      out[0] = 255;
      out[1] = unorm8(rough);
      out[2] = unorm8(grey_at(metalness, x, y, width, height, 1.0f));
      out[3] = 255;
    }
  }
  const Texture* named = roughness ? roughness : metalness ? metalness : gloss;
  return Texture::from_rgba8(width, height, std::move(rgba), /*srgb=*/false,
                             (named ? named->name() : std::string()) + " (metallic-roughness)");
}

}  // namespace facet::io
