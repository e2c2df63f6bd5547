// Stage: raster + shade, the part every raster path shares: covered pixels packed for shading
// (PackedPixels), and PixelWriter, which shades them with the draw's model (a batch at a time
// with SIMD where the model allows) and writes them into the tile (tile_context.hpp) with the
// draw's blending (sample_writer.hpp).
#pragma once

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/vec4.hpp>
#include <limits>
#include <type_traits>
#include <variant>

#include "pipeline/frame.hpp"
#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/model_traits.hpp"
#include "pipeline/raster/sample_writer.hpp"
#include "pipeline/raster/tile_context.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "pipeline/setup/sample_positions.hpp"
#include "shading/fragment.hpp"
#include "shading/kernels.hpp"
#include "shading/shade_batch.hpp"
#include "shading/texel_batch.hpp"

namespace facet::pipeline {

// Covered pixels that passed the depth test, packed, waiting to be shaded: those of a triangle's
// partly covered blocks (raster.hpp), a small triangle's or several small triangles' of one draw
// (WaitingPixels) at most.
struct PackedPixels {
  static constexpr int kCapacity = kBlockPixels;
  int count = 0;
  // Positions have room for as many again: a block's or a small triangle's pixels may be found
  // past a full batch before they move to the front of the next (raster.hpp, WaitingPixels); and
  // for the whole vectors the search stores past the last it finds. Depths, like w, come from
  // interpolate_pixels.
  std::int16_t x[2 * kCapacity + kBoxSearchSlack], y[2 * kCapacity + kBoxSearchSlack];
  alignas(64) float z[kCapacity];
  alignas(64) float w[kCapacity];
  alignas(64) float v[kMaxVaryings][kCapacity];

  // Zeroes the 7 positions after count, which interpolate_pixels may read (and ignore) past the
  // pixels it interpolates.
  void pad_positions() {
    std::fill_n(x + count, 7, std::int16_t{0});
    std::fill_n(y + count, 7, std::int16_t{0});
  }

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
  double distance = std::numeric_limits<double>::max();
  for (int i = 0; i < 3; ++i) {
    const auto e = static_cast<double>(edge_at_centre(t, i, x, y));
    distance = std::min(distance, e * scales.per_unit[i]);
  }
  return static_cast<float>(distance);
}

// Shades one covered pixel that passed the depth test and writes it with the draw's blending:
// the part of the raster loop that is the same for every path (raster.hpp, small_triangles.hpp).
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
  // A tile of codes takes the wire overlay's pixels from nothing (store_codes_all).
  static_assert(!display_referred<Shading>() || !edge_overlay<Shading>());

  // Blended draws test depth but do not write it (they are sorted back to front instead).
  static constexpr bool kDepthWrite =
      depth_tested<Shading>() && (kAlpha == AlphaMode::opaque || kAlpha == AlphaMode::mask);

  PixelWriter(TileContext& tile, const SetupTriangle& t)
      : PixelWriter(tile, t.draw, &t, make_edge_scales(t)) {
    fragment.planes = tile.frame->planes.data() + t.varying_planes;
    fragment.inv_w = &t.inv_w;
  }

  // For the pixels of several triangles of draw `draw` (shade_waiting()).
  PixelWriter(TileContext& tile, std::uint32_t draw) : PixelWriter(tile, draw, nullptr, {}) {}

  // Shades the packed pixels and writes them; returns how many were written (the alpha test
  // may discard some). The material's maps are sampled for all of them at once, and models
  // with a batch form are shaded all at once, both with SIMD.
  int shade(PackedPixels& pixels) {
    if (pixels.count == 0) return 0;
    if (batches()) pixels.pad(Shading::kVaryings);
    if constexpr (batch_shaded<Shading>()) {
      alignas(64) float colors[PackedPixels::kCapacity][4];
      shading::ShadeInput in{pixels.count, pixels.w, pixels.z, pixels.v, nullptr, batch_fog()};
      sample_maps(in, pixels.v, pixels.w);
      alignas(64) std::uint32_t codes[PackedPixels::kCapacity];
      if (tile_.codes != nullptr) in.codes = codes;
      Shading::fragment_batch(uniforms_, in, colors);
      if (tile_.codes != nullptr) return store_codes_all(pixels, codes);
      return store_all(pixels, colors, kBatchFogs);
    } else {
      return shade_one_at_a_time(pixels);
    }
  }

