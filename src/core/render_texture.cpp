// RenderTexture (see facet/render_texture.hpp): a framebuffer and the textures made of it.
#include "facet/render_texture.hpp"

#include <utility>

#include "core/clear_tiles.hpp"
#include "facet/error.hpp"

namespace facet {

RenderTexture::RenderTexture(int width, int height, const RenderTextureOptions& options)
    : options_(options),
      framebuffer_(options.color ? Framebuffer(width, height, options.format,
                                               options.depth ? DepthImage::keep : DepthImage::none)
                                 : Framebuffer::depth_only(width, height)) {
  if (!options.color && !options.depth) {
    throw Error("render texture: keeps neither color nor depth (RenderTextureOptions)");
  }
  if (options.color) {
    const bool rgba8 = options.format == ColorFormat::rgba8_srgb;
    color_texture_ = Texture::render_target(
        width, height, rgba8 ? Texture::Format::rgba8 : Texture::Format::rgba32f,
        rgba8 && options.srgb_texture, options.mipmaps, "render texture");
  }
  if (options.depth) {
    depth_texture_ = Texture::render_target(width, height, Texture::Format::r32f, false, false,
                                            "render texture depth");
  }
  framebuffer_clear_ = std::make_unique<ClearTiles>();
  texture_clear_ = std::make_unique<ClearTiles>();
  trade_buffers();
}

RenderTexture::~RenderTexture() = default;
RenderTexture::RenderTexture(RenderTexture&&) noexcept = default;
RenderTexture& RenderTexture::operator=(RenderTexture&&) noexcept = default;

Framebuffer& RenderTexture::framebuffer() {
  if (framebuffer_clear_) framebuffer_clear_->forget();
  return framebuffer_;
}

bool RenderTexture::owns(const Texture* texture) const {
  return texture != nullptr && (texture == color_texture_.get() || texture == depth_texture_.get());
}

void RenderTexture::update() {
  if (framebuffer_clear_) framebuffer_clear_->forget();  // written by its caller
  trade_buffers();
}

void RenderTexture::trade_buffers() {
  std::swap(framebuffer_clear_, texture_clear_);
  // The framebuffer's image and the textures' base levels trade buffers: no copy, and the
  // framebuffer keeps buffers of the right size for the next render.
  if (color_texture_) {
    Texture::Level& color = color_texture_->base_level();
    if (options_.format == ColorFormat::rgba8_srgb) {
      std::swap(color.rgba8, framebuffer_.rgba8());
    } else {
      std::swap(color.rgba32f, framebuffer_.rgba32f());
    }
    color_texture_->refresh_from_base_level();
  }
  if (!depth_texture_) return;
  std::swap(depth_texture_->base_level().r32f, framebuffer_.depth());
  depth_texture_->refresh_from_base_level();
}

}  // namespace facet
