// Dear ImGui drawn by facet (see imgui_drawing.hpp).
#include "imgui_drawing.hpp"

#include <cmath>
#include <span>

namespace facet::cli {
namespace {

glm::vec4 unpack_color(ImU32 c) {  // IM_COL32: R in the lowest byte
  return glm::vec4(c & 0xff, (c >> 8) & 0xff, (c >> 16) & 0xff, (c >> 24) & 0xff) / 255.0f;
}

}  // namespace

std::shared_ptr<Texture> make_imgui_font_texture() {
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  std::vector<std::uint8_t> rgba(pixels, pixels + static_cast<std::size_t>(width) * height * 4);
  std::shared_ptr<Texture> font =
      Texture::from_rgba8(width, height, std::move(rgba), false, "imgui-font");
  io.Fonts->SetTexID(static_cast<ImTextureID>(font.get()));
  return font;
}

void draw_imgui(const ImDrawData& data, Framebuffer& target, ImVec2 origin,
                std::vector<OverlayVertex>& vertices, std::vector<std::uint32_t>& indices) {
  const float left = data.DisplayPos.x + origin.x, top = data.DisplayPos.y + origin.y;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList* list = data.CmdLists[l];
    vertices.clear();
    for (const ImDrawVert& v : list->VtxBuffer) {
      vertices.push_back({{v.pos.x - left, v.pos.y - top}, {v.uv.x, v.uv.y}, unpack_color(v.col)});
    }
    indices.assign(list->IdxBuffer.begin(), list->IdxBuffer.end());
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback) continue;  // none is installed
      ImVec4 clip = cmd.ClipRect;
      OverlayDraw draw;
      draw.vertices = std::span<const OverlayVertex>(vertices).subspan(cmd.VtxOffset);
      draw.indices = std::span<const std::uint32_t>(indices).subspan(cmd.IdxOffset, cmd.ElemCount);
      draw.texture = static_cast<const Texture*>(cmd.GetTexID());
      draw.scissor = {
          static_cast<int>(std::floor(clip.x - left)), static_cast<int>(std::floor(clip.y - top)),
          static_cast<int>(std::ceil(clip.z - left)), static_cast<int>(std::ceil(clip.w - top))};
      draw_overlay(target, draw);
    }
  }
}

}  // namespace facet::cli
