// RenderTexture: an offscreen target that later draws sample as a texture. A frame renders into
// it (Renderer::finish(RenderTexture&), the same tiled pipeline as any frame, so the same image
// for any thread count, tile size and SIMD target), and its texture() then holds that image:
// a mirror's view, a screen inside the scene, a light's depth. The texture is one object for
// the target's whole life, given each new image by each such finish() (the frame is rendered
// into a framebuffer whose buffers then trade places with the texture's: no copy), so the
// materials that hold it see every new image; its mip chain is filtered after each render when
// asked for.
#pragma once

#include <memory>

#include "facet/framebuffer.hpp"
#include "facet/texture.hpp"

namespace facet {

struct RenderTextureOptions {
  // rgba8_srgb: an 8-bit sRGB texture, as a framebuffer's PNG; rgba32f: linear float color.
  ColorFormat format = ColorFormat::rgba8_srgb;
  // The color texture's whole mip chain (box filtered in linear light, as Texture's), refreshed
  // after every render, for draws that see the texture minified (Filter::trilinear); otherwise
  // the base level alone. The depth texture has its base level alone either way: depths are
  // compared, not averaged.
  bool mipmaps = false;
  // Also depth_texture(): the window depth of each pixel (0 at the near plane, 1 at the far
  // and where nothing was drawn), read as red, green and blue with alpha 1; stored as one float
  // a texel (Texture::Format::r32f).
  bool depth = false;
  // False: depth alone (with depth true), as a shadow map is made: no color is cleared,
  // shaded or resolved, and texture() is null.
  bool color = true;
  // For rgba8_srgb: whether the texture reads its 8-bit codes as sRGB (a picture, as a PNG is
  // read) or as code / 255 (data, as OpenGL's RGBA8 target holds it: a frame of display values
  // alone, such as the normals view, stores each value as its code, and reads back its values).
  bool srgb_texture = true;
};

class RenderTexture {
 public:
  // Throws facet::Error if a side is outside [1, Framebuffer::kMaxSize], or for options that
  // keep neither color nor depth.
  RenderTexture(int width, int height, const RenderTextureOptions& options = {});
  ~RenderTexture();
  RenderTexture(RenderTexture&&) noexcept;
  RenderTexture& operator=(RenderTexture&&) noexcept;

  int width() const { return framebuffer_.width(); }
  int height() const { return framebuffer_.height(); }
  const RenderTextureOptions& options() const { return options_; }

  // What Renderer::finish renders into (its extra outputs: none). update() then moves the image
  // into the textures by trading buffers, so afterwards the framebuffer holds an earlier image,
  // for the next render to overwrite: what was rendered is read through texture() and
  // depth_texture() (Texture::level(0), rows top first as here). Renders leave alone the tiles
  // where they draw nothing that still hold the same clear values from an earlier render into
  // the same buffers; the non-const framebuffer() forgets which those are, since you may write
  // it.
  Framebuffer& framebuffer();
  const Framebuffer& framebuffer() const { return framebuffer_; }
  // The color image, as a texture for materials (TextureMap) and environments; null for a
  // depth-only target.
  std::shared_ptr<const Texture> texture() const { return color_texture_; }
  // The depth image as a texture; null unless RenderTextureOptions::depth.
  std::shared_ptr<const Texture> depth_texture() const { return depth_texture_; }
  // Whether texture is one of this target's textures.
  bool owns(const Texture* texture) const;

  // Moves the framebuffer's image into the textures, trading their buffers (no copy: the
  // framebuffer then holds the textures' earlier image), and filters the color texture's mip
  // chain with oneTBB's threads (Renderer::finish calls it, after rendering, on the renderer's
  // own). After writing framebuffer() yourself, every pixel, call it, once per image: a second
  // call trades the buffers back. Allocates nothing.
  void update();

 private:
  friend class Renderer;  // renders into framebuffer_ without forgetting its cleared tiles
  void trade_buffers();   // update() without the forgetting

  RenderTextureOptions options_;
  Framebuffer framebuffer_;
  std::shared_ptr<Texture> color_texture_, depth_texture_;  // rewritten by update()
  // Which tiles hold the clear values alone: the framebuffer's buffers', and the textures',
  // traded with the buffers.
  std::unique_ptr<ClearTiles> framebuffer_clear_, texture_clear_;
};

}  // namespace facet
