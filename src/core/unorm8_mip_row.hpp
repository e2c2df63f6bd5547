// A row of an 8-bit unorm mip level from the two rows above it, written once with Highway
// (unorm8_mip_row.cpp, compiled for every target): each texel's channels are the four texels'
// (a + b + c + d + 2) >> 2, which for every combination of four codes is exactly what the float
// average of their decoded values rounds to (checked over all 2^32), at a fraction of its cost.
// Integers alone: the same bytes on every target.
#pragma once

#include <cstdint>

#include "core/simd_target.hpp"

namespace facet {

// out[4 x + c] for x in [0, count): the average of texels 2x and 2x + 1 of rows top and bottom
// (RGBA, 4 bytes a texel), channel c.
using HalveUnorm8RowKernel = void (*)(const std::uint8_t* top, const std::uint8_t* bottom,
                                      int count, std::uint8_t* out);
HalveUnorm8RowKernel halve_unorm8_row_kernel(SimdTarget target);

}  // namespace facet
