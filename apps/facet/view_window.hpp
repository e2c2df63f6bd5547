// The viewer's window: an SDL2 window with a software SDL_Renderer and one streaming RGBA8
// texture of the render resolution. facet renders into its Framebuffer; present() uploads it
// and SDL scales it to the window with letterboxing (no OpenGL anywhere).
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

  // Uploads an rgba8_srgb framebuffer of the size given at construction and shows it.
  void present(const Framebuffer& frame);

 private:
  void close();  // destroys what exists and shuts SDL down

  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  int width_;
  int height_;
};

}  // namespace facet::cli
