// Texture sampling for a batch of pixels at once: the raster loop (pipeline/raster.hpp) packs
// the texture coordinates of up to 64 pixels (of one triangle, or of several small triangles of
// one draw) and samples the base color map for
// all of them with SIMD (texel_batch.cpp, compiled for every target Highway supports), instead
// of one sample_map() call per pixel. Same operations as sample_map_at() lane by lane, so the
// same bits; textures the SIMD path does not handle take sample_map_at() per pixel.
#pragma once

#include <cstdint>

#include "facet/material.hpp"
#include "pipeline/frame.hpp"

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
  // Pixels of several triangles: each pixel's triangle's plane slopes, kSlopes arrays of
  // kTexelBatch entries (readable as u is), in the order of the Slope names; they replace
  // sample_batch's planes and inv_w. Null: every pixel is of the triangle those describe.
  enum Slope { u_dx, v_dx, u_dy, v_dy, inv_w_dx, inv_w_dy, kSlopes };
  const float (*slopes)[kTexelBatch] = nullptr;
  // Out: linear RGBA of each pixel's texel.
  alignas(64) float rgba[kTexelBatch][4];
};

// Samples map at every pixel of the batch. planes: the triangle's u/w and v/w planes (two in a
// row), inv_w its 1/w plane; they give the exact derivatives, as Fragment::ddx/ddy do (both
// unused when batch.slopes is set).
void sample_batch(const TextureMap& map, const pipeline::Plane* planes,
                  const pipeline::Plane& inv_w, TexelBatch& batch);

}  // namespace facet::shading
