// The viewer's window: an SDL2 window with a software SDL_Renderer and one streaming RGBA8
// texture of the render resolution. facet renders into its Framebuffer; present() uploads it
// and SDL scales it to the window with letterboxing (no OpenGL anywhere), then blends a layer
// of window resolution over it (the F1 help). Also: a new render resolution, fullscreen, and a
// capture of what the window shows (bars and layer included).
#pragma once

#include <string>

#include "facet/framebuffer.hpp"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

namespace facet::cli {

// An image drawn over the window at the window's own resolution, after the scaled frame: panels
// that must stay readable whatever the render resolution. Straight (not premultiplied) alpha;
// (x, y) is its top-left corner in window pixels.
struct WindowLayer {
  const Framebuffer* image = nullptr;
  int x = 0, y = 0;
};

class ViewWindow {
 public:
  // The smallest window: the F1 help panel's rows fit it (view_overlay.cpp).
  static constexpr int kMinWidth = 640, kMinHeight = 360;

  // Opens a resizable window showing width x height frames. Its size is the frame's times the
  // smallest whole number that makes it at least kMinWidth x kMinHeight (a 320x180 render
  // opens a 640x360 window), a smaller multiple where that would not fit the display, and never
  // less than kMinWidth x kMinHeight. Throws facet::Error with one line suggesting xvfb-run or
  // `facet render` when there is no display.
  ViewWindow(const std::string& title, int width, int height);
  ~ViewWindow();
  ViewWindow(const ViewWindow&) = delete;
  ViewWindow& operator=(const ViewWindow&) = delete;

  // Uploads an rgba8_srgb framebuffer of the render size and shows it, with `layer` (if it
  // has an image) blended over it.
  void present(const Framebuffer& frame, const WindowLayer& layer = {});

  // Frames are width x height from now on (the window keeps its size).
  void set_render_size(int width, int height);
  // Fullscreen on the window's display (SDL_WINDOW_FULLSCREEN_DESKTOP: no mode change), or
  // back to the window.
  void set_fullscreen(bool fullscreen);
  // The window's drawable size in pixels.
  void window_size(int& width, int& height) const;
  // What the window shows for `frame` and `layer`: the frame scaled into the window with its
  // bars, and the layer over them.
  Framebuffer capture(const Framebuffer& frame, const WindowLayer& layer = {});

 private:
  void close();  // destroys what exists and shuts SDL down
  // Uploads and draws the frame and the layer, not yet shown.
  void draw(const Framebuffer& frame, const WindowLayer& layer);
  void draw_layer(const WindowLayer& layer);

  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  SDL_Texture* layer_texture_ = nullptr;  // the layer's, remade when its size changes
  int layer_width_ = 0, layer_height_ = 0;
  int width_;
  int height_;
  int windowed_width_ = 0, windowed_height_ = 0;  // the window's size before fullscreen
};

}  // namespace facet::cli
