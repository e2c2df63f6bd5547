// Stage: output (see output.hpp).
#include "pipeline/output.hpp"

#include <algorithm>

#include "shading/color.hpp"

namespace facet::pipeline {
namespace {

// Depth of a cleared pixel: the far plane.
constexpr float kClearDepth = 1.0f;

void store(Framebuffer& target, std::size_t pixel, const glm::vec4& c) {
  if (target.format() == ColorFormat::rgba8_srgb) {
    std::uint8_t* out = target.rgba8().data() + pixel * 4;
    out[0] = shading::encode_srgb8(c.r);
    out[1] = shading::encode_srgb8(c.g);
    out[2] = shading::encode_srgb8(c.b);
    float a = std::clamp(c.a, 0.0f, 1.0f);  // alpha is linear coverage, never sRGB
    out[3] = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
  } else {
    float* out = target.rgba32f().data() + pixel * 4;
    out[0] = c.r, out[1] = c.g, out[2] = c.b, out[3] = c.a;
  }
}

}  // namespace

void clear_tile(TileContext& tile, const glm::vec4& color) {
  for (int y = 0; y < tile.y1 - tile.y0; ++y) {
    std::fill_n(tile.color + static_cast<std::ptrdiff_t>(y) * tile.stride, tile.x1 - tile.x0,
                color);
    std::fill_n(tile.depth + static_cast<std::ptrdiff_t>(y) * tile.stride, tile.x1 - tile.x0,
                kClearDepth);
  }
}

void resolve_tile(const TileContext& tile, Framebuffer& target) {
  for (int y = tile.y0; y < tile.y1; ++y) {
    const glm::vec4* color = tile.color + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
    const float* depth = tile.depth + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride;
    std::size_t row = static_cast<std::size_t>(y) * target.width();
    for (int x = tile.x0; x < tile.x1; ++x) store(target, row + x, color[x - tile.x0]);
    std::copy_n(depth, tile.x1 - tile.x0, target.depth().data() + row + tile.x0);
  }
}

void resolve_cleared_tile(const TileContext& tile, const glm::vec4& color, Framebuffer& target) {
  for (int y = tile.y0; y < tile.y1; ++y) {
    std::size_t row = static_cast<std::size_t>(y) * target.width();
    for (int x = tile.x0; x < tile.x1; ++x) store(target, row + x, color);
    std::fill_n(target.depth().data() + row + tile.x0, tile.x1 - tile.x0, kClearDepth);
  }
}

}  // namespace facet::pipeline
