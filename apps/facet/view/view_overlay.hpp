// The viewer's overlay: Dear ImGui panels (frame statistics, the last setting changed, the F1
// help) whose draw lists facet itself draws with draw_overlay (no OpenGL, no ImGui renderer
// backend): into the frame, or, for the help, into a layer the window shows at its own
// resolution. Input reaches ImGui from the SDL events the loop already reads.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "facet/framebuffer.hpp"
#include "facet/overlay.hpp"
#include "facet/texture.hpp"
#include "view_window.hpp"

union SDL_Event;
struct ImGuiContext;
struct ImVec2;

namespace facet::cli {

// What the statistics panel shows.
struct OverlayInfo {
  double frame_ms = 0;  // smoothed
  double fps = 0;       // smoothed
  ImageSize size;
  float fov_degrees = 0;
  std::uint64_t triangles = 0;  // FrameStats::drawn
  std::uint64_t lines = 0;      // FrameStats::lines_drawn
  int threads = 0;              // 0 = all cores
  int msaa = 1;                 // samples per pixel
  std::string tone_mapping;     // "pbr-neutral", "aces" or "none" (T)
  bool shadows = false;         // --shadows
  bool reflections = false;     // --reflections
  std::string mode, shading, camera;
  std::string sound;      // "on", "muted", "off (no device)"; empty: the scene has none
  std::string backend;    // "facet", "gl" or "difference" (B)
  double backend_ms = 0;  // what the backend took to draw the frame
  std::string gl_name;    // the OpenGL renderer, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
};

class ViewOverlay {
 public:
  ViewOverlay();  // an ImGui context and its font atlas as a facet texture
  ~ViewOverlay();
  ViewOverlay(const ViewOverlay&) = delete;
  ViewOverlay& operator=(const ViewOverlay&) = delete;

  // Mouse position, buttons and wheel for ImGui (in render pixels: SDL maps them there).
  void handle(const SDL_Event& event);
  // Shows `message` in the change panel for two seconds from `now` (seconds).
  void show_change(const std::string& message, double now);
  // Builds this frame's panels and draws them. Without `help`: the statistics (when `stats`)
  // and the change panel (while it lasts) over `frame`. With `help`: the help and the change
  // panel at the window's resolution instead (window_width x window_height), into the returned
  // layer, so that the help is whole and readable at any render resolution (it does not fit a
  // 320x180 frame). The layer has no image when nothing is drawn in it.
  WindowLayer draw(Framebuffer& frame, const OverlayInfo& info, bool stats, bool help,
                   int window_width, int window_height, double now, double dt);

 private:
  WindowLayer draw_layer(int window_width, int window_height, bool changing);
  // Draws ImGui's draw data into target, whose top-left corner is at `origin` on ImGui's display.
  void render_draw_data(Framebuffer& target, ImVec2 origin);

  ImGuiContext* context_ = nullptr;
  std::shared_ptr<Texture> font_;
  std::string change_;
  double change_until_ = -1.0;
  std::vector<OverlayVertex> vertices_;  // one draw list's, reused
  std::vector<std::uint32_t> indices_;
  std::optional<Framebuffer> layer_;  // the window layer's image, remade when its size changes
};

}  // namespace facet::cli
