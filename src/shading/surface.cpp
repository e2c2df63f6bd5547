// Texture map sampling at a fragment (see surface.hpp).
#include "shading/surface.hpp"

#include "facet/texture.hpp"

namespace facet::shading {

glm::vec4 sample_map_at(const TextureMap& map, glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy) {
  const glm::mat3& m = map.transform;
  const glm::vec2 uv_t = transform_texcoord(m, uv);
  float lod = 0.0f;
  if (map.sampler.filter == Filter::trilinear) {
    // Derivatives transform by the linear part only.
    const glm::vec2 dx{m[0][0] * duv_dx.x + m[1][0] * duv_dx.y,
                       m[0][1] * duv_dx.x + m[1][1] * duv_dx.y};
    const glm::vec2 dy{m[0][0] * duv_dy.x + m[1][0] * duv_dy.y,
                       m[0][1] * duv_dy.x + m[1][1] * duv_dy.y};
    lod = map.texture->lod(dx, dy);
  }
  return map.texture->sample(map.sampler, uv_t, lod);
}

glm::vec4 sample_map(const TextureMap& map, const Fragment& f, int slot) {
  return sample_map_at(map, {f.v[slot], f.v[slot + 1]}, {f.ddx(slot), f.ddx(slot + 1)},
                       {f.ddy(slot), f.ddy(slot + 1)});
}

}  // namespace facet::shading
