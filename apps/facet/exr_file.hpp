// Writing OpenEXR files (through OpenEXR's C++ library) for the float and id outputs of
// `facet render`: scan lines, ZIP compression (lossless), 32-bit float or unsigned channels.
#pragma once

#include <string>
#include <vector>

namespace facet::cli {

struct ExrChannel {
  std::string name;          // e.g. "R", "Z"
  const void* first;         // the channel's value in the top-left pixel
  bool is_uint;              // 32-bit unsigned values; else 32-bit float
  int values_per_pixel = 1;  // the step from one pixel's value to the next, in values
};

// Writes a width x height image whose channels read row-major, top row first. Throws
// facet::Error naming `name` (the path the user sees) if OpenEXR cannot write `path`.
void write_exr(const std::string& path, const std::string& name, int width, int height,
               const std::vector<ExrChannel>& channels);

}  // namespace facet::cli
