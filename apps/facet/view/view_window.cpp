// The viewer's SDL window (see view_window.hpp).
#include "view_window.hpp"

#define SDL_MAIN_HANDLED  // facet has its own main(); SDL must not rename it
#include <SDL.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "facet/error.hpp"

namespace facet::cli {
namespace {

const char* const kNoDisplayHint =
    "; run it under a virtual display with `xvfb-run -a facet view ...`, or render to a file "
    "with `facet render`";

bool has_env(const char* name) {
  const char* value = std::getenv(name);
  return value && *value;
}

}  // namespace

ViewWindow::ViewWindow(const std::string& title, int width, int height)
    : width_(width), height_(height) {
  // With no display named and no driver forced, SDL could only fail (or grab the console
  // through KMSDRM), so say so plainly instead of passing on SDL's message.
  if (!has_env("SDL_VIDEODRIVER") && !has_env("DISPLAY") && !has_env("WAYLAND_DISPLAY")) {
    throw Error(std::string("view: no display (DISPLAY is not set)") + kNoDisplayHint);
  }
  SDL_SetMainReady();
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    std::string message = SDL_GetError();
    SDL_Quit();
    throw Error("view: cannot open the display (" + message + ")" + kNoDisplayHint);
  }
  int scale = std::max({1, (kMinWidth + width - 1) / width, (kMinHeight + height - 1) / height});
  // No bigger than the display, though: a 500x100 render would ask for 2000x400.
  SDL_DisplayMode display;
  if (SDL_GetDesktopDisplayMode(0, &display) == 0) {
    while (scale > 1 && (width * scale > display.w || height * scale > display.h)) --scale;
  }
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                             std::max(width * scale, kMinWidth),
                             std::max(height * scale, kMinHeight), SDL_WINDOW_RESIZABLE);
  if (window_) {
    SDL_SetWindowMinimumSize(window_, kMinWidth, kMinHeight);
    renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  }
  SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");  // smooth scaling of the texture
  // The frame is uploaded as bytes R, G, B, A, which SDL_PIXELFORMAT_RGBA32 names on any
  // endianness.
  if (renderer_) {
    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING,
                                 width, height);
  }
  if (!texture_) {
    std::string message = std::string("view: cannot create the window (") + SDL_GetError() + ")";
    close();
    throw Error(message);
  }
  // A logical size scales the frame to the window keeping its aspect ratio, with black bars:
  // rendering cost depends only on the render resolution, never on the window.
  SDL_RenderSetLogicalSize(renderer_, width, height);
}

ViewWindow::~ViewWindow() { close(); }

void ViewWindow::close() {
  if (layer_texture_) SDL_DestroyTexture(layer_texture_);
  if (texture_) SDL_DestroyTexture(texture_);
  if (renderer_) SDL_DestroyRenderer(renderer_);
  if (window_) SDL_DestroyWindow(window_);
  layer_texture_ = nullptr, texture_ = nullptr, renderer_ = nullptr, window_ = nullptr;
  SDL_Quit();
}

void ViewWindow::draw(const Framebuffer& frame, const WindowLayer& layer) {
  if (frame.width() != width_ || frame.height() != height_ ||
      frame.format() != ColorFormat::rgba8_srgb) {
    throw Error("view: the frame does not match the window's texture");
  }
  SDL_UpdateTexture(texture_, nullptr, frame.rgba8().data(), width_ * 4);
  SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
  SDL_RenderClear(renderer_);
  SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
  if (layer.image != nullptr) draw_layer(layer);
}

void ViewWindow::draw_layer(const WindowLayer& layer) {
  const Framebuffer& image = *layer.image;
  if (image.format() != ColorFormat::rgba8_srgb) {
    throw Error("view: the window layer must be an rgba8_srgb framebuffer");
  }
  if (image.width() != layer_width_ || image.height() != layer_height_) {
    if (layer_texture_) SDL_DestroyTexture(layer_texture_);
    layer_width_ = layer_height_ = 0;
    layer_texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32,
                                       SDL_TEXTUREACCESS_STREAMING, image.width(), image.height());
    if (!layer_texture_) {
      throw Error(std::string("view: cannot create the overlay's texture (") + SDL_GetError() +
                  ")");
    }
    layer_width_ = image.width(), layer_height_ = image.height();
    SDL_SetTextureBlendMode(layer_texture_, SDL_BLENDMODE_BLEND);
  }
  SDL_UpdateTexture(layer_texture_, nullptr, image.rgba8().data(), image.width() * 4);
  // In window pixels: lift the logical size (the frame's) for this copy.
  SDL_RenderSetLogicalSize(renderer_, 0, 0);
  SDL_RenderSetViewport(renderer_, nullptr);
  const SDL_Rect where{layer.x, layer.y, image.width(), image.height()};
  SDL_RenderCopy(renderer_, layer_texture_, nullptr, &where);
  SDL_RenderSetLogicalSize(renderer_, width_, height_);
}

void ViewWindow::present(const Framebuffer& frame, const WindowLayer& layer) {
  draw(frame, layer);
  SDL_RenderPresent(renderer_);
}

void ViewWindow::set_render_size(int width, int height) {
  if (width == width_ && height == height_) return;
  SDL_Texture* texture = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32,
                                           SDL_TEXTUREACCESS_STREAMING, width, height);
  if (!texture) {
    std::string message = "view: cannot create a ";
    message += std::to_string(width) + "x" + std::to_string(height) + " texture (";
    message += SDL_GetError();
    throw Error(message + ")");
  }
  SDL_DestroyTexture(texture_);
  texture_ = texture;
  width_ = width, height_ = height;
  SDL_RenderSetLogicalSize(renderer_, width, height);
}

void ViewWindow::set_fullscreen(bool fullscreen) {
  bool now = (SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
  if (fullscreen == now) return;
  if (fullscreen) SDL_GetWindowSize(window_, &windowed_width_, &windowed_height_);
  SDL_SetWindowFullscreen(window_, fullscreen ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
  // Without a window manager (Xvfb, kiosks) nothing restores the old size; ask for it.
  if (!fullscreen) SDL_SetWindowSize(window_, windowed_width_, windowed_height_);
}

void ViewWindow::window_size(int& width, int& height) const {
  SDL_GetRendererOutputSize(renderer_, &width, &height);
}

Framebuffer ViewWindow::capture(const Framebuffer& frame, const WindowLayer& layer) {
  draw(frame, layer);
  int width = 0, height = 0;
  window_size(width, height);
  Framebuffer shot(width, height);
  // The logical size limits reads to the letterboxed frame; lift it to read the bars too.
  SDL_RenderSetLogicalSize(renderer_, 0, 0);
  SDL_RenderSetViewport(renderer_, nullptr);
  int status = SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGBA32, shot.rgba8().data(),
                                    width * 4);
  SDL_RenderSetLogicalSize(renderer_, width_, height_);
  if (status != 0)
    throw Error(std::string("view: cannot read the window (") + SDL_GetError() + ")");
  return shot;
}

}  // namespace facet::cli
