// Surface helpers for the lit shading models (see surface.hpp).
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

template <bool kWithTangent, bool kPositioned>
SurfacePoint surface_point(const Fragment& f, const DrawUniforms& u) {
  const Material& m = *u.material;
  SurfacePoint s;
  glm::vec3 n = safe_normalize(load3(f.v + kNormalSlot));
  if constexpr (kPositioned) {
    s.position = load3(f.v + kPositionSlot);
    s.view = safe_normalize(u.frame->eye - s.position);
  } else {
    s.position = s.view = glm::vec3(0.0f);
  }
  // The material tests here (normal map, base color map) are runtime branches on constants of
  // the draw, taken the same way for each of its pixels (BENCHMARKS.md, "Per-draw constants").
  if constexpr (kWithTangent) {
    glm::vec4 tangent = load4(f.v + kTangentSlot);
    if (m.normal_map && glm::dot(glm::vec3(tangent), glm::vec3(tangent)) > 0.0f) {
      // Tangent space -> world: Gram-Schmidt the interpolated tangent against the normal.
      glm::vec3 t = safe_normalize(glm::vec3(tangent) - n * glm::dot(n, glm::vec3(tangent)));
      glm::vec3 b = glm::cross(n, t) * (tangent.w < 0.0f ? -1.0f : 1.0f);
      glm::vec3 texel = glm::vec3(sample_map(m.normal_map, f)) * 2.0f - 1.0f;
      texel.x *= m.normal_scale;
      texel.y *= m.normal_scale;
      glm::vec3 mapped = safe_normalize(t * texel.x + b * texel.y + n * texel.z);
      if (mapped != glm::vec3(0.0f)) n = mapped;
    }
  }
  s.normal = n;
  s.albedo = load4(f.v + kColorSlot);
  if (m.base_color_map) s.albedo *= base_color_texel(f, u);
  return s;
}

template SurfacePoint surface_point<true>(const Fragment&, const DrawUniforms&);
template SurfacePoint surface_point<false>(const Fragment&, const DrawUniforms&);
template SurfacePoint surface_point<false, false>(const Fragment&, const DrawUniforms&);

glm::vec3 mapped_emission(const Fragment& f, const DrawUniforms& u) {
  const Material& m = *u.material;
  glm::vec3 e = m.emissive;
  if (m.emissive_map) e *= glm::vec3(sample_map(m.emissive_map, f));
  return e;
}

}  // namespace facet::shading
