// Debug views (see debug_view.hpp).
#include "pipeline/output/debug_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/color.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"

namespace facet::pipeline {
namespace {

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

// Writes an sRGB display value (not light: no exposure) to one pixel of the target.
void store_display(Framebuffer& target, std::size_t pixel, glm::vec3 shown) {
  if (target.format() == ColorFormat::rgba8_srgb) {
    std::uint8_t* out = target.rgba8().data() + pixel * 4;
    for (int c = 0; c < 3; ++c) out[c] = shading::encode_unorm8(shown[c]);
    out[3] = 255;
  } else {
    float* out = target.rgba32f().data() + pixel * 4;
    for (int c = 0; c < 3; ++c) out[c] = shading::srgb_to_linear(std::clamp(shown[c], 0.0f, 1.0f));
    out[3] = 1.0f;
  }
}

// Mixes a display value halfway into a resolved pixel (in the stored encoding: it is a tint).
void tint_display(Framebuffer& target, std::size_t pixel, glm::vec3 tint, float amount) {
  if (target.format() == ColorFormat::rgba8_srgb) {
    std::uint8_t* out = target.rgba8().data() + pixel * 4;
    for (int c = 0; c < 3; ++c) {
      out[c] = shading::encode_unorm8(glm::mix(out[c] / 255.0f, tint[c], amount));
    }
  } else {
    float* out = target.rgba32f().data() + pixel * 4;
    for (int c = 0; c < 3; ++c) out[c] = glm::mix(out[c], shading::srgb_to_linear(tint[c]), amount);
  }
}

void resolve_overdraw(const TileContext& tile, Framebuffer& target) {
  for (int y = tile.y0; y < tile.y1; ++y) {
    const glm::vec4* counts = tile.color + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
    std::size_t row = static_cast<std::size_t>(y) * target.width();
    for (int x = tile.x0; x < tile.x1; ++x) {
      store_display(target, row + x, heat(counts[x - tile.x0].r, 2.0f));
    }
    if (target.has_depth())
      std::fill_n(target.depth().data() + row + tile.x0, tile.x1 - tile.x0, 1.0f);
  }
}

// The shaded tile, tinted by its bin size, with a dark outline so the tile grid shows.
void resolve_tile_bins(const TileContext& tile, std::size_t bin_size, float scale,
                       Framebuffer& target) {
  resolve_tile(tile, Resolve{scale}, target);
  const glm::vec3 tint = heat(static_cast<float>(bin_size), 10.0f);
  for (int y = tile.y0; y < tile.y1; ++y) {
    std::size_t row = static_cast<std::size_t>(y) * target.width();
    for (int x = tile.x0; x < tile.x1; ++x) {
      bool outline = x == tile.x0 || y == tile.y0;
      tint_display(target, row + x, outline ? glm::vec3(0.0f) : tint, outline ? 0.7f : 0.5f);
    }
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
    resolve_tile(tile, Resolve{scale}, target);
  }
}

}  // namespace facet::pipeline
