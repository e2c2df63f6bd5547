// The viewer's overlay (see view_overlay.hpp).
#include "view_overlay.hpp"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "view_bindings.hpp"

namespace facet::cli {
namespace {

constexpr double kChangeSeconds = 2.0;
constexpr float kMargin = 8.0f;
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
    ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;

glm::vec4 unpack_color(ImU32 c) {  // IM_COL32: R in the lowest byte
  return glm::vec4(c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, (c >> 24) & 0xff) / 255.0f;
}

void stats_panel(const OverlayInfo& info) {
  ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin));
  ImGui::SetNextWindowBgAlpha(0.6f);
  if (ImGui::Begin("stats", nullptr, kPanelFlags)) {
    ImGui::Text("%.2f ms  %.1f fps", info.frame_ms, info.fps);
    ImGui::Text("%dx%d  fov %.0f", info.size.width, info.size.height, info.fov_degrees);
    ImGui::Text("%llu triangles", static_cast<unsigned long long>(info.triangles));
    if (info.threads == 0) {
      ImGui::Text("threads: all cores");
    } else {
      ImGui::Text("threads: %d", info.threads);
    }
    ImGui::Text("mode: %s", info.mode.c_str());
    ImGui::Text("shading: %s", info.shading.c_str());
    ImGui::Text("camera: %s", info.camera.c_str());
    if (!info.sound.empty()) ImGui::Text("sound: %s", info.sound.c_str());
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
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  std::vector<std::uint8_t> rgba(pixels, pixels + static_cast<std::size_t>(width) * height * 4);
  font_ = Texture::from_rgba8(width, height, std::move(rgba), false, "imgui-font");
  io.Fonts->SetTexID(static_cast<ImTextureID>(font_.get()));
  ImGui::StyleColorsDark();
  // Tight rows, so the help panel fits a 640x360 frame.
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

void ViewOverlay::draw(Framebuffer& frame, const OverlayInfo& info, bool stats, bool help,
                       double now, double dt) {
  bool changing = now < change_until_;
  if (!stats && !help && !changing) return;
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(frame.width()), static_cast<float>(frame.height()));
  io.DeltaTime = static_cast<float>(std::max(dt, 1e-4));
  ImGui::NewFrame();
  if (stats && !help) stats_panel(info);  // the help covers it anyway
  if (changing) change_panel(change_, io.DisplaySize);
  if (help) help_panel(io.DisplaySize);
  ImGui::Render();
  render_draw_data(frame);
}

void ViewOverlay::render_draw_data(Framebuffer& frame) {
  const ImDrawData* data = ImGui::GetDrawData();
  for (int l = 0; l < data->CmdListsCount; ++l) {
    const ImDrawList* list = data->CmdLists[l];
    vertices_.clear();
    for (const ImDrawVert& v : list->VtxBuffer) {
      vertices_.push_back({{v.pos.x - data->DisplayPos.x, v.pos.y - data->DisplayPos.y},
                           {v.uv.x, v.uv.y},
                           unpack_color(v.col)});
    }
    indices_.assign(list->IdxBuffer.begin(), list->IdxBuffer.end());
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback) continue;  // we install none
      ImVec4 clip = cmd.ClipRect;
      OverlayDraw draw;
      draw.vertices = std::span<const OverlayVertex>(vertices_).subspan(cmd.VtxOffset);
      draw.indices = std::span<const std::uint32_t>(indices_).subspan(cmd.IdxOffset, cmd.ElemCount);
      draw.texture = static_cast<const Texture*>(cmd.GetTexID());
      draw.scissor = {static_cast<int>(std::floor(clip.x - data->DisplayPos.x)),
                      static_cast<int>(std::floor(clip.y - data->DisplayPos.y)),
                      static_cast<int>(std::ceil(clip.z - data->DisplayPos.x)),
                      static_cast<int>(std::ceil(clip.w - data->DisplayPos.y))};
      draw_overlay(frame, draw);
    }
  }
}

}  // namespace facet::cli
