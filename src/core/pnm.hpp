// PNM reader: the Netpbm formats PGM and PPM (P2, P3, P5, P6), parsed from memory into RGBA8.
// Used by load_texture (image_read.cpp) and by the fuzz target tests/fuzz/pnm_fuzz.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace facet::io {

// Each side of a PNM image is limited to this, as for textures (Texture::from_rgba8).
inline constexpr int kMaxPnmSize = 16384;

struct PnmImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, top row first, alpha 255
};

// Parses a whole PNM file (format per https://netpbm.sourceforge.net/doc/ppm.html and pgm.html):
// comments from '#' to the end of the line anywhere in the header (and between plain-text
// values), maxval 1..65535 scaled to 0..255 with rounding, 16-bit binary samples big-endian.
// Gray (PGM) becomes r = g = b. Bytes after the raster are ignored.
// Throws facet::Error "<name>: <what> (line N)" (or "... (byte N)" inside binary data) for any
// malformed input; never reads outside [data, data + size).
PnmImage parse_pnm(const std::uint8_t* data, std::size_t size, const std::string& name);

}  // namespace facet::io
