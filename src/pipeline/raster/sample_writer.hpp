// Stage: raster + shade, writing a shaded color into the tile with the draw's blending
// (blend_into), and under MSAA into the samples the triangle covers (SampleWriter).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>

#include "facet/material.hpp"
#include "pipeline/raster/model_traits.hpp"
#include "pipeline/raster/tile_context.hpp"

namespace facet::pipeline {

// Writes one shaded color into the tile with the draw's blending.
template <class Shading, AlphaMode kAlpha>
void blend_into(glm::vec4& out, const glm::vec4& color) {
  if constexpr (additive<Shading>()) {
    out += color;
  } else if constexpr (kAlpha == AlphaMode::blend) {  // "over", straight alpha
    out = glm::vec4(glm::vec3(color) * color.a + glm::vec3(out) * (1.0f - color.a),
                    color.a + out.a * (1.0f - color.a));
  } else if constexpr (kAlpha == AlphaMode::additive) {
    out += glm::vec4(glm::vec3(color) * color.a, 0.0f);
  } else {
    // Channel by channel: GCC assembles `color` in memory from 4- and 8-byte pieces, and a
    // 16-byte copy reloading them would stall on store forwarding. Opaque and cut-out draws
    // cover what they draw: alpha 1, whatever a texture's alpha channel says (glTF ignores an
    // opaque material's alpha; a PNG with alpha must not see through an opaque surface).
    out.r = color.r;
    out.g = color.g;
    out.b = color.b;
    out.a = writes_data<Shading>() ? color.a : 1.0f;
  }
}

// MSAA: writes a pixel's color, shaded once, to the samples that its triangle covers and that
// pass the depth test, with the draw's blending, and with kDepthWrite each sample's own depth
// (PixelWriter::store_samples; waiting pixels' colors go through
// RasterKernels::write_sample_colors, the search having written their depths). The tile's
// buffers are read once, into the writer: a store to split, a byte, may alias TileContext's
// fields, which would otherwise be read again after each.
template <class Shading, AlphaMode kAlpha, bool kDepthWrite>
struct SampleWriter {
  // Whether a written color replaces the samples' (opaque and cut-out draws).
  static constexpr bool kReplaces =
      !additive<Shading>() && (kAlpha == AlphaMode::opaque || kAlpha == AlphaMode::mask);

  // depth_steps: the triangle's depth at each sample minus its depth at the pixel centre.
  SampleWriter(const TileContext& tile, const float* depth_steps)
      : color(tile.color),
        others(tile.sample_colors),
        depth(tile.depth),
        split(tile.split),
        plane(tile.sample_plane),
        samples(tile.samples),
        all((1u << tile.samples) - 1),
        sample_z(depth_steps) {}

  // The samples of `mask` (bits, not 0) of tile pixel `pixel` take `c` and depth z at the centre.
  void write(std::ptrdiff_t pixel, unsigned mask, float z, const glm::vec4& c) const {
    glm::vec4* first = color + pixel;                  // sample 0
    glm::vec4* rest = others + pixel * (samples - 1);  // rest[s - 1]: sample s >= 1
    auto at = [&](int s) -> glm::vec4& { return s == 0 ? *first : rest[s - 1]; };
    float* depth_at = depth + pixel;
    if (mask == all) {
      if (kReplaces || !split[pixel]) {
        blend_into<Shading, kAlpha>(*first, c);  // every sample alike (again)
        split[pixel] = 0;
      } else {
        for (int s = 0; s < samples; ++s) blend_into<Shading, kAlpha>(at(s), c);
      }
      if constexpr (kDepthWrite) {
        for (int s = 0; s < samples; ++s) depth_at[s * plane] = z + sample_z[s];
      }
      return;
    }
    if (!split[pixel]) {  // each sample its own copy of the pixel's color (split_pixel)
      // A replacing color overwrites the covered ones next; sample 0 is the copied one.
      const unsigned copied = (kReplaces ? all & ~mask : all) & ~1u;
      for (unsigned m = copied; m != 0; m &= m - 1) rest[std::countr_zero(m) - 1] = *first;
      split[pixel] = 1;
    }
    for (unsigned m = mask; m != 0; m &= m - 1) {
      const int s = std::countr_zero(m);
      blend_into<Shading, kAlpha>(at(s), c);
      if constexpr (kDepthWrite) depth_at[s * plane] = z + sample_z[s];
    }
  }

  glm::vec4* color;
  glm::vec4* others;  // TileContext::sample_colors
  float* depth;
  std::uint8_t* split;
  std::ptrdiff_t plane;
  int samples;
  unsigned all;  // every sample's bit
  const float* sample_z;
};

}  // namespace facet::pipeline
