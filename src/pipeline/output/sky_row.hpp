// Stage: output, the SIMD part of the background. fill_background (output.cpp) draws the
// environment into the pixels nothing covered; for the procedural sky gradient (an environment
// without an image) it does a tile row at a time here, with SIMD (sky_row.cpp, compiled for
// every target Highway supports), computing what the scalar path computes, bit for bit.
#pragma once

#include <glm/glm.hpp>

#include "core/simd_target.hpp"
#include "facet/light.hpp"

namespace facet::pipeline {

// The view through the frame's pixels.
struct SkyView {
  glm::mat4 inverse_view_projection;
  glm::vec3 eye;
  int width, height;  // framebuffer size
};

// The environment's radiance through pixel (x, y) of the frame, scalar: unproject the pixel
// centre's point on the far plane, look along it from the eye.
glm::vec3 background_radiance(const SkyView& view, const Environment& environment, int x, int y);

// For pixels (x0 + i, y), i in [0, count), whose depth[i] equals clear_depth: colors[i] =
// (background_radiance(...), 1) of a sky-gradient environment (no image).
using SkyRowKernel = void (*)(const SkyView& view, const Environment& environment, int x0, int y,
                              int count, const float* depth, float clear_depth, glm::vec4* colors);
SkyRowKernel sky_row_kernel(SimdTarget target);

}  // namespace facet::pipeline
