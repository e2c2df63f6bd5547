// A plain scalar texture sampler, a texel at a time through Texture::texel(): the oracle the SIMD
// sampler (core/texture_sample-inl.h, shading/texel_batch.cpp) is checked against bit for bit.
// The same IEEE operations in the same order as OpenGL 4.6 §8.14 writes them (no fused
// multiply-add in the tests' build either).
#pragma once

#include <algorithm>
#include <glm/glm.hpp>

#include "core/portable_math.hpp"
#include "facet/material.hpp"
#include "facet/texture.hpp"

namespace facet::test {

// A texel-space coordinate made safe to convert to int (NaN and huge values to +-2^23), then
// its floor.
inline int reference_floor(float x) {
  constexpr float kLimit = 8388608.0f;
  x = x > -kLimit ? std::min(x, kLimit) : -kLimit;  // the comparison is false for NaN
  const int t = static_cast<int>(x);
  return static_cast<float>(t) > x ? t - 1 : t;
}

// Integer texel coordinate -> inside [0, size), OpenGL 4.6 §8.14.2 (table 8.20).
inline int reference_wrap(Wrap mode, int i, int size) {
  auto positive_mod = [](int a, int n) { return ((a % n) + n) % n; };
  switch (mode) {
    case Wrap::clamp_to_edge:
      return std::clamp(i, 0, size - 1);
    case Wrap::mirrored_repeat: {
      const int m = positive_mod(i, 2 * size);
      return m < size ? m : 2 * size - 1 - m;
    }
    case Wrap::repeat:
    default:
      return positive_mod(i, size);
  }
}

// The texel at wrapped (i, j) of a level, j counted from the bottom row.
inline glm::vec4 reference_texel(const Texture& t, const Sampler& s, int level, int i, int j) {
  const int w = t.level(level).width, h = t.level(level).height;
  return t.texel(level, reference_wrap(s.wrap_u, i, w), h - 1 - reference_wrap(s.wrap_v, j, h));
}

inline glm::vec4 reference_bilinear(const Texture& t, const Sampler& s, int level, glm::vec2 uv) {
  const int w = t.level(level).width, h = t.level(level).height;
  const float x = uv.x * static_cast<float>(w) - 0.5f, y = uv.y * static_cast<float>(h) - 0.5f;
  const int i0 = reference_floor(x), j0 = reference_floor(y);
  constexpr float kLimit = 8388608.0f;  // the fractions of the clamped coordinates
  const float xs = x > -kLimit ? std::min(x, kLimit) : -kLimit;
  const float ys = y > -kLimit ? std::min(y, kLimit) : -kLimit;
  const float a = xs - static_cast<float>(i0), b = ys - static_cast<float>(j0);
  const glm::vec4 bottom = reference_texel(t, s, level, i0, j0) * (1.0f - a) +
                           reference_texel(t, s, level, i0 + 1, j0) * a;
  const glm::vec4 top = reference_texel(t, s, level, i0, j0 + 1) * (1.0f - a) +
                        reference_texel(t, s, level, i0 + 1, j0 + 1) * a;
  return bottom * (1.0f - b) + top * b;
}

// Texture::sample.
inline glm::vec4 reference_sample(const Texture& t, const Sampler& s, glm::vec2 uv, float lod) {
  switch (s.filter) {
    case Filter::nearest: {
      const int i = reference_floor(uv.x * static_cast<float>(t.width()));
      const int j = reference_floor(uv.y * static_cast<float>(t.height()));
      return reference_texel(t, s, 0, i, j);
    }
    case Filter::bilinear:
      return reference_bilinear(t, s, 0, uv);
    case Filter::trilinear:
    default: {
      // Negative lod is magnification (the base level); NaN also lands on level 0.
      const float top = static_cast<float>(t.level_count() - 1);
      const float l = lod > 0.0f ? std::min(lod, top) : 0.0f;
      const int l0 = static_cast<int>(l);
      const float f = l - static_cast<float>(l0);
      const glm::vec4 a = reference_bilinear(t, s, l0, uv);
      if (f <= 0.0f) return a;
      return a * (1.0f - f) + reference_bilinear(t, s, l0 + 1, uv) * f;
    }
  }
}

// The level of detail from uv's screen-space derivatives (OpenGL 4.6 §8.14.1 without
// anisotropy): log2 of the longer footprint edge in base texels, from squared lengths.
inline float reference_lod(const Texture& t, glm::vec2 duv_dx, glm::vec2 duv_dy) {
  const glm::vec2 size(static_cast<float>(t.width()), static_cast<float>(t.height()));
  const glm::vec2 dx = duv_dx * size, dy = duv_dy * size;
  const float rho2 = std::max(dx.x * dx.x + dx.y * dx.y, dy.x * dy.x + dy.y * dy.y);
  return 0.5f * shading::lod_log2(rho2);
}

// A material's map at texture coordinate uv whose derivatives are duv_dx, duv_dy: the map's
// transform ((m00 u + m10 v) + m20; none for the identity), the derivatives through its linear
// part, then the texture.
inline glm::vec4 reference_sample_map(const TextureMap& map, glm::vec2 uv, glm::vec2 duv_dx,
                                      glm::vec2 duv_dy) {
  const glm::mat3& m = map.transform;
  const glm::vec2 uv_t = m == glm::mat3(1.0f)
                             ? uv
                             : glm::vec2{m[0][0] * uv.x + m[1][0] * uv.y + m[2][0],
                                         m[0][1] * uv.x + m[1][1] * uv.y + m[2][1]};
  float lod = 0.0f;
  if (map.sampler.filter == Filter::trilinear) {
    const glm::vec2 dx{m[0][0] * duv_dx.x + m[1][0] * duv_dx.y,
                       m[0][1] * duv_dx.x + m[1][1] * duv_dx.y};
    const glm::vec2 dy{m[0][0] * duv_dy.x + m[1][0] * duv_dy.y,
                       m[0][1] * duv_dy.x + m[1][1] * duv_dy.y};
    lod = reference_lod(*map.texture, dx, dy);
  }
  return reference_sample(*map.texture, map.sampler, uv_t, lod);
}

}  // namespace facet::test
