// The viewer's window: an SDL2 window with a software SDL_Renderer and one streaming RGBA8
// texture of the render resolution. facet renders into its Framebuffer; present() uploads it
// and SDL scales it to the window with letterboxing (no OpenGL anywhere). Also: a new render
// resolution, fullscreen, and a capture of what the window shows (bars included).
#pragma once

#include <string>

#include "facet/framebuffer.hpp"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

namespace facet::cli {

class ViewWindow {
 public:
  // Opens a resizable window showing width x height frames. Throws facet::Error with one line
  // suggesting xvfb-run or `facet render` when there is no display.
  ViewWindow(const std::string& title, int width, int height);
  ~ViewWindow();
  ViewWindow(const ViewWindow&) = delete;
  ViewWindow& operator=(const ViewWindow&) = delete;

  // Uploads an rgba8_srgb framebuffer of the render size and shows it.
  void present(const Framebuffer& frame);

  // Frames are width x height from now on (the window keeps its size).
  void set_render_size(int width, int height);
  // Fullscreen on the window's display (SDL_WINDOW_FULLSCREEN_DESKTOP: no mode change), or
  // back to the window.
  void set_fullscreen(bool fullscreen);
  // The window's drawable size in pixels.
  void window_size(int& width, int& height) const;
  // What the window shows for `frame`: the frame scaled into the window with its bars.
  Framebuffer capture(const Framebuffer& frame);

 private:
  void close();                         // destroys what exists and shuts SDL down
  void draw(const Framebuffer& frame);  // uploads and draws the frame, not yet shown

  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  int width_;
  int height_;
  int windowed_width_ = 0, windowed_height_ = 0;  // the window's size before fullscreen
};

}  // namespace facet::cli
