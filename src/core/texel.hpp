// A texture's texel as linear RGBA, and 8-bit texel codes decoded to it: sRGB-encoded color
// (IEC 61966-2-1) and plain unorm data (code / 255), alpha always unorm. What textures read
// when building mipmaps and their linear copy (texture.cpp) and when sampling
// (texture_sample-inl.h).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>

namespace facet {

// One linear RGBA texel in a 128-bit vector, one lane per channel (GCC/Clang vector extension:
// SSE on x86, NEON on ARM, on every Highway target too). Lane-wise +, -, * round exactly as the
// scalar glm::vec4 operations they replace (no fused multiply-add: -ffp-contract=off).
using Texel = float __attribute__((vector_size(16)));

// The float RGBA texel at p.
inline Texel load_texel(const float* p) {
  Texel t;
  std::memcpy(&t, p, sizeof t);
  return t;
}

struct TexelDecode {
  std::array<float, 256> srgb;
  std::array<float, 256> unorm;
  // The table for the color channels of an sRGB-encoded (srgb) or plain texture.
  const float* color(bool is_srgb) const { return is_srgb ? srgb.data() : unorm.data(); }
};

// Built on first use (no static-initialisation order issue).
const TexelDecode& texel_decode();

// The 8-bit RGBA texel at p decoded: its color channels by `color` (TexelDecode::color), alpha
// by `alpha` (TexelDecode::unorm).
inline Texel decode_rgba8(const std::uint8_t* p, const float* color, const float* alpha) {
  return Texel{color[p[0]], color[p[1]], color[p[2]], alpha[p[3]]};
}

}  // namespace facet
