// RenderTexture (see facet/render_texture.hpp): a framebuffer and the textures made of it.
#include "facet/render_texture.hpp"

#include <algorithm>
#include <cstring>

#include "facet/error.hpp"

namespace facet {

RenderTexture::RenderTexture(int width, int height, const RenderTextureOptions& options)
    : options_(options),
      framebuffer_(width, height, options.format,
                   options.depth ? DepthImage::keep : DepthImage::none) {
  if (!options.color && !options.depth) {
    throw Error("render texture: keeps neither color nor depth (RenderTextureOptions)");
  }
  if (options.color) {
    const bool srgb = options.format == ColorFormat::rgba8_srgb;
    color_texture_ = Texture::render_target(
        width, height, srgb ? Texture::Format::rgba8 : Texture::Format::rgba32f, srgb,
        options.mipmaps, "render texture");
  }
  if (options.depth) {
    depth_texture_ = Texture::render_target(width, height, Texture::Format::r32f, false,
                                            options.mipmaps, "render texture depth");
  }
  update();
}

bool RenderTexture::owns(const Texture* texture) const {
  return texture != nullptr && (texture == color_texture_.get() || texture == depth_texture_.get());
}

void RenderTexture::update() {
  if (color_texture_) {
    Texture::Level& color = color_texture_->base_level();
    if (options_.format == ColorFormat::rgba8_srgb) {
      std::memcpy(color.rgba8.data(), framebuffer_.rgba8().data(), color.rgba8.size());
    } else {
      std::memcpy(color.rgba32f.data(), framebuffer_.rgba32f().data(),
                  color.rgba32f.size() * sizeof(float));
    }
    color_texture_->refresh_from_base_level();
  }
  if (!depth_texture_) return;
  const std::vector<float>& depth = framebuffer_.depth();
  std::copy(depth.begin(), depth.end(), depth_texture_->base_level().r32f.begin());
  depth_texture_->refresh_from_base_level();
}

}  // namespace facet
