// Stage: raster + shade. Reads one tile's bin (bin.cpp) and, for each triangle in submission
// order, finds the covered pixel centres with the fixed-point edge functions set up in
// setup.cpp, tests depth early, shades with the draw's shading model and writes the tile's
// own color and depth buffers; output.cpp then resolves the tile to the framebuffer.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/vec4.hpp>
#include <limits>
#include <type_traits>
#include <variant>

#include "pipeline/block_raster.hpp"
#include "pipeline/fixed_point.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/setup.hpp"
#include "shading/fog.hpp"
#include "shading/fragment.hpp"
#include "shading/shade_batch.hpp"
#include "shading/texel_batch.hpp"

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

// The varying slot of the texture coordinate a model reads its base color map at (through
// shading::base_color_texel), or -1: such models have the map sampled ahead, a batch of pixels
// at a time (shading/texel_batch.hpp).
template <class Shading>
constexpr int base_color_texcoord() {
  if constexpr (requires { Shading::kBaseColorTexcoord; }) return Shading::kBaseColorTexcoord;
  return -1;
}

// Models with fragment_batch are shaded a batch of pixels at a time with SIMD when their
// batch_shades accepts the draw (shading/shade_batch.hpp).
template <class Shading>
constexpr bool batch_shaded() {
  return requires { &Shading::fragment_batch; };
}

// Covered pixels of one triangle that passed the depth test, packed, waiting to be shaded: a
// block's or a small triangle's worth at most.
struct PackedPixels {
  static constexpr int kCapacity = kBlockPixels;
  int count = 0;
  std::int16_t x[kCapacity], y[kCapacity];
  alignas(64) float z[kCapacity];
  alignas(64) float w[kCapacity];
  alignas(64) float v[kMaxVaryings][kCapacity];

  // Zeroes the entries from count up to the next multiple of 8 (position, depth, w and the
  // first `varyings` varyings), which the SIMD code reads (and ignores).
  void pad(int varyings) {
    for (int n = count; n % 8 != 0; ++n) {
      x[n] = y[n] = 0;
      z[n] = w[n] = 0.0f;
      for (int k = 0; k < varyings; ++k) v[k][n] = 0.0f;
    }
  }
};
static_assert(PackedPixels::kCapacity == shading::kTexelBatch &&
              PackedPixels::kCapacity == shading::kShadeBatch);

// 1 / |(a, b)| of each edge, in pixels: E_i times it is the distance to edge i in pixels (E is
// in fixed-point units, hence the sub-pixel scale). Only the wire overlay view needs them, so
// setup does not pay for the square roots; PixelWriter computes them once per triangle.
struct EdgeScales {
  double per_unit[3];
  explicit EdgeScales(const SetupTriangle& t) {
    for (int i = 0; i < 3; ++i) {
      const double length = std::sqrt(double(t.a[i]) * t.a[i] + double(t.b[i]) * t.b[i]);
      per_unit[i] = 1.0 / (length * kSubpixelScale);
    }
  }
};

// Distance in pixels from pixel (x, y)'s centre to the triangle's nearest edge (inside: >= 0).
inline float distance_to_edges(const SetupTriangle& t, const EdgeScales& scales, int x, int y) {
  const std::int64_t cx = pixel_centre(x), cy = pixel_centre(y);
  double distance = std::numeric_limits<double>::max();
  for (int i = 0; i < 3; ++i) {
    const std::int64_t e = std::int64_t{t.a[i]} * cx + std::int64_t{t.b[i]} * cy + t.c[i];
    distance = std::min(distance, static_cast<double>(e) * scales.per_unit[i]);
  }
  return static_cast<float>(distance);
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
    // Channel by channel: GCC assembles `color` in memory from 4- and 8-byte pieces, and a
    // 16-byte copy reloading them stalled store forwarding (a third of the normals view's
    // raster loop).
    out.r = color.r;
    out.g = color.g;
    out.b = color.b;
    out.a = color.a;
  }
}

