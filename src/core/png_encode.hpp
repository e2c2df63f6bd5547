// PNG encoder for 8-bit RGBA images, compressing bands of rows on all cores.
#pragma once

#include <cstdint>
#include <vector>

namespace facet::io {

// A whole PNG file (signature, IHDR, sRGB, IDAT, IEND) for width x height pixels of 8-bit sRGB
// RGBA, top row first. An image whose alpha is 255 everywhere is stored as RGB. The bytes are
// the same for any number of threads.
std::vector<std::uint8_t> encode_png(const std::uint8_t* rgba, int width, int height);

}  // namespace facet::io
