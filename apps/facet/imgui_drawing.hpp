// Dear ImGui drawn by facet: the font atlas as a facet texture, and a frame's draw data drawn
// into a framebuffer with draw_overlay. Shared by the viewer's panels (view/view_overlay.cpp) and
// the labels of `facet render --compare` (render_compare.cpp).
#pragma once

#include <imgui.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/overlay.hpp"
#include "facet/texture.hpp"

namespace facet::cli {

// The current ImGui context's font atlas as an rgba8 texture, set as the atlas's texture id
// (draw commands then name it). Keep it alive as long as the context draws.
std::shared_ptr<Texture> make_imgui_font_texture();

// Draws `data` into target, whose top-left corner is at `origin` on ImGui's display; vertices
// and indices are scratch space, reused between calls.
void draw_imgui(const ImDrawData& data, Framebuffer& target, ImVec2 origin,
                std::vector<OverlayVertex>& vertices, std::vector<std::uint32_t>& indices);

}  // namespace facet::cli