// Fewer packed pixels than this are shaded one at a time with fragment() even when the model
// has a batch form: the batch call's fixed cost outweighs its SIMD for them (bunny-far, the
// normals view of tiny triangles, 8 % faster with 4 than with 1; 8 made islands 3.5 % slower).
inline constexpr int kMinBatch = 4;

// Shades one covered pixel that passed the depth test and writes it with the draw's blending:
// the part of the raster loop that is the same for every path below.
template <class Shading, AlphaMode kAlpha>
class PixelWriter {
  static auto make_edge_scales(const SetupTriangle& t) {
    if constexpr (edge_overlay<Shading>()) {
      return EdgeScales(t);
    } else {
      return std::monostate{};
    }
  }

 public:
  // Blended draws test depth but do not write it (they are sorted back to front instead).
  static constexpr bool kDepthWrite =
      depth_tested<Shading>() && (kAlpha == AlphaMode::opaque || kAlpha == AlphaMode::mask);

  PixelWriter(TileContext& tile, const SetupTriangle& t)
      : tile_(tile),
        t_(t),
        uniforms_(tile.frame->draws[t.draw].uniforms),
        fog_(uniforms_.lighting->fog),
        alpha_cutoff_(uniforms_.material->alpha_cutoff),
        edge_scales_(make_edge_scales(t)) {
    fragment.planes = tile.frame->planes.data() + t.varying_planes;
    fragment.inv_w = &t.inv_w;
    if constexpr (kTexcoordSlot >= 0) {
      if (uniforms_.material->base_color_map) base_map_ = &uniforms_.material->base_color_map;
    }
    if constexpr (batch_shaded<Shading>()) batch_ = tile.frame->draws[t.draw].batch_shaded;
  }

  // Shades the packed pixels and writes them; returns how many were written (the alpha test
  // may discard some). The base color map is sampled for all of them at once, and models
  // with a batch form are shaded all at once (from kMinBatch pixels on), both with SIMD.
  int shade(PackedPixels& pixels) {
    if (pixels.count == 0) return 0;
    if (batches()) pixels.pad(Shading::kVaryings);
    const Texels texels = sample_base_map(pixels.count, pixels.v, pixels.w);
    int written = 0;
    if constexpr (batch_shaded<Shading>()) {
      if (batch_ && pixels.count >= kMinBatch) {
        alignas(64) float colors[PackedPixels::kCapacity][4];
        Shading::fragment_batch(uniforms_, {pixels.count, pixels.w, pixels.v, texels, batch_fog()},
                                colors);
        for (int n = 0; n < pixels.count; ++n) {
          const float* c = colors[n];
          written += store<kBatchFogs>(pixels.x[n], pixels.y[n], pixels.z[n], pixels.w[n],
                                       glm::vec4(c[0], c[1], c[2], c[3]));
        }
        return written;
      }
    }
    for (int n = 0; n < pixels.count; ++n) {
      fragment.w = pixels.w[n];
      for (int k = 0; k < Shading::kVaryings; ++k) fragment.v[k] = pixels.v[k][n];
      if (texels != nullptr) {
        fragment.base_texel = {texels[n][0], texels[n][1], texels[n][2], texels[n][3]};
        fragment.base_texel_ready = true;
      }
      written += write(pixels.x[n], pixels.y[n], pixels.z[n]);
    }
    return written;
  }

  // Whether shade_full_block() can take this draw's blocks: opaque, depth-writing, batch-
  // shaded, no wire overlay (all known here but the draw's lights and material:
  // DrawRecord::batch_shaded).
  static constexpr bool kFullBlocks = batch_shaded<Shading>() && kAlpha == AlphaMode::opaque &&
                                      kDepthWrite && !edge_overlay<Shading>();
  bool full_blocks() const { return kFullBlocks && batch_; }

