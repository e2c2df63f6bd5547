// The viewer's overlay (see view_overlay.hpp).
#include "view_overlay.hpp"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "imgui_drawing.hpp"
#include "view_bindings.hpp"

namespace facet::cli {
namespace {

constexpr double kChangeSeconds = 2.0;
constexpr float kMargin = 8.0f;
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
    ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;

void stats_panel(const OverlayInfo& info) {
  ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin));
  ImGui::SetNextWindowBgAlpha(0.6f);
  if (ImGui::Begin("stats", nullptr, kPanelFlags)) {
    ImGui::Text("%.2f ms  %.1f fps", info.frame_ms, info.fps);
    ImGui::Text("%dx%d  fov %.0f", info.size.width, info.size.height, info.fov_degrees);
    if (info.lines > 0) {  // wireframe: its edges are lines
      ImGui::Text("%llu triangles, %llu lines", static_cast<unsigned long long>(info.triangles),
                  static_cast<unsigned long long>(info.lines));
    } else {
      ImGui::Text("%llu triangles", static_cast<unsigned long long>(info.triangles));
    }
    if (info.threads == 0) {
      ImGui::Text("threads: all cores");
    } else {
      ImGui::Text("threads: %d", info.threads);
    }
    if (info.msaa > 1) {
      ImGui::Text("msaa: %dx (F10)", info.msaa);
    } else {
      ImGui::Text("msaa: off (F10)");
    }
    ImGui::Text("tone mapping: %s (T)", info.tone_mapping.c_str());
    ImGui::Text("shadows: %s", info.shadows ? "on" : "off");
    ImGui::Text("reflections: %s", info.reflections ? "on" : "off");
    ImGui::Text("mode: %s", info.mode.c_str());
    ImGui::Text("shading: %s", info.shading.c_str());
    ImGui::Text("camera: %s", info.camera.c_str());
    if (!info.sound.empty()) ImGui::Text("sound: %s", info.sound.c_str());
    ImGui::Text("backend: %s (B), %.1f ms", info.backend.c_str(), info.backend_ms);
    if (!info.gl_name.empty()) ImGui::Text("OpenGL: %s", info.gl_name.c_str());
    ImGui::TextDisabled("F1 help");
  }
  ImGui::End();
}

void change_panel(const std::string& message, const ImVec2& display) {
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y - kMargin), 0, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  if (ImGui::Begin("change", nullptr, kPanelFlags)) ImGui::TextUnformatted(message.c_str());
  ImGui::End();
}

void help_panel(const ImVec2& display) {
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), 0, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("help", nullptr, kPanelFlags)) {
    ImGui::TextUnformatted("facet view: keys");
    ImGui::Separator();
    if (ImGui::BeginTable("keys", 2)) {
      for (const ViewBinding& b : kViewBindings) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(b.keys);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(b.action);
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

// The box in display pixels that the panels' vertices reach, within the display.
OverlayRect panels_box(const ImDrawData& data, int display_width, int display_height) {
  float x0 = static_cast<float>(display_width), y0 = static_cast<float>(display_height);
  float x1 = 0.0f, y1 = 0.0f;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    for (const ImDrawVert& v : data.CmdLists[l]->VtxBuffer) {
      x0 = std::min(x0, v.pos.x), y0 = std::min(y0, v.pos.y);
      x1 = std::max(x1, v.pos.x), y1 = std::max(y1, v.pos.y);
    }
  }
  return {std::max(0, static_cast<int>(std::floor(x0))),
          std::max(0, static_cast<int>(std::floor(y0))),
          std::min(display_width, static_cast<int>(std::ceil(x1))),
          std::min(display_height, static_cast<int>(std::ceil(y1)))};
}

// draw_overlay blends "over" in the image: over transparent black that leaves color x alpha,
// and a window blends straight alpha.
void to_straight_alpha(std::vector<std::uint8_t>& rgba) {
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    const unsigned alpha = rgba[i + 3];
    if (alpha == 0 || alpha == 255) continue;
    for (std::size_t c = i; c < i + 3; ++c) {
      rgba[c] = static_cast<std::uint8_t>(std::min(255u, (rgba[c] * 255u + alpha / 2) / alpha));
    }
  }
}

}  // namespace

