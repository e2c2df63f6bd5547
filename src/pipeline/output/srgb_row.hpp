// Stage: output, the SIMD part of resolve (srgb_row.cpp, compiled for every target Highway
// supports). resolve_tile (output.cpp) turns each tile row of linear colors into 8-bit sRGB
// here: SIMD lanes scale, clamp and find each channel's run of the encoding table
// (shading/color.hpp), each run's entry is loaded one at a time (scalar loads: faster than
// gathers on the CPUs this runs on), then SIMD lanes finish the codes. Faster than encoding a
// channel at a time, and bit for bit the same. Rows of display values only need rounding
// (round_unorm8_row).
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>

#include "core/simd_target.hpp"

namespace facet::pipeline {

// rgba[4 i + c] for the count colors: red, green and blue times scale (the exposure) as
// shading::encode_srgb8 encodes them; alpha (not scaled) clamped to [0, 1] and rounded to 8
// bits. NaN encodes as 0.
using EncodeSrgbRowKernel = void (*)(const glm::vec4* colors, int count, float scale,
                                     std::uint8_t* rgba);
EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target);

// rgba[4 i + c] for the count colors, every channel clamped to [0, 1] (NaN to 0) and rounded
// to 8 bits as the encode kernel rounds alpha: the resolve of display values (output.hpp).
using RoundUnorm8RowKernel = void (*)(const glm::vec4* colors, int count, std::uint8_t* rgba);
RoundUnorm8RowKernel round_unorm8_row_kernel(SimdTarget target);

}  // namespace facet::pipeline