  // A block whose 64 pixels are all covered and pass the depth test, at frame pixel
  // (block_x, block_y): sampled, shaded and fogged with SIMD straight from cover_block's
  // arrays, then copied into the tile a row at a time; no per-pixel step. Only when
  // full_blocks().
  void shade_full_block(const BlockFragments& block, int block_x, int block_y) {
    if constexpr (kFullBlocks) {
      const Texels texels = sample_base_map(kBlockPixels, block.v, block.w);
      alignas(64) float colors[kBlockPixels][4];
      Shading::fragment_batch(uniforms_, {kBlockPixels, block.w, block.v, texels, &fog_}, colors);
      const std::ptrdiff_t first =
          static_cast<std::ptrdiff_t>(block_y - tile_.y0) * tile_.stride + (block_x - tile_.x0);
      for (int row = 0; row < kBlockSize; ++row) {
        const std::ptrdiff_t pixel = first + static_cast<std::ptrdiff_t>(row) * tile_.stride;
        std::memcpy(&tile_.color[pixel], colors[row * kBlockSize], sizeof(float) * 4 * kBlockSize);
        std::memcpy(&tile_.depth[pixel], block.z + row * kBlockSize, sizeof(float) * kBlockSize);
      }
      shaded += kBlockPixels;
    }
  }

  // Whether shade() does anything in batches; if not, raster loops may skip packing and call
  // write() per pixel.
  bool batches() const { return base_map_ != nullptr || batch_; }

  // Shades `fragment` (w and varyings filled in by the caller) for pixel (x, y) of the frame
  // at depth z and writes it. False if the alpha test discarded it.
  bool write(int x, int y, float z) {
    return store(x, y, z, fragment.w, Shading::fragment(fragment, uniforms_));
  }

  // Writes the shaded color of pixel (x, y) of the frame, at depth z and clip w, with the
  // draw's alpha test, overlay, fog and blending.
  // kFogged: the color has had its fog already (shade_batch applies it).
  template <bool kFogged = false>
  bool store(int x, int y, float z, float w, glm::vec4 color) {
    if constexpr (kAlpha == AlphaMode::mask) {
      if (!(color.a >= alpha_cutoff_)) return false;  // cut-out: no color, no depth
    }
    if constexpr (edge_overlay<Shading>()) {
      if (distance_to_edges(t_, edge_scales_, x, y) < kOverlayHalfWidth) {
        color = uniforms_.wire_color;
      }
    }
    if constexpr (!kFogged) shading::apply_fog(color, w, fog_);
    const std::ptrdiff_t pixel =
        static_cast<std::ptrdiff_t>(y - tile_.y0) * tile_.stride + (x - tile_.x0);
    blend_into<Shading, kAlpha>(tile_.color[pixel], color);
    if constexpr (kDepthWrite) tile_.depth[pixel] = z;
    ++shaded;
    return true;
  }

  shading::Fragment fragment;
  std::uint64_t shaded = 0;

 private:
  static constexpr int kTexcoordSlot = base_color_texcoord<Shading>();  // -1: none

  // The base color map sampled for `count` pixels whose varyings and clip w are v[k][n] and
  // w[n] (PackedPixels and BlockFragments alike): their texels, or null when the model reads
  // no map or the draw has none.
  using Texels = const float (*)[4];
  Texels sample_base_map(int count, const float (*v)[kBlockPixels], const float* w) {
    if constexpr (kTexcoordSlot >= 0) {
      if (base_map_) {
        texels_.count = count;
        texels_.u = v[kTexcoordSlot];
        texels_.v = v[kTexcoordSlot + 1];
        texels_.w = w;
        shading::sample_batch(*base_map_, fragment.planes + kTexcoordSlot, t_.inv_w, texels_);
        return texels_.rgba;
      }
    }
    return nullptr;
  }

