// Stage: output, the SIMD part of the background. fill_background (output.cpp) draws the
// environment into the pixels nothing covered a tile row at a time here (sky_row.cpp, compiled
// for every target Highway supports): the procedural sky gradient (shading/sky_gradient-inl.h)
// with SIMD, or the view directions with SIMD and then the image's texels through the texture
// lookups.
#pragma once

#include <glm/glm.hpp>

#include "core/simd_target.hpp"
#include "core/texture_sampler.hpp"
#include "facet/light.hpp"

namespace facet::pipeline {

// The view through the frame's pixels.
struct SkyView {
  glm::mat4 inverse_view_projection;
  glm::vec3 eye;
  int width, height;  // framebuffer size
};

// The most pixels a row call takes: a tile's row (raster/tile_context.hpp's kMaxTileSize).
inline constexpr int kMaxSkyRow = 128;

// For pixels (x0 + i, y), i in [0, count <= kMaxSkyRow), whose depth[i] equals clear_depth:
// colors[i] = (the environment's radiance, 1) through the pixel's centre, seen from the eye along
// the direction to the centre's point on the far plane (unprojected); an image environment at its
// level 0, read with sample_at (the frame's texture lookups).
using SkyRowKernel = void (*)(const SkyView& view, const Environment& environment,
                              SampleAtKernel sample_at, int x0, int y, int count,
                              const float* depth, float clear_depth, glm::vec4* colors);
SkyRowKernel sky_row_kernel(SimdTarget target);

}  // namespace facet::pipeline
