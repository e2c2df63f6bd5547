// Stage: output, filling a row with one value (fill_row.cpp, compiled for every target Highway
// supports): clear_tile (output.cpp) clears each tile's colors and sample depths with them at the
// start of every tile drawn, with the widest stores the target has.
#pragma once

#include <cstddef>
#include <glm/vec4.hpp>

#include "core/simd_target.hpp"

namespace facet::pipeline {

// out[i] = value for the count entries of a row.
using FillFloatRowKernel = void (*)(float* out, std::ptrdiff_t count, float value);
FillFloatRowKernel fill_float_row_kernel(SimdTarget target);

// out[i] = value for the count colors of a row.
using FillColorRowKernel = void (*)(glm::vec4* out, std::ptrdiff_t count, const glm::vec4& value);
FillColorRowKernel fill_color_row_kernel(SimdTarget target);

}  // namespace facet::pipeline