  // The batch shader fogs, except under the wire overlay, whose wire color store() fogs.
  static constexpr bool kBatchFogs = !edge_overlay<Shading>();
  const Fog* batch_fog() const { return kBatchFogs ? &fog_ : nullptr; }
  TileContext& tile_;
  const SetupTriangle& t_;
  const shading::DrawUniforms& uniforms_;
  const Fog& fog_;
  float alpha_cutoff_;
  // Only the wire overlay reads it (an empty struct otherwise, and never computed).
  [[no_unique_address]] std::conditional_t<edge_overlay<Shading>(), EdgeScales, std::monostate>
      edge_scales_;
  const TextureMap* base_map_ = nullptr;  // the map sampled ahead, if any
  bool batch_ = false;                    // shade() uses Shading::fragment_batch
  shading::TexelBatch texels_;
};

// Triangles whose bounding box in the tile is at most this many pixels skip the block
// machinery: for them, one pixel at a time is cheaper than classifying and dispatching blocks
// (measured on bunny-close and million: 16 to 256 all gain on 0, 64 at least as much as any).
inline constexpr int kSmallTrianglePixels = 64;

// The loop over the bounding box [x0, x1] x [y0, y1] (inclusive), for small triangles: finds
// the covered pixels that pass the depth test one at a time, then interpolates their varyings
// with SIMD (interpolate_pixels) and shades them. Same arithmetic as cover_block, so the same
// pixels get the same values.
template <class Shading, AlphaMode kAlpha>
void raster_small_triangle(TileContext& tile, const SetupTriangle& t, int x0, int y0, int x1,
                           int y1, PixelWriter<Shading, kAlpha>& out) {
  static_assert(kSmallTrianglePixels <= PackedPixels::kCapacity);
  PackedPixels found;
  // Without branches: every pixel of the box is written to the next free entry, which only
  // the covered ones that pass the depth test claim (whether a box pixel is covered is as
  // good as random to the branch predictor).
  const float* depth = tile.depth;
  const std::int64_t step[3] = {std::int64_t{t.a[0]} * kSubpixelScale,
                                std::int64_t{t.a[1]} * kSubpixelScale,
                                std::int64_t{t.a[2]} * kSubpixelScale};
  int count = 0;
  for (int y = y0; y <= y1; ++y) {
    const std::int64_t cy = pixel_centre(y), cx = pixel_centre(x0);
    std::int64_t e[3];
    for (int i = 0; i < 3; ++i)
      e[i] = std::int64_t{t.a[i]} * cx + std::int64_t{t.b[i]} * cy + t.c[i];
    const float py = static_cast<float>(y) + 0.5f;
    const float z_row = evaluate_row(t.z, t.ref_y, py);
    const float* depth_row =
        depth + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride - tile.x0;
    for (int x = x0; x <= x1; ++x) {
      bool pass = (e[0] | e[1] | e[2]) >= 0;
      for (int i = 0; i < 3; ++i) e[i] += step[i];
      const float z = evaluate_in_row(z_row, t.z, t.ref_x, static_cast<float>(x) + 0.5f);
      if constexpr (depth_tested<Shading>()) pass &= z < depth_row[x];  // less; NaN fails
      found.x[count] = static_cast<std::int16_t>(x);
      found.y[count] = static_cast<std::int16_t>(y);
      found.z[count] = z;
      count += pass;
    }
  }
  found.count = count;
  if (found.count == 0) return;
  found.pad(0);  // interpolate_pixels reads whole vectors of positions
  interpolate_pixels(t, out.fragment.planes, Shading::kVaryings, found.count, found.x, found.y,
                     found.w, found.v);
  out.shade(found);
}

