// Stage: output (see output.hpp).
#include "pipeline/output/output.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "core/color.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/output/framebuffer_rows.hpp"

namespace facet::pipeline {
namespace {

// Writes one row of linear colors (scaled by the exposure) in the target's format; or of
// display values, to an 8-bit target, rounded as they are. Colors with known's bits take its
// codes without being encoded.
void store_row(const Kernels& kernels, Framebuffer& target, std::size_t first_pixel,
               const glm::vec4* colors, int count, float scale, bool display_referred = false,
               const shading::KnownCodes* known = nullptr) {
  if (target.format() == ColorFormat::rgba8_srgb) {
    std::uint8_t* out = target.rgba8().data() + first_pixel * 4;
    if (display_referred) {
      kernels.round_unorm8_row(colors, count, out);
    } else if (known != nullptr) {
      kernels.encode_srgb_row_knowing(colors, count, scale, *known, out);
    } else {
      kernels.encode_srgb_row(colors, count, scale, out);
    }
  } else {
    float* out = target.rgba32f().data() + first_pixel * 4;
    for (int i = 0; i < count; ++i, out += 4) {
      const glm::vec4& c = colors[i];
      out[0] = c.r * scale, out[1] = c.g * scale, out[2] = c.b * scale, out[3] = c.a;
    }
  }
}

// A tile row of the clear depth.
const float* clear_depth_row() {
  static const std::array<float, kMaxTileSize> kRow = [] {
    std::array<float, kMaxTileSize> row;
    row.fill(kClearDepth);
    return row;
  }();
  return kRow.data();
}

}  // namespace

glm::vec4 display_value_of(const Kernels& kernels, const glm::vec4& linear) {
  std::uint8_t codes[4];
  kernels.encode_srgb_row(&linear, 1, 1.0f, codes);
  glm::vec4 shown = linear;
  for (int c = 0; c < 3; ++c) shown[c] = static_cast<float>(codes[c]) * shading::kInverse255;
  return shown;
}

std::uint32_t display_codes(const Kernels& kernels, const glm::vec4& value) {
  std::uint32_t codes;
  kernels.round_unorm8_row(&value, 1, reinterpret_cast<std::uint8_t*>(&codes));
  return codes;
}

shading::KnownCodes background_codes(const Kernels& kernels, const Resolve& resolve,
                                     const glm::vec4& clear) {
  shading::KnownCodes known{clear, 0};
  float scale = resolve.scale;
  if (resolve.tone_mapping != ToneMapping::none) {  // as resolve_tile maps a row, then encodes
    const float depth = kClearDepth;
    kernels.tone_map_row(resolve.tone_mapping, &clear, &depth, kClearDepth, 1, resolve.scale,
                         &known.color);
    scale = 1.0f;
  }
  std::uint8_t codes[4];
  kernels.encode_srgb_row(&known.color, 1, scale, codes);
  std::memcpy(&known.codes, codes, sizeof(codes));
  return known;
}

void clear_tile(TileContext& tile, const Background& background, bool color_hidden) {
  const Kernels& kernels = *tile.frame->kernels;
  const int width = tile.x1 - tile.x0, height = tile.y1 - tile.y0;
  const bool clears_color = !background.environment && !color_hidden && !background.depth_only;
  // Whole tiles' rows are contiguous: each plane is filled in one go.
  const bool whole = width == tile.stride;
  const int rows = whole ? 1 : height;
  const std::ptrdiff_t row_length = whole ? static_cast<std::ptrdiff_t>(width) * height : width;
  for (int y = 0; y < rows; ++y) {
    const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(y) * tile.stride;
    if (clears_color && tile.codes != nullptr) {
      std::fill_n(tile.codes + row, row_length, background.clear_codes);
    } else if (clears_color) {
      kernels.fill_color_row(tile.color + row, row_length, background.clear_color);
    }
    // every sample at the clear depth, each pixel's samples alike (MSAA)
    for (int s = 0; s < tile.samples; ++s) {
      kernels.fill_float_row(tile.depth + s * tile.sample_plane + row, row_length, kClearDepth);
    }
  }
  std::fill_n(tile.block_max_depth, tile.blocks_x * tile.blocks_x, kClearDepth);
  if (tile.samples > 1) std::fill_n(tile.split, tile.sample_plane, std::uint8_t{0});
}

void fill_background(TileContext& tile, const Background& background) {
  if (!background.environment) return;
  const Environment& environment = *background.environment;
  const SkyView view{background.inverse_view_projection, background.eye, background.width,
                     background.height};
  const SkyRowKernel sky_row = tile.frame->kernels->sky_row;
  const SampleAtKernel sample_at = tile.frame->kernels->shading.sample_at;
  static_assert(kMaxTileSize <= kMaxSkyRow, "a tile row is one sky_row call");
  for (int y = 0; y < tile.y1 - tile.y0; ++y) {
    sky_row(view, environment, sample_at, tile.x0, tile.y0 + y, tile.x1 - tile.x0,
            tile.depth + static_cast<std::ptrdiff_t>(y) * tile.stride, kClearDepth,
            tile.color + static_cast<std::ptrdiff_t>(y) * tile.stride);
  }
  if (tile.samples == 1) return;
  // The other samples of pixels whose samples differ (sample 0 is done above): the environment
  // seen through the pixel centre (the row kernel for that one pixel), into those still at the
  // clear depth.
  const float clear = kClearDepth;
  for (int y = 0; y < tile.y1 - tile.y0; ++y) {
    for (int x = 0; x < tile.x1 - tile.x0; ++x) {
      const std::ptrdiff_t pixel = static_cast<std::ptrdiff_t>(y) * tile.stride + x;
      if (!tile.split[pixel]) continue;
      bool computed = false;
      glm::vec4 sky{0.0f};
      for (int s = 1; s < tile.samples; ++s) {
        if (tile.depth[s * tile.sample_plane + pixel] != kClearDepth) continue;
        if (!computed) {
          sky_row(view, environment, sample_at, tile.x0 + x, tile.y0 + y, 1, &clear, kClearDepth,
                  &sky);
          computed = true;
        }
        sample_color(tile, pixel, s) = sky;
      }
    }
  }
}

namespace {

// Tone maps count colors of the tile from index first (of its color and depth planes) into out,
// exposure included.
void tone_map(const TileContext& tile, const Resolve& resolve, std::ptrdiff_t first, int count,
              glm::vec4* out) {
  const float* depth = resolve.maps_background ? nullptr : tile.depth + first;
  tile.frame->kernels->tone_map_row(resolve.tone_mapping, tile.color + first, depth, kClearDepth,
                                    count, resolve.scale, out);
}

// The MSAA resolve of one tile row: each pixel's samples averaged in linear light (in sample
// order, then scaled: the same sum on every path), or its one color where they are alike.
// Tone mapped, each sample is mapped before the average: the split pixels' other samples are
// gathered, with their depths, and mapped together, kSamplesMapped at most a call (the curves map
// each lane alone, so gathering changes no bits); then each such pixel's sum is taken.
void average_samples(const TileContext& tile, const Resolve& resolve, std::ptrdiff_t first,
                     int count, glm::vec4* out) {
  const std::uint8_t* split = tile.split + first;
  const int others = tile.samples - 1;
  const glm::vec4* row_others = tile.sample_colors + first * others;
  if (resolve.tone_mapping == ToneMapping::none) {
    tile.frame->kernels->average_samples_row(tile.color + first, row_others, tile.samples, split,
                                             count, out);
    return;
  }
  tone_map(tile, resolve, first, count, out);
  const float inverse = 1.0f / static_cast<float>(tile.samples);
  constexpr int kSamplesMapped = 256;
  static_assert(kSamplesMapped >= kMaxSamples - 1);
  glm::vec4 gathered[kSamplesMapped], mapped[kSamplesMapped];
  float depths[kSamplesMapped];
  int pixels[kSamplesMapped];
  int gathered_count = 0, pixel_count = 0;
  const auto map_gathered = [&] {
    // Nothing drawn at a sample keeps the clear color unmapped.
    tile.frame->kernels->tone_map_row(resolve.tone_mapping, gathered,
                                      resolve.maps_background ? nullptr : depths, kClearDepth,
                                      gathered_count, resolve.scale, mapped);
    for (int k = 0; k < pixel_count; ++k) {
      glm::vec4 sum = out[pixels[k]];
      for (int s = 0; s < others; ++s) sum += mapped[k * others + s];
      out[pixels[k]] = sum * inverse;
    }
    gathered_count = pixel_count = 0;
  };
  for (int x = 0; x < count; ++x) {
    if (!split[x]) continue;
    if (gathered_count + others > kSamplesMapped) map_gathered();
    // A loop rather than std::copy_n, which for a count known only at run time calls memmove.
    for (int s = 1; s <= others; ++s) {
      gathered[gathered_count + s - 1] = row_others[x * others + s - 1];
      depths[gathered_count + s - 1] = tile.depth[s * tile.sample_plane + first + x];
    }
    gathered_count += others;
    pixels[pixel_count++] = x;
  }
  if (gathered_count > 0) map_gathered();
}

}  // namespace

void resolve_tile(const TileContext& tile, const Resolve& resolve, Framebuffer& target) {
  // Mapped colors have the exposure in them.
  const float scale = resolve.tone_mapping == ToneMapping::none ? resolve.scale : 1.0f;
  const int width = tile.x1 - tile.x0;
  auto write_row = [&](int y, const glm::vec4* color) {
    const std::size_t row = static_cast<std::size_t>(y) * target.width();
    store_row(*tile.frame->kernels, target, row + tile.x0, color, width, scale,
              resolve.display_referred, resolve.background ? &*resolve.background : nullptr);
    if (target.has_depth()) {
      const float* depth = tile.depth + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
      std::copy_n(depth, width, target.depth().data() + row + tile.x0);
    }
  };
  if (tile.codes != nullptr) {  // rounded already: copied
    for (int y = tile.y0; y < tile.y1; ++y) {
      const std::uint32_t* codes =
          tile.codes + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
      const std::size_t first = static_cast<std::size_t>(y) * target.width() + tile.x0;
      std::memcpy(target.rgba8().data() + first * 4, codes, sizeof(std::uint32_t) * width);
      if (target.has_depth()) {
        const float* depth = tile.depth + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
        std::copy_n(depth, width, target.depth().data() + first);
      }
    }
    return;
  }
  if (tile.samples > 1) {
    // Each row averaged one row ahead of its encode: the encode's wide loads of colors the
    // average has just stored a color at a time would wait for those stores to complete.
    glm::vec4 averaged[2][kMaxTileSize];
    for (int y = tile.y0; y < tile.y1; ++y) {
      const std::ptrdiff_t first = static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
      average_samples(tile, resolve, first, width, averaged[(y - tile.y0) & 1]);
      if (y > tile.y0) write_row(y - 1, averaged[(y - 1 - tile.y0) & 1]);
    }
    write_row(tile.y1 - 1, averaged[(tile.y1 - 1 - tile.y0) & 1]);
    return;
  }
  glm::vec4 mapped[kMaxTileSize];
  for (int y = tile.y0; y < tile.y1; ++y) {
    const std::ptrdiff_t first = static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
    const glm::vec4* color = tile.color + first;
    if (resolve.tone_mapping != ToneMapping::none) {
      tone_map(tile, resolve, first, width, mapped);
      color = mapped;
    }
    write_row(y, color);
  }
}

void resolve_depth_tile(const TileContext& tile, bool cleared, Framebuffer& target) {
  const bool streaming = cleared && streams_cleared_rows(sizeof(float) * target.depth().size());
  for (int y = tile.y0; y < tile.y1; ++y) {
    float* out = target.depth().data() + static_cast<std::size_t>(y) * target.width() + tile.x0;
    if (cleared) {
      write_cleared_row(out, clear_depth_row(), sizeof(float) * (tile.x1 - tile.x0), streaming);
    } else {
      std::copy_n(tile.depth + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride,
                  tile.x1 - tile.x0, out);
    }
  }
  if (streaming) end_streamed_rows();
}

void resolve_cleared_tile(const TileContext& tile, const glm::vec4& clear, float scale,
                          Framebuffer& target) {
  const int width = tile.x1 - tile.x0;
  const bool bytes_color = target.format() == ColorFormat::rgba8_srgb;
  const bool streams_color = bytes_color && streams_cleared_rows(target.rgba8().size());
  const bool streams_depth = streams_cleared_rows(sizeof(float) * target.depth().size());
  // Convert the clear color once into one tile row, then copy that row down the tile.
  std::uint8_t row_bytes[kMaxTileSize * 4];
  if (bytes_color) {
    std::uint8_t pixel[4];
    tile.frame->kernels->encode_srgb_row(&clear, 1, scale, pixel);
    for (int x = 0; x < width; ++x) std::memcpy(row_bytes + x * 4, pixel, 4);
  }
  for (int y = tile.y0; y < tile.y1; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * target.width();
    if (bytes_color) {
      write_cleared_row(target.rgba8().data() + (row + tile.x0) * 4, row_bytes, width * 4,
                        streams_color);
    } else {
      for (int x = tile.x0; x < tile.x1; ++x) {
        store_row(*tile.frame->kernels, target, row + x, &clear, 1, scale);
      }
    }
    if (target.has_depth()) {
      write_cleared_row(target.depth().data() + row + tile.x0, clear_depth_row(),
                        sizeof(float) * width, streams_depth);
    }
  }
  if (streams_color || streams_depth) end_streamed_rows();
}

}  // namespace facet::pipeline
