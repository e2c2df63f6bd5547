// RenderTexture (see facet/render_texture.hpp): a framebuffer and the textures made of it.
#include "facet/render_texture.hpp"

#include <algorithm>
#include <cstring>

#include "core/parallel.hpp"
#include "facet/error.hpp"

namespace facet {
namespace {

// Copies count values in parallel chunks of 1 MiB: the copy is part of every frame that renders
// into the target.
template <class T>
void parallel_copy(const T* from, T* to, std::size_t count) {
  constexpr std::size_t kChunk = (std::size_t{1} << 20) / sizeof(T);
  const int chunks = static_cast<int>((count + kChunk - 1) / kChunk);
  parallel_tasks(chunks, default_workers(), [&](int chunk, int) {
    const std::size_t first = static_cast<std::size_t>(chunk) * kChunk;
    std::memcpy(to + first, from + first, std::min(kChunk, count - first) * sizeof(T));
  });
}

}  // namespace

RenderTexture::RenderTexture(int width, int height, const RenderTextureOptions& options)
    : options_(options),
      framebuffer_(width, height, options.format,
                   options.depth ? DepthImage::keep : DepthImage::none) {
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
  update();
}

bool RenderTexture::owns(const Texture* texture) const {
  return texture != nullptr && (texture == color_texture_.get() || texture == depth_texture_.get());
}

void RenderTexture::update() {
  if (color_texture_) {
    Texture::Level& color = color_texture_->base_level();
    if (options_.format == ColorFormat::rgba8_srgb) {
      parallel_copy(framebuffer_.rgba8().data(), color.rgba8.data(), color.rgba8.size());
    } else {
      parallel_copy(framebuffer_.rgba32f().data(), color.rgba32f.data(), color.rgba32f.size());
    }
    color_texture_->refresh_from_base_level();
  }
  if (!depth_texture_) return;
  parallel_copy(framebuffer_.depth().data(), depth_texture_->base_level().r32f.data(),
                framebuffer_.depth().size());
  depth_texture_->refresh_from_base_level();
}

}  // namespace facet