// Rasterizes one triangle into the tile; a template over the shading model and the alpha
// mode so that the per-pixel loop is specialised once per draw state (shade.cpp builds the
// table). Small triangles take raster_small_triangle; the others are walked in 8x8 blocks:
//   1. blocks every edge keeps out are skipped, and edges that cover a block are not tested;
//   2. blocks whose nearest triangle depth is behind everything drawn there are skipped
//      (tile.block_max_depth, a per-block bound on the depth buffer: hierarchical depth);
//   3. cover_block finds the covered pixels that pass the depth test, with their depth and
//      varyings, SIMD across a block row;
//   4. those pixels are shaded and written (PixelWriter::shade): the base color map sampled
//      and models with a batch form (fragment_batch) evaluated for all of them at once with
//      SIMD, other models one pixel at a time; whole covered blocks of opaque batch-shaded
//      draws go straight into the tile (shade_full_block).
template <class Shading, AlphaMode kAlpha = AlphaMode::opaque>
void raster_triangle(TileContext& tile, const SetupTriangle& t) {
  const int x0 = std::max(t.min_x, tile.x0), x1 = std::min(t.max_x, tile.x1 - 1);
  const int y0 = std::max(t.min_y, tile.y0), y1 = std::min(t.max_y, tile.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  PixelWriter<Shading, kAlpha> out(tile, t);
  if ((x1 - x0 + 1) * (y1 - y0 + 1) <= kSmallTrianglePixels) {
    raster_small_triangle(tile, t, x0, y0, x1, y1, out);
    tile.pixels_shaded += out.shaded;
    return;
  }
  constexpr bool kDepthTest = depth_tested<Shading>();
  // Writes that leave every pixel of a block at a depth we know: the block's bound can drop.
  constexpr bool kTightensBound =
      PixelWriter<Shading, kAlpha>::kDepthWrite && kAlpha == AlphaMode::opaque;
  BlockInput in;
  in.triangle = &t;
  in.varying_planes = out.fragment.planes;
  in.varyings = Shading::kVaryings;
  in.depth_test = kDepthTest;
  in.depth_stride = tile.stride;
  alignas(64) BlockFragments block;
  PackedPixels pixels;
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
      if (block.mask == 0) continue;
      if (block.mask == ~std::uint64_t{0} && out.full_blocks()) {
        out.shade_full_block(block, block_x, block_y);
        if constexpr (kTightensBound) {
          float largest = 0.0f;
          for (int i = 0; i < kBlockPixels; ++i) largest = std::max(largest, block.z[i]);
          max_depth = std::min(max_depth, largest);
        }
        continue;
      }
      int written = 0;
      if (out.batches()) {
        pixels.count = 0;
        for (std::uint64_t m = block.mask; m != 0; m &= m - 1) {
          const int i = std::countr_zero(m);
          const int n = pixels.count++;
          pixels.x[n] = static_cast<std::int16_t>(block_x + i % kBlockSize);
          pixels.y[n] = static_cast<std::int16_t>(block_y + i / kBlockSize);
          pixels.z[n] = block.z[i];
          pixels.w[n] = block.w[i];
          for (int k = 0; k < Shading::kVaryings; ++k) pixels.v[k][n] = block.v[k][i];
        }
        written = out.shade(pixels);
      } else {
        for (std::uint64_t m = block.mask; m != 0; m &= m - 1) {
          const int i = std::countr_zero(m);
          out.fragment.w = block.w[i];
          for (int k = 0; k < Shading::kVaryings; ++k) out.fragment.v[k] = block.v[k][i];
          written += out.write(block_x + i % kBlockSize, block_y + i / kBlockSize, block.z[i]);
        }
      }
      if constexpr (kTightensBound) {
        // Every pixel of the block written by this triangle: their largest depth bounds it.
        const std::uint64_t all = block_pixels_mask(std::min(kBlockSize, tile.x1 - block_x),
                                                    std::min(kBlockSize, tile.y1 - block_y));
        if (block.mask == all && written == std::popcount(all)) {
          float largest = 0.0f;
          for (std::uint64_t m = all; m != 0; m &= m - 1) {
            largest = std::max(largest, block.z[std::countr_zero(m)]);
          }
          max_depth = std::min(max_depth, largest);
        }
      }
    }
  }
  tile.pixels_shaded += out.shaded;
}

// Rasterizes one segment into the tile (line.cpp).
void raster_line(TileContext& tile, const SetupLine& line);

}  // namespace facet::pipeline
