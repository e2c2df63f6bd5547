// Linear colors to 8-bit codes a row at a time: the library's one sRGB encoder and its one
// rounding of display values, written once with Highway (srgb_row.cpp, compiled for every
// target). Resolve encodes each tile row here (the frame's kernels, pipeline/kernels.hpp); the
// texture mip builder, float images written as 8-bit and display_value_of fetch the kernel for
// chosen_simd_target() once per call. SIMD lanes scale and clamp each channel, pick its line of
// the encode (core/color.hpp; from registers with AVX-512, else by a gather) and evaluate it in
// integers: no pow per channel, the same bytes on every target.
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>

#include "core/simd_target.hpp"

namespace facet::shading {

// rgba[4 i + c] for the count colors: red, green and blue times scale (the exposure) encoded
// to 8-bit sRGB by color.hpp's lines (within one code of round(linear_to_srgb(v) * 255), v
// clamped to [0, 1], NaN as 0); alpha (not scaled) clamped to [0, 1] (NaN as 0) and rounded to
// 8 bits, v * 255 + 0.5 truncated. The same bytes on every target.
using EncodeSrgbRowKernel = void (*)(const glm::vec4* colors, int count, float scale,
                                     std::uint8_t* rgba);
EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target);

// A color whose codes are known already, and those codes (RGBA, byte 0 red): what the resolve's
// background pixels hold, the clear color.
struct KnownCodes {
  glm::vec4 color{0.0f};
  std::uint32_t codes = 0;  // the encode kernel's for color at the row's scale
};
// As EncodeSrgbRowKernel, except that runs of colors with known.color's bits (a vector of them
// at a time) take known.codes instead of being encoded again: the same bytes when known.codes
// is color's encode at this scale. A tile row's undrawn pixels cost a compare.
using EncodeSrgbRowKnowingKernel = void (*)(const glm::vec4* colors, int count, float scale,
                                            const KnownCodes& known, std::uint8_t* rgba);
EncodeSrgbRowKnowingKernel encode_srgb_row_knowing_kernel(SimdTarget target);

// rgba[4 i + c] for the count colors, every channel clamped to [0, 1] (NaN to 0) and rounded
// to 8 bits as the encode kernel rounds alpha: unorm texture levels, and the resolve of
// display values (pipeline/output/output.hpp).
using RoundUnorm8RowKernel = void (*)(const glm::vec4* colors, int count, std::uint8_t* rgba);
RoundUnorm8RowKernel round_unorm8_row_kernel(SimdTarget target);

}  // namespace facet::shading
