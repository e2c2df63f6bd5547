// Linear colors to 8-bit codes a row at a time: the library's one sRGB encoder and its one
// rounding of display values, written once with Highway (srgb_row.cpp, compiled for every
// target). Resolve encodes each tile row here (the frame's kernels, pipeline/kernels.hpp); the
// texture mip builder, float images written as 8-bit and display_value_of fetch the kernel for
// chosen_simd_target() once per call. SIMD lanes scale, clamp and find each channel's run of
// the encoding table (core/color.hpp), fetch each run's entry (a gather where gathers are fast,
// else a load a lane), and finish the codes: exact, with no pow per channel.
#pragma once

#include <cstdint>
#include <glm/vec4.hpp>

#include "core/simd_target.hpp"

namespace facet::shading {

// rgba[4 i + c] for the count colors: red, green and blue times scale (the exposure) encoded
// to 8-bit sRGB, each v as the largest code whose SrgbTables threshold is at most v (v clamped
// to [0, 1], NaN as 0; color.hpp); alpha (not scaled) clamped to [0, 1] (NaN as 0) and rounded
// to 8 bits, v * 255 + 0.5 truncated. The same bytes on every target.
using EncodeSrgbRowKernel = void (*)(const glm::vec4* colors, int count, float scale,
                                     std::uint8_t* rgba);
EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target);
// The kernel fetching the table's entries by gathers or by a load a lane (the same bytes):
// encode_srgb_row_kernel(target) takes gathers where gathers_are_fast().
EncodeSrgbRowKernel encode_srgb_row_kernel(SimdTarget target, bool gathering);
// Whether the CPU's AVX-512 gathers are faster than loading each lane: an Intel CPU with
// AVX-512 and no microcode mitigation of Gather Data Sampling (Linux's
// vulnerabilities/gather_data_sampling reads "Not affected"), which makes them several times
// slower. Not AMD's: on Zen 4 a load a lane measured faster. The gathering kernel gathers on
// AVX-512 targets alone (the others load a lane at a time).
bool gathers_are_fast();

// rgba[4 i + c] for the count colors, every channel clamped to [0, 1] (NaN to 0) and rounded
// to 8 bits as the encode kernel rounds alpha: unorm texture levels, and the resolve of
// display values (pipeline/output/output.hpp).
using RoundUnorm8RowKernel = void (*)(const glm::vec4* colors, int count, std::uint8_t* rgba);
RoundUnorm8RowKernel round_unorm8_row_kernel(SimdTarget target);

}  // namespace facet::shading
