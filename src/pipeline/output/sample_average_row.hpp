// Stage: output, the MSAA resolve's average (sample_average_row.cpp, compiled for every target
// Highway supports): a tile row's pixels whose samples differ become the mean of their samples,
// in linear light (frames without tone mapping; tone mapped, output.cpp maps each sample
// first). Along a model's silhouette and its small triangles' edges, which pixels differ is as
// good as random to the branch predictor: the kernel selects rather than branches, but for runs
// of pixels none of which differs, which it copies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>

#include "core/simd_target.hpp"

namespace facet::pipeline {

// out[i] for the count pixels i of a row: where split[i], the sum of its samples' colors,
// colors[i] then others[i * (samples - 1) + s - 1] for s = 1 ... samples - 1, in that order,
// times 1 / samples; elsewhere colors[i] (every sample alike). out may be colors. The same bits
// on every target.
using AverageSamplesRowKernel = void (*)(const glm::vec4* colors, const glm::vec4* others,
                                         int samples, const std::uint8_t* split, int count,
                                         glm::vec4* out);
AverageSamplesRowKernel average_samples_row_kernel(SimdTarget target);

}  // namespace facet::pipeline
