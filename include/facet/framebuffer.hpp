// Framebuffer: the render target — a color image (RGBA8 sRGB or RGBA32F linear) and, unless
// asked not to keep one, a 32-bit float depth image of the same size; from 1x1 up to 8192x8192.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

namespace facet {

enum class ColorFormat {
  rgba8_srgb,  // 8 bits per channel, sRGB-encoded color, linear alpha
  rgba32f,     // linear float
};

// Whether the renderer copies its depth out into the framebuffer. Depth is tested either way
// (in the renderer's own tile buffers); a color-only job (a PNG, a window) saves the copy, a
// sizeable share of a simple frame's time.
enum class DepthImage { keep, none };

class Framebuffer {
 public:
  static constexpr int kMaxSize = 8192;

  // Throws facet::Error if a size is outside [1, kMaxSize].
  Framebuffer(int width, int height, ColorFormat format = ColorFormat::rgba8_srgb,
              DepthImage depth = DepthImage::keep);

  int width() const { return width_; }
  int height() const { return height_; }
  ColorFormat format() const { return format_; }

  // Row-major, top row first, 4 values per pixel. Only the one matching format() is non-empty.
  std::vector<std::uint8_t>& rgba8() { return rgba8_; }
  const std::vector<std::uint8_t>& rgba8() const { return rgba8_; }
  std::vector<float>& rgba32f() { return rgba32f_; }
  const std::vector<float>& rgba32f() const { return rgba32f_; }
  // Window depth per pixel, row-major, top row first; empty for DepthImage::none. 0 is the
  // camera's near plane and 1 its far plane (OpenGL's glDepthRange(0, 1)), not linear in
  // distance: Camera::view_distance turns it into scene units. 1 where nothing was drawn.
  std::vector<float>& depth() { return depth_; }
  const std::vector<float>& depth() const { return depth_; }
  bool has_depth() const { return !depth_.empty(); }

  // Linear color of one pixel, whatever the format (sRGB decoded). Throws facet::Error if
  // (x, y) is outside the image.
  glm::vec4 pixel(int x, int y) const;
  // Depth of one pixel. Throws facet::Error if (x, y) is outside the image or there is no
  // depth image (DepthImage::none).
  float depth_at(int x, int y) const;

 private:
  int width_;
  int height_;
  ColorFormat format_;
  std::vector<std::uint8_t> rgba8_;
  std::vector<float> rgba32f_;
  std::vector<float> depth_;

  // Index of pixel (x, y); throws facet::Error naming `what` if it is outside the image.
  std::size_t checked_index(int x, int y, const char* what) const;
};

}  // namespace facet
