// Stage: raster + shade. Reads one tile's bin (bin.cpp) and, for each triangle in submission
// order, finds the covered pixel centres with the fixed-point edge functions set up in
// setup.cpp, tests depth early, shades with the draw's shading model and writes the tile's
// own color and depth buffers; output.cpp then resolves the tile to the framebuffer.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/vec4.hpp>
#include <limits>

#include "pipeline/block_raster.hpp"
#include "pipeline/fixed_point.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/setup.hpp"
#include "shading/fragment.hpp"

namespace facet::pipeline {

// Largest tile edge the renderer accepts (RenderSettings::tile_size).
inline constexpr int kMaxTileSize = 128;

// One tile being rendered: owned by one task for the whole frame, so nothing here is shared.
struct TileContext {
  const Frame* frame = nullptr;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixel rectangle [x0, x1) x [y0, y1)
  int stride = 0;                      // pixels per row of the tile buffers
  glm::vec4* color = nullptr;          // linear RGBA
  float* depth = nullptr;
  // Per 8x8 block (row-major, blocks_x per row): no depth in the block is larger. Starts at the
  // clear depth; lowered when a triangle writes a whole block (raster_triangle).
  float* block_max_depth = nullptr;
  int blocks_x = 0;
  std::uint64_t pixels_shaded = 0;
};

// Shading models may opt out of the depth test (debug counters) and blend additively.
template <class Shading>
constexpr bool depth_tested() {
  if constexpr (requires { Shading::kDepthTest; }) return Shading::kDepthTest;
  return true;
}
template <class Shading>
constexpr bool additive() {
  if constexpr (requires { Shading::kAdditive; }) return Shading::kAdditive;
  return false;
}

// Models with kEdgeOverlay draw the triangle's edges over their shading: pixels closer to an
// edge than kOverlayHalfWidth pixels take the draw's wire color. Measured from the edge
// functions, so the edges sit exactly on the surface: no depth fighting with the fill.
template <class Shading>
constexpr bool edge_overlay() {
  if constexpr (requires { Shading::kEdgeOverlay; }) return Shading::kEdgeOverlay;
  return false;
}
inline constexpr float kOverlayHalfWidth = 0.5f;

// Distance in pixels from pixel (x, y)'s centre to the triangle's nearest edge (inside: >= 0).
inline float distance_to_edges(const SetupTriangle& t, int x, int y) {
  const std::int64_t cx = pixel_centre(x), cy = pixel_centre(y);
  float distance = std::numeric_limits<float>::max();
  for (int i = 0; i < 3; ++i) {
    const std::int64_t e = std::int64_t{t.a[i]} * cx + std::int64_t{t.b[i]} * cy + t.c[i];
    distance = std::min(distance, static_cast<float>(e) * t.edge_scale[i]);
  }
  return distance;
}

// Distance fog (the classic darkening with distance): a per-draw constant decides the mode,
// so this branch is perfectly predicted; a template flag would double every raster loop.
inline glm::vec4 apply_fog(glm::vec4 color, float view_depth, const Fog& fog) {
  if (fog.mode == FogMode::none) return color;
  float keep = fog.mode == FogMode::linear
                   ? (fog.end - view_depth) / std::max(fog.end - fog.start, 1e-6f)
                   : std::exp(-fog.density * view_depth);
  keep = std::clamp(keep, 0.0f, 1.0f);
  return {glm::mix(fog.color, glm::vec3(color), keep), color.a};
}

// Classifies the three edges at the four corners of the block rectangle in.[xy]_begin/end
// (exact, in 64 bits) and fills the 32-bit edge values cover_block steps with (block_raster.hpp
// says why 32 bits hold them). An edge inside at all four corners is inside at every pixel
// between them; false when one edge is outside at all four (no pixel covered).
inline bool classify_edges(const SetupTriangle& t, int block_x, int block_y, BlockInput& in) {
  for (int i = 0; i < 3; ++i) {
    const std::int64_t at_origin = std::int64_t{t.a[i]} * pixel_centre(block_x) +
                                   std::int64_t{t.b[i]} * pixel_centre(block_y) + t.c[i];
    const std::int64_t e = at_origin >> kSubpixelBits;  // floor(E / 256): arithmetic shift
    const std::int64_t ax0 = std::int64_t{t.a[i]} * in.x_begin,
                       ax1 = std::int64_t{t.a[i]} * (in.x_end - 1);
    const std::int64_t by0 = std::int64_t{t.b[i]} * in.y_begin,
                       by1 = std::int64_t{t.b[i]} * (in.y_end - 1);
    const std::int64_t c00 = e + ax0 + by0, c10 = e + ax1 + by0, c01 = e + ax0 + by1,
                       c11 = e + ax1 + by1;
    if ((c00 | c10 | c01 | c11) >= 0) {  // inside at every corner: no test needed
      in.e[i] = in.a[i] = in.b[i] = 0;
      continue;
    }
    if ((c00 & c10 & c01 & c11) < 0) return false;  // outside at every corner
    in.e[i] = static_cast<std::int32_t>(e);
    in.a[i] = t.a[i];
    in.b[i] = t.b[i];
  }
  return true;
}

// Bits of the block pixels that lie inside the tile (all 64 except at the frame's right and
// bottom edges).
inline std::uint64_t block_pixels_mask(int width, int height) {
  const std::uint64_t row = (std::uint64_t{1} << width) - 1;
  std::uint64_t mask = 0;
  for (int y = 0; y < height; ++y) mask |= row << (y * kBlockSize);
  return mask;
}

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
    out = color;
  }
}