  // shade() for the models without a batch form: fragment() per pixel, the base color map
  // sampled ahead and the fog applied to all of them at once all the same.
  int shade_one_at_a_time(PackedPixels& pixels) {
    const Texels texels = sample_base_map(pixels.count, pixels.v, pixels.w);
    alignas(64) float colors[PackedPixels::kCapacity][4];
    for (int n = 0; n < pixels.count; ++n) {
      fragment.w = pixels.w[n];
      fragment.z = pixels.z[n];
      for (int k = 0; k < Shading::kVaryings; ++k) fragment.v[k] = pixels.v[k][n];
      if (texels != nullptr) {
        fragment.base_texel = {texels[n][0], texels[n][1], texels[n][2], texels[n][3]};
      }
      const glm::vec4 color = Shading::fragment(fragment, uniforms_);
      for (int c = 0; c < 4; ++c) colors[n][c] = color[c];
    }
    return store_all(pixels, colors, false);
  }

  // Writes the packed pixels' colors (store()), fogging them first unless `fogged`, and the
  // wire overlay's wire color too; returns how many were written.
  int store_all(const PackedPixels& pixels, float (*colors)[4], bool fogged) {
    if (!fogged) fog(pixels, colors);
    int written = 0;
    if constexpr (edge_overlay<Shading>()) {
      alignas(64) float wires[PackedPixels::kCapacity][4];
      const glm::vec4& wire = uniforms_.material->wire_color;
      for (int n = 0; n < pixels.count; ++n) {
        for (int c = 0; c < 4; ++c) wires[n][c] = wire[c];
      }
      fog(pixels, wires);
      for (int n = 0; n < pixels.count; ++n) {
        const float *c = colors[n], *w = wires[n];
        written += store(pixels.x[n], pixels.y[n], pixels.z[n], glm::vec4(c[0], c[1], c[2], c[3]),
                         glm::vec4(w[0], w[1], w[2], w[3]));
      }
    } else {
      for (int n = 0; n < pixels.count; ++n) {
        const float* c = colors[n];
        written += store(pixels.x[n], pixels.y[n], pixels.z[n], glm::vec4(c[0], c[1], c[2], c[3]));
      }
    }
    return written;
  }

  // store_all() into a tile of codes (TileContext::codes), of the codes a display-referred
  // model's batch form gave the packed pixels (ShadeInput::codes): their alpha is 1, which the
  // alpha test of a cut-out draw passes or fails for all of them, and such frames have no fog
  // and their models no wire overlay.
  int store_codes_all(const PackedPixels& pixels, const std::uint32_t* codes) {
    if constexpr (kAlpha == AlphaMode::mask) {
      if (!(1.0f >= alpha_cutoff_)) return 0;
    }
    // In locals: a code's store may alias the count.
    std::uint32_t* const tile_codes = tile_.codes;
    const int count = pixels.count;
    for (int n = 0; n < count; ++n) {
      const std::ptrdiff_t pixel = index(pixels.x[n], pixels.y[n]);
      tile_codes[pixel] = codes[n];
      if constexpr (kDepthWrite) tile_.depth[pixel] = pixels.z[n];
    }
    shaded += static_cast<std::uint64_t>(pixels.count);
    return pixels.count;
  }

  // The fog of the frame on the colors of the packed pixels, in place, with the shading
  // kernel's fog.
  void fog(const PackedPixels& pixels, float (*rgba)[4]) const {
    if (fog_.mode == FogMode::none) return;
    const shading::ShadeInput in{pixels.count, pixels.w, pixels.z, nullptr, nullptr, &fog_};
    uniforms_.frame->kernels->fog_batch(uniforms_, in, rgba);
  }

  // Whether shade_full_block() takes this draw's whole blocks: opaque, depth-writing, batch-
  // shaded, no wire overlay.
  static constexpr bool kFullBlocks = batch_shaded<Shading>() && kAlpha == AlphaMode::opaque &&
                                      kDepthWrite && !edge_overlay<Shading>();
  bool full_blocks() const { return kFullBlocks; }

  // Whether the draw's small triangles may wait to be shaded with the next ones
  // (WaitingPixels): as for whole blocks, and depth-tested (a waiting pixel is tested again
  // when written).
  static constexpr bool kWaits = kFullBlocks && depth_tested<Shading>();

  // The waiting pixels of several triangles of the draw, whose plane slopes for the base
  // color map's level of detail are slopes[k][n] (TexelBatch): sampled and shaded with SIMD,
  // fogged, into colors, or, where `codes` is not null (a tile of codes), into their codes
  // (ShadeInput::codes); write_waiting (small_triangles.hpp) tests and stores them.
  void shade_waiting(PackedPixels& pixels, const float (*slopes)[PackedPixels::kCapacity],
                     float (*colors)[4], std::uint32_t* codes) {
    if constexpr (kWaits) {
      pixels.pad(Shading::kVaryings);
      shading::ShadeInput in{pixels.count, pixels.w, pixels.z, pixels.v, nullptr, &fog_};
      in.codes = codes;
      sample_maps(in, pixels.v, pixels.w, slopes);
      Shading::fragment_batch(uniforms_, in, colors);
    }
  }