ViewOverlay::ViewOverlay() {
  IMGUI_CHECKVERSION();
  context_ = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the user's directory
  io.LogFilename = nullptr;
  // facet draws VtxOffset correctly, so ImGui may emit lists of more than 64K vertices.
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  io.BackendRendererName = "facet";
  font_ = make_imgui_font_texture();
  ImGui::StyleColorsDark();
  // Tight rows, so the help panel fits a 640x360 window.
  ImGui::GetStyle().ItemSpacing.y = 1.0f;
  ImGui::GetStyle().CellPadding.y = 0.0f;
}

ViewOverlay::~ViewOverlay() { ImGui::DestroyContext(context_); }

void ViewOverlay::handle(const SDL_Event& event) {
  ImGuiIO& io = ImGui::GetIO();
  switch (event.type) {
    case SDL_MOUSEMOTION:
      io.MousePos = ImVec2(static_cast<float>(event.motion.x), static_cast<float>(event.motion.y));
      break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP: {
      int button = event.button.button == SDL_BUTTON_LEFT     ? 0
                   : event.button.button == SDL_BUTTON_RIGHT  ? 1
                   : event.button.button == SDL_BUTTON_MIDDLE ? 2
                                                              : -1;
      if (button >= 0) io.MouseDown[button] = event.type == SDL_MOUSEBUTTONDOWN;
      break;
    }
    case SDL_MOUSEWHEEL:
      io.MouseWheel += static_cast<float>(event.wheel.y);
      break;
    default:
      break;
  }
}

void ViewOverlay::show_change(const std::string& message, double now) {
  change_ = message;
  change_until_ = now + kChangeSeconds;
}

WindowLayer ViewOverlay::draw(Framebuffer& frame, const OverlayInfo& info, bool stats, bool help,
                              int window_width, int window_height, double now, double dt) {
  const bool changing = now < change_until_;
  if (!stats && !help && !changing) return {};
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DeltaTime = static_cast<float>(std::max(dt, 1e-4));
  if (help) return draw_layer(window_width, window_height, changing);
  io.DisplaySize = ImVec2(static_cast<float>(frame.width()), static_cast<float>(frame.height()));
  ImGui::NewFrame();
  if (stats) stats_panel(info);
  if (changing) change_panel(change_, io.DisplaySize);
  ImGui::Render();
  render_draw_data(frame, ImVec2(0.0f, 0.0f));
  return {};
}

// The help (which covers the statistics anyway) and the change panel over the whole window,
// drawn into an image of just the panels' box, which the window blends over the frame.
WindowLayer ViewOverlay::draw_layer(int window_width, int window_height, bool changing) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(window_width), static_cast<float>(window_height));
  ImGui::NewFrame();
  if (changing) change_panel(change_, io.DisplaySize);
  help_panel(io.DisplaySize);
  ImGui::Render();

  const OverlayRect box = panels_box(*ImGui::GetDrawData(), window_width, window_height);
  const int left = box.x0, top = box.y0, right = box.x1, bottom = box.y1;
  if (left >= right || top >= bottom) return {};  // nothing drawn (a panel's first frame)

  if (!layer_ || layer_->width() != right - left || layer_->height() != bottom - top) {
    layer_.emplace(right - left, bottom - top, ColorFormat::rgba8_srgb, DepthImage::none);
  }
  std::vector<std::uint8_t>& rgba = layer_->rgba8();
  std::fill(rgba.begin(), rgba.end(), std::uint8_t{0});
  render_draw_data(*layer_, ImVec2(static_cast<float>(left), static_cast<float>(top)));
  to_straight_alpha(rgba);
  return {&*layer_, left, top};
}

void ViewOverlay::render_draw_data(Framebuffer& target, ImVec2 origin) {
  draw_imgui(*ImGui::GetDrawData(), target, origin, vertices_, indices_);
}

}  // namespace facet::cli
