// Texture sampling for a batch of pixels at once: the raster loop (pipeline/raster/raster.hpp)
// packs the texture coordinates of up to 64 pixels (of one triangle, or of several small triangles
// of one draw) and samples each map the model reads for all of them with SIMD (texel_batch.cpp,
// compiled for every target Highway supports): the map's transform, each pixel's level of detail
// from exact derivatives of its triangle's planes, then the texture's filtering.
#pragma once

#include <cstdint>

#include "core/simd_target.hpp"
#include "facet/material.hpp"
#include "shading/varyings.hpp"

namespace facet::shading {

inline constexpr int kTexelBatch = 64;

struct TexelBatch {
  int count = 0;  // pixels in the batch
  // In: the texture coordinate and clip w of each pixel (perspective-correct, as in Fragment),
  // kTexelBatch entries each; those from count up to the next multiple of 8 must be readable
  // (they are computed, then ignored).
  const float* u = nullptr;
  const float* v = nullptr;
  const float* w = nullptr;
  // Where the exact derivatives for the level of detail come from (as Fragment::ddx/ddy):
  // pixels of one triangle use its u/w and v/w planes (two in a row) and its 1/w plane;
  // pixels of several triangles (slopes set) each their triangle's plane slopes, kSlopes arrays
  // of kTexelBatch entries (readable as u is) in the order of the Slope names.
  const Plane* planes = nullptr;
  const Plane* inv_w = nullptr;
  enum Slope { u_dx, v_dx, u_dy, v_dy, inv_w_dx, inv_w_dy, kSlopes };
  const float (*slopes)[kTexelBatch] = nullptr;

  // Slope k of pixel j's triangle.
  float slope(int k, int j) const {
    if (slopes != nullptr) return slopes[k][j];
    switch (k) {
      case u_dx:
        return planes[0].dx;
      case v_dx:
        return planes[1].dx;
      case u_dy:
        return planes[0].dy;
      case v_dy:
        return planes[1].dy;
      case inv_w_dx:
        return inv_w->dx;
      default:
        return inv_w->dy;
    }
  }
  // Out: linear RGBA of each pixel's texel.
  alignas(64) float rgba[kTexelBatch][4];
};

// Samples map at every pixel of the batch, any texture, filter and wrap modes.
using SampleBatchKernel = void (*)(const TextureMap& map, TexelBatch& batch);
SampleBatchKernel sample_batch_kernel(SimdTarget target);

}  // namespace facet::shading