// Rasterizes one triangle into the tile; a template over the shading model and the alpha
// mode so that the per-pixel loop is specialised once per draw state (shade.cpp builds the
// table). The triangle's bounding box is walked in 8x8 blocks:
//   1. blocks every edge keeps out are skipped, and edges that cover a block are not tested;
//   2. blocks whose nearest triangle depth is behind everything drawn there are skipped
//      (tile.block_max_depth, a per-block bound on the depth buffer: hierarchical depth);
//   3. cover_block finds the covered pixels that pass the depth test, with their depth and
//      varyings, SIMD across a block row;
//   4. those pixels are shaded one at a time and written.
template <class Shading, AlphaMode kAlpha = AlphaMode::opaque>
void raster_triangle(TileContext& tile, const SetupTriangle& t) {
  const int x0 = std::max(t.min_x, tile.x0), x1 = std::min(t.max_x, tile.x1 - 1);
  const int y0 = std::max(t.min_y, tile.y0), y1 = std::min(t.max_y, tile.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  const shading::DrawUniforms& uniforms = tile.frame->draws[t.draw].uniforms;
  const Fog& fog = uniforms.lighting->fog;
  const float alpha_cutoff = uniforms.material->alpha_cutoff;
  constexpr bool kDepthTest = depth_tested<Shading>();
  // Blended draws test depth but do not write it (they are sorted back to front instead).
  constexpr bool kDepthWrite =
      kDepthTest && (kAlpha == AlphaMode::opaque || kAlpha == AlphaMode::mask);
  // Writes that leave every pixel of a block at a depth we know: the block's bound can drop.
  constexpr bool kTightensBound = kDepthWrite && kAlpha == AlphaMode::opaque;
  shading::Fragment f;
  f.planes = tile.frame->planes.data() + t.varying_planes;
  f.inv_w = &t.inv_w;
  BlockInput in;
  in.triangle = &t;
  in.varying_planes = f.planes;
  in.varyings = Shading::kVaryings;
  in.depth_test = kDepthTest;
  in.depth_stride = tile.stride;
  alignas(64) BlockFragments block;
  std::uint64_t shaded = 0;
  for (int by = (y0 - tile.y0) / kBlockSize; by <= (y1 - tile.y0) / kBlockSize; ++by) {
    const int block_y = tile.y0 + by * kBlockSize;
    in.y_begin = std::max(y0, block_y) - block_y;
    in.y_end = std::min(y1, block_y + kBlockSize - 1) - block_y + 1;
    for (int bx = (x0 - tile.x0) / kBlockSize; bx <= (x1 - tile.x0) / kBlockSize; ++bx) {
      const int block_x = tile.x0 + bx * kBlockSize;
      in.x_begin = std::max(x0, block_x) - block_x;
      in.x_end = std::min(x1, block_x + kBlockSize - 1) - block_x + 1;
      if (!classify_edges(t, block_x, block_y, in)) continue;
      in.px0 = static_cast<float>(block_x) + 0.5f;
      in.py0 = static_cast<float>(block_y) + 0.5f;
      float& max_depth = tile.block_max_depth[by * tile.blocks_x + bx];
      if constexpr (kDepthTest) {
        const float nearest = depth_range_over(t, block_x + in.x_begin, block_y + in.y_begin,
                                               block_x + in.x_end - 1, block_y + in.y_end - 1)
                                  .nearest;
        if (nearest >= max_depth) continue;  // every pixel fails "less"; NaN goes on
      }
      const std::ptrdiff_t block_offset =
          static_cast<std::ptrdiff_t>(block_y - tile.y0) * tile.stride + (block_x - tile.x0);
      in.depth = tile.depth + block_offset;
      cover_block(in, block);
      std::uint64_t written = 0;
      for (std::uint64_t m = block.mask; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        const int x = i % kBlockSize, y = i / kBlockSize;
        f.w = block.w[i];
        for (int k = 0; k < Shading::kVaryings; ++k) f.v[k] = block.v[k][i];
        glm::vec4 color = Shading::fragment(f, uniforms);
        if constexpr (kAlpha == AlphaMode::mask) {
          if (!(color.a >= alpha_cutoff)) continue;  // cut-out: no color, no depth
        }
        if constexpr (edge_overlay<Shading>()) {
          if (distance_to_edges(t, block_x + x, block_y + y) < kOverlayHalfWidth) {
            color = uniforms.wire_color;
          }
        }
        color = apply_fog(color, f.w, fog);
        const std::ptrdiff_t pixel =
            block_offset + static_cast<std::ptrdiff_t>(y) * tile.stride + x;
        blend_into<Shading, kAlpha>(tile.color[pixel], color);
        if constexpr (kDepthWrite) tile.depth[pixel] = block.z[i];
        written |= std::uint64_t{1} << i;
        ++shaded;
      }
      if constexpr (kTightensBound) {
        // Every pixel of the block written by this triangle: their largest depth bounds it.
        const std::uint64_t all = block_pixels_mask(std::min(kBlockSize, tile.x1 - block_x),
                                                    std::min(kBlockSize, tile.y1 - block_y));
        if (written == all) {
          float largest = 0.0f;
          for (std::uint64_t m = all; m != 0; m &= m - 1) {
            largest = std::max(largest, block.z[std::countr_zero(m)]);
          }
          max_depth = std::min(max_depth, largest);
        }
      }
    }
  }
  tile.pixels_shaded += shaded;
}

// Rasterizes one segment into the tile (line.cpp).
void raster_line(TileContext& tile, const SetupLine& line);

}  // namespace facet::pipeline