  // A block whose 64 pixels are all covered and pass the depth test, at frame pixel
  // (block_x, block_y): sampled, shaded and fogged with SIMD straight from cover_block's
  // arrays into the tile's rows; no per-pixel step. Its depths are the caller's to write (one
  // sample's, or each sample's under MSAA). Only when full_blocks().
  void shade_full_block(const BlockFragments& block, int block_x, int block_y) {
    if constexpr (kFullBlocks) {
      static_assert(kBlockSize == 8, "ShadeInput::rgba_row_stride counts rows of 8 pixels");
      const std::ptrdiff_t first = index(block_x, block_y);
      shading::ShadeInput in{kBlockPixels, block.w, block.z, block.v, nullptr, &fog_};
      in.rgba_row_stride = tile_.stride;
      in.opaque = !writes_data<Shading>();  // alpha 1, as blend_into writes it
      sample_maps(in, block.v, block.w);
      // A tile of codes takes them from the display-referred models' batch forms, the only
      // ones its frames draw (ShadeInput::codes).
      if (tile_.codes != nullptr) in.codes = tile_.codes + first;
      Shading::fragment_batch(uniforms_, in, reinterpret_cast<float(*)[4]>(&tile_.color[first]));
      shaded += kBlockPixels;
    }
  }

  // Whether shade() does anything in batches; if not, raster loops may skip packing and call
  // write() per pixel. Always for the models without fragment(), and under fog (fogged a
  // batch at a time).
  bool batches() const {
    return batch_shaded<Shading>() || base_map_ != nullptr || fog_.mode != FogMode::none;
  }

  // Shades `fragment` (w and varyings filled in by the caller) for pixel (x, y) of the frame
  // at depth z and writes it. False if the alpha test discarded it. Only for the models with
  // fragment() and without fog (the others' batches() is always true).
  bool write(int x, int y, float z) requires(!batch_shaded<Shading>()) {
    assert(fog_.mode == FogMode::none);
    fragment.z = z;
    return store(x, y, z, Shading::fragment(fragment, uniforms_), uniforms_.material->wire_color);
  }

  // Writes the shaded (and fogged) color of pixel (x, y) of the frame at depth z, with the
  // draw's alpha test, wire overlay (`wire`, the wire's color fogged likewise, where the pixel is
  // near an edge; only models with the overlay read it, and every caller for them passes it) and
  // blending.
  bool store(int x, int y, float z, glm::vec4 color, const glm::vec4& wire = glm::vec4(0.0f)) {
    if constexpr (kAlpha == AlphaMode::mask) {
      if (tile_.samples > 1) {
        // Alpha to coverage: the cut-out's edge falls across the samples.
        const std::ptrdiff_t pixel = index(x, y);
        tile_.sample_mask[pixel] &= alpha_to_coverage(color.a, alpha_cutoff_, tile_.samples);
        if (tile_.sample_mask[pixel] == 0) return false;
      } else if (!(color.a >= alpha_cutoff_)) {
        return false;  // cut-out: no color, no depth
      }
    }
    if constexpr (edge_overlay<Shading>()) {
      if (distance_to_edges(*t_, edge_scales_, x, y) < kOverlayHalfWidth) color = wire;
    }
    const std::ptrdiff_t pixel = index(x, y);
    if (tile_.samples > 1) {
      store_samples(pixel, z, color);
    } else if (tile_.codes != nullptr) {
      store_codes(pixel, color);
      if constexpr (kDepthWrite) tile_.depth[pixel] = z;
    } else {
      blend_into<Shading, kAlpha>(tile_.color[pixel], color);
      if constexpr (kDepthWrite) tile_.depth[pixel] = z;
    }
    ++shaded;
    return true;
  }

  // The codes of `color` into a tile of codes (TileContext::codes), whose draws are display-
  // referred, opaque or cut out: blend_into reads nothing of what was there.
  void store_codes(std::ptrdiff_t pixel, const glm::vec4& color) {
    glm::vec4 written(0.0f);
    blend_into<Shading, kAlpha>(written, color);
    tile_.codes[pixel] = display_codes(*tile_.frame->kernels, written);
  }

  // MSAA: writes the pixel's color, shaded once, to the samples tile.sample_mask says, each
  // with its own depth and blending.
  void store_samples(std::ptrdiff_t pixel, float z, const glm::vec4& color) {
    const SampleWriter<Shading, kAlpha, kDepthWrite> samples(tile_, tile_.sample_z);
    samples.write(pixel, tile_.sample_mask[pixel], z, color);
  }

