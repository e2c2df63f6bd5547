// Framebuffer storage.
#include "facet/framebuffer.hpp"

#include <string>

#include "core/clear_tiles.hpp"
#include "core/color.hpp"
#include "facet/error.hpp"

namespace facet {

Framebuffer::Framebuffer(int width, int height, ColorFormat format, DepthImage depth,
                         const ExtraOutputs& extra)
    : Framebuffer(width, height, format, ColorImage::keep, depth, extra) {}

Framebuffer Framebuffer::depth_only(int width, int height) {
  return Framebuffer(width, height, ColorFormat::rgba8_srgb, ColorImage::none, DepthImage::keep,
                     {});
}

Framebuffer::Framebuffer(int width, int height, ColorFormat format, ColorImage color,
                         DepthImage depth, const ExtraOutputs& extra)
    : width_(width), height_(height), format_(format), extra_(extra) {
  if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize) {
    throw Error("framebuffer: size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside 1x1 .. " + std::to_string(kMaxSize) + "x" + std::to_string(kMaxSize));
  }
  std::size_t pixels = static_cast<std::size_t>(width) * height;
  if (color == ColorImage::keep && format == ColorFormat::rgba8_srgb) {
    rgba8_.assign(pixels * 4, 0);
  } else if (color == ColorImage::keep) {
    rgba32f_.assign(pixels * 4, 0.0f);
  }
  if (depth == DepthImage::keep) depth_.assign(pixels, 1.0f);
  if (extra.view_depth) view_depth_.assign(pixels, 0.0f);
  if (extra.ray_distance) ray_distance_.assign(pixels, 0.0f);
  if (extra.normals != NormalSpace::none) normals_.assign(pixels * 3, 0.0f);
  if (extra.instance_ids) instance_ids_.assign(pixels, 0);
  if (extra.triangle_ids) triangle_ids_.assign(pixels, 0);
  if (extra.barycentrics) barycentrics_.assign(pixels * 3, 0.0f);
  if (extra.albedo) albedo_.assign(pixels * 4, 0.0f);
}

Framebuffer::KeptTiles::KeptTiles() = default;
Framebuffer::KeptTiles::KeptTiles(const KeptTiles& other)
    : tiles(other.tiles ? std::make_unique<ClearTiles>() : nullptr) {}
Framebuffer::KeptTiles::KeptTiles(KeptTiles&& other) noexcept = default;
Framebuffer::KeptTiles& Framebuffer::KeptTiles::operator=(const KeptTiles& other) {
  tiles = other.tiles ? std::make_unique<ClearTiles>() : nullptr;
  return *this;
}
Framebuffer::KeptTiles& Framebuffer::KeptTiles::operator=(KeptTiles&& other) noexcept = default;
Framebuffer::KeptTiles::~KeptTiles() = default;

void Framebuffer::keep_cleared_tiles(bool keep) {
  if (keep == keeps_cleared_tiles()) return;
  cleared_tiles_.tiles = keep ? std::make_unique<ClearTiles>() : nullptr;
}

void Framebuffer::forget_kept_tiles() { cleared_tiles_.tiles->forget(); }

std::size_t Framebuffer::checked_index(int x, int y, const char* what) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) {
    throw Error(std::string("framebuffer: ") + what + " at (" + std::to_string(x) + ", " +
                std::to_string(y) + ") is outside the " + std::to_string(width_) + "x" +
                std::to_string(height_) + " image");
  }
  return static_cast<std::size_t>(y) * width_ + x;
}

glm::vec4 Framebuffer::pixel(int x, int y) const {
  const std::size_t i = checked_index(x, y, "pixel") * 4;
  if (!has_color()) throw Error("framebuffer: pixel on a depth-only framebuffer (no color image)");
  if (format_ == ColorFormat::rgba32f) {
    return {rgba32f_[i], rgba32f_[i + 1], rgba32f_[i + 2], rgba32f_[i + 3]};
  }
  return {shading::decode_srgb8(rgba8_[i]), shading::decode_srgb8(rgba8_[i + 1]),
          shading::decode_srgb8(rgba8_[i + 2]), rgba8_[i + 3] / 255.0f};
}

float Framebuffer::depth_at(int x, int y) const {
  const std::size_t i = checked_index(x, y, "depth_at");
  if (depth_.empty()) {
    throw Error(
        "framebuffer: depth_at on a framebuffer made without a depth image "
        "(DepthImage::none)");
  }
  return depth_[i];
}

}  // namespace facet
