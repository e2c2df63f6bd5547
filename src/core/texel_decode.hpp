// 8-bit texel codes to linear floats, for sRGB-encoded color (IEC 61966-2-1) and for plain
// unorm data (code / 255): how textures decode their 8-bit levels when building mipmaps and
// their linear copy (texture.cpp), and when sampling levels that have no linear copy
// (texture_sample-inl.h). Alpha is always unorm.
#pragma once

#include <array>

namespace facet {

struct TexelDecode {
  std::array<float, 256> srgb;
  std::array<float, 256> unorm;
  // The table for the color channels of an sRGB-encoded (srgb) or plain texture.
  const float* color(bool is_srgb) const { return is_srgb ? srgb.data() : unorm.data(); }
};

// Built on first use (no static-initialisation order issue).
const TexelDecode& texel_decode();

}  // namespace facet
