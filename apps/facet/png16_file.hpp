// Writing 16-bit grayscale PNGs (through libpng), for id outputs under a .png or .ppm name:
// lossless, and readable by any image tool.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace facet::cli {

// Writes width x height values, row-major, top row first, to an open file. Throws
// facet::Error naming `name` (the path the user sees) if libpng fails.
void write_png16(std::FILE* file, const std::string& name, int width, int height,
                 const std::vector<std::uint16_t>& values);

}  // namespace facet::cli
