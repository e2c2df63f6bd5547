// The viewer's overlay: Dear ImGui panels (frame statistics, the last setting changed, the F1
// help) whose draw lists facet itself draws into the frame with draw_overlay (no OpenGL, no
// ImGui renderer backend). Input reaches ImGui from the SDL events the loop already reads.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "facet/framebuffer.hpp"
#include "facet/overlay.hpp"
#include "facet/texture.hpp"

union SDL_Event;
struct ImGuiContext;

namespace facet::cli {

// What the statistics panel shows.
struct OverlayInfo {
  double frame_ms = 0;  // smoothed
  double fps = 0;       // smoothed
  ImageSize size;
  float fov_degrees = 0;
  std::uint64_t triangles = 0;  // FrameStats::drawn
  int threads = 0;              // 0 = all cores
  std::string mode, shading, camera;
  std::string sound;  // "on", "muted", "off (no device)"; empty: the scene has none
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
  // Builds this frame's panels and draws them over `frame`: the statistics when `stats`, the
  // help when `help`, the change panel while it lasts.
  void draw(Framebuffer& frame, const OverlayInfo& info, bool stats, bool help, double now,
            double dt);

 private:
  void render_draw_data(Framebuffer& frame);

  ImGuiContext* context_ = nullptr;
  std::shared_ptr<Texture> font_;
  std::string change_;
  double change_until_ = -1.0;
  std::vector<OverlayVertex> vertices_;  // one draw list's, reused
  std::vector<std::uint32_t> indices_;
};

}  // namespace facet::cli
