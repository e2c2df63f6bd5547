// Stage: output, tone mapping (tone_map_row.cpp, compiled for every target Highway supports):
// how linear colors of any brightness become colors a display can show, before the sRGB
// encode. resolve_tile (output.cpp) maps each tile row here, each sample of a multisampled
// pixel before the samples are averaged, so a bright highlight next to a dark background
// makes a smooth edge rather than a white one. The curves (RenderSettings::tone_mapping) are
// written once, here, with SIMD; the same operations in every lane, unfused, so every target
// computes the same bits.
#pragma once

#include <glm/vec4.hpp>

#include "core/simd_target.hpp"
#include "facet/color.hpp"

namespace facet::pipeline {

// out[i] for the count colors: red, green and blue times scale (the exposure), then through
// curve (negative values and NaN taken as 0, values above 65504 as 65504); alpha as it is.
// Where depth is not null and depth[i] equals clear_depth (nothing was drawn), out[i] is
// colors[i] scaled but not mapped: the clear color stays the color asked for. out may be
// colors. curve is never ToneMapping::none.
using ToneMapRowKernel = void (*)(ToneMapping curve, const glm::vec4* colors, const float* depth,
                                  float clear_depth, int count, float scale, glm::vec4* out);
ToneMapRowKernel tone_map_row_kernel(SimdTarget target);

}  // namespace facet::pipeline
