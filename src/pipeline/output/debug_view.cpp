// Debug views (see debug_view.hpp).
#include "pipeline/output/debug_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/color.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"

namespace facet::pipeline {
namespace {

// The debug views' resolve: the exposure, nothing mapped.
Resolve exposure_only(float scale) {
  Resolve resolve;
  resolve.scale = scale;
  return resolve;
}

// The heat ramp, sRGB display values: black, blue, green, yellow, red, white.
constexpr std::array<glm::vec3, 6> kRamp = {{{0.0f, 0.0f, 0.0f},
                                             {0.1f, 0.2f, 0.9f},
                                             {0.1f, 0.8f, 0.2f},
                                             {0.95f, 0.9f, 0.1f},
                                             {0.95f, 0.15f, 0.1f},
                                             {1.0f, 1.0f, 1.0f}}};

// Ramp position 0 for a count of 0, 1 for 1, then one more step per factor of `base`:
// overdraw uses base 2 (1, 2, 4, 8, 16), tile bins base 10 (1, 10, 100, 1000, 10000).
glm::vec3 heat(float count, float base) {
  if (count < 1.0f) return glm::mix(kRamp[0], kRamp[1], std::max(count, 0.0f));
  float position = 1.0f + std::log(count) / std::log(base);
  int i = std::min(static_cast<int>(position), static_cast<int>(kRamp.size()) - 1);
  if (i == static_cast<int>(kRamp.size()) - 1) return kRamp.back();
  return glm::mix(kRamp[i], kRamp[i + 1], position - static_cast<float>(i));
}

// Writes sRGB display values (not light: no exposure), one a pixel, to `count` pixels of the
// target from `first` on: 8-bit codes through the row kernel's rounding, or decoded floats.
void store_display(const TileContext& tile, Framebuffer& target, std::size_t first,
                   const glm::vec4* shown, int count) {
  if (target.format() == ColorFormat::rgba8_srgb) {
    tile.frame->kernels->round_unorm8_row(shown, count, target.rgba8().data() + first * 4);
    return;
  }
  float* out = target.rgba32f().data() + first * 4;
  for (int i = 0; i < count; ++i, out += 4) {
    for (int c = 0; c < 3; ++c)
      out[c] = shading::srgb_to_linear(std::clamp(shown[i][c], 0.0f, 1.0f));
    out[3] = 1.0f;
  }
}

void resolve_overdraw(const TileContext& tile, Framebuffer& target) {
  glm::vec4 shown[kMaxTileSize];
  const int width = tile.x1 - tile.x0;
  for (int y = tile.y0; y < tile.y1; ++y) {
    const glm::vec4* counts = tile.color + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
    const std::size_t row = static_cast<std::size_t>(y) * target.width();
    for (int x = 0; x < width; ++x) shown[x] = glm::vec4(heat(counts[x].r, 2.0f), 1.0f);
    store_display(tile, target, row + tile.x0, shown, width);
    if (target.has_depth()) std::fill_n(target.depth().data() + row + tile.x0, width, 1.0f);
  }
}

// The shaded tile, tinted by its bin size, with a dark outline so the tile grid shows: each
// pixel's stored value mixed toward the tint (in the stored encoding: it is a tint), 8-bit codes
// rounded again by the row kernel.
void resolve_tile_bins(const TileContext& tile, std::size_t bin_size, float scale,
                       Framebuffer& target) {
  resolve_tile(tile, exposure_only(scale), target);
  const glm::vec3 tint = heat(static_cast<float>(bin_size), 10.0f);
  const int width = tile.x1 - tile.x0;
  const bool codes = target.format() == ColorFormat::rgba8_srgb;
  glm::vec4 mixed[kMaxTileSize];
  for (int y = tile.y0; y < tile.y1; ++y) {
    const std::size_t first = static_cast<std::size_t>(y) * target.width() + tile.x0;
    for (int x = 0; x < width; ++x) {
      const bool outline = x == 0 || y == tile.y0;
      const glm::vec3 toward = outline ? glm::vec3(0.0f) : tint;
      const float amount = outline ? 0.7f : 0.5f;
      if (!codes) {
        float* out = target.rgba32f().data() + (first + x) * 4;
        for (int c = 0; c < 3; ++c)
          out[c] = glm::mix(out[c], shading::srgb_to_linear(toward[c]), amount);
        continue;
      }
      const std::uint8_t* stored = target.rgba8().data() + (first + x) * 4;
      for (int c = 0; c < 3; ++c) mixed[x][c] = glm::mix(stored[c] / 255.0f, toward[c], amount);
      mixed[x][3] = static_cast<float>(stored[3]) * shading::kInverse255;  // kept as it is
    }
    if (codes)
      tile.frame->kernels->round_unorm8_row(mixed, width, target.rgba8().data() + first * 4);
  }
}

}  // namespace

const DrawPipeline& debug_pipeline(DebugView view, const DrawPipeline& own) {
  static const DrawPipeline kOverdraw = make_pipeline<shading::OverdrawCountShading>();
  return view == DebugView::overdraw ? kOverdraw : own;
}

void prepare_debug_frame(DebugView view, Lighting& lighting, Background& background) {
  if (view != DebugView::overdraw) return;
  lighting.fog.mode = FogMode::none;  // fog would mix the counts toward its color
  background.environment = nullptr;
  background.clear_color = glm::vec4(0.0f);
}

void resolve_debug_tile(const TileContext& tile, DebugView view, std::size_t bin_size, float scale,
                        Framebuffer& target) {
  if (view == DebugView::overdraw) {
    resolve_overdraw(tile, target);
  } else if (view == DebugView::tile_bins) {
    resolve_tile_bins(tile, bin_size, scale, target);
  } else {
    resolve_tile(tile, exposure_only(scale), target);
  }
}

}  // namespace facet::pipeline