  shading::Fragment fragment;
  std::uint64_t shaded = 0;

 private:
  static constexpr int kTexcoordSlot = base_color_texcoord<Shading>();  // -1: none

  // Where frame pixel (x, y) is in the tile's buffers.
  std::ptrdiff_t index(int x, int y) const { return tile_index(tile_, x, y); }

  using EdgeScalesOrNone = std::conditional_t<edge_overlay<Shading>(), EdgeScales, std::monostate>;
  PixelWriter(TileContext& tile, std::uint32_t draw, const SetupTriangle* t,
              EdgeScalesOrNone edge_scales)
      : tile_(tile),
        t_(t),
        draw_(draw),
        uniforms_(tile.frame->draws[draw].uniforms),
        fog_(uniforms_.frame->lighting->fog),
        alpha_cutoff_(uniforms_.material->alpha_cutoff),
        edge_scales_(edge_scales) {
    const Material& material = *uniforms_.material;
    if constexpr (kTexcoordSlot >= 0) {
      if (material.base_color_map) base_map_ = &material.base_color_map;
    }
  }

  // Every map the model reads and the draw has, sampled for in.count pixels whose varyings and
  // clip w are v[k][n] and w[n], into `in` (base_texel, map_texel).
  void sample_maps(shading::ShadeInput& in, const float (*v)[kBlockPixels], const float* w,
                   const float (*slopes)[kBlockPixels] = nullptr) {
    in.base_texel = sample_base_map(in.count, v, w, slopes);
    if constexpr (kMapsRead != 0) {
      const TextureMap* const* maps = tile_.frame->draws[draw_].maps;
      for (int k = 0; k < shading::kMaterialMaps; ++k) {
        if (maps[k] != nullptr) {
          in.map_texel[k] = sample(*maps[k], map_texels_[k], in.count, v, w, slopes);
        }
      }
    }
  }

  // `map` sampled into `texels` for `count` pixels whose varyings and clip w are v[k][n] and
  // w[n], at the texture coordinate of slot kTexcoordSlot: their texels. The pixels are of this
  // writer's triangle, or of several whose plane slopes are `slopes` (TexelBatch).
  using Texels = const float (*)[4];
  Texels sample(const TextureMap& map, shading::TexelBatch& texels, int count,
                const float (*v)[kBlockPixels], const float* w,
                const float (*slopes)[kBlockPixels]) {
    texels.count = count;
    texels.u = v[kTexcoordSlot];
    texels.v = v[kTexcoordSlot + 1];
    texels.w = w;
    texels.slopes = slopes;
    if (slopes == nullptr) {
      texels.planes = fragment.planes + kTexcoordSlot;
      texels.inv_w = &t_->inv_w;
    }
    uniforms_.frame->kernels->sample_batch(map, texels);
    return texels.rgba;
  }

  // The base color map sampled for `count` pixels (PackedPixels and BlockFragments alike; see
  // sample()): their texels, or null when the model reads no map or the draw has none.
  Texels sample_base_map(int count, const float (*v)[kBlockPixels], const float* w,
                         const float (*slopes)[kBlockPixels] = nullptr) {
    if constexpr (kTexcoordSlot >= 0) {
      if (base_map_) return sample(*base_map_, texels_, count, v, w, slopes);
    }
    return nullptr;
  }

  // The batch shader fogs, except under the wire overlay, whose colors store_all() fogs with
  // its wire color.
  static constexpr bool kBatchFogs = !edge_overlay<Shading>();
  const Fog* batch_fog() const { return kBatchFogs ? &fog_ : nullptr; }
  TileContext& tile_;
  const SetupTriangle* t_;  // null for the pixels of several triangles
  std::uint32_t draw_;
  const shading::DrawUniforms& uniforms_;
  const Fog& fog_;
  float alpha_cutoff_;
  // Only the wire overlay reads it (an empty struct otherwise, and never computed).
  [[no_unique_address]] EdgeScalesOrNone edge_scales_;
  const TextureMap* base_map_ = nullptr;  // the map sampled ahead, if any
  shading::TexelBatch texels_;
  // The texels of the other maps the model reads that the draw has (DrawRecord::maps).
  static constexpr unsigned kMapsRead = maps_read<Shading>();
  static_assert(kMapsRead == 0 || kTexcoordSlot >= 0,
                "the maps are read at the base map's coordinate");
  using MapTexels = std::conditional_t<kMapsRead != 0, shading::TexelBatch[shading::kMaterialMaps],
                                       std::monostate>;
  [[no_unique_address]] MapTexels map_texels_;
};

}  // namespace facet::pipeline
