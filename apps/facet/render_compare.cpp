// Side-by-side variants (see render_compare.hpp).
#include "render_compare.hpp"

#include <imgui.h>

#include <algorithm>
#include <memory>

#include "facet/error.hpp"
#include "imgui_drawing.hpp"

namespace facet::cli {
namespace {

constexpr int kMaxWidth = 8192;  // as --size

std::string known_names() {
  std::string names = "facet, gl, none, pbr-neutral, aces";
  for (std::string_view model : shading_model_names()) names += ", " + std::string(model);
  return names;
}

// Writes each panel's name at its top-left corner, white on a dark box, with Dear ImGui's
// built-in font (drawn by facet's overlay, as the viewer's panels are).
void label_panels(Framebuffer& picture, const std::vector<CompareVariant>& variants,
                  int panel_width) {
  ImGuiContext* context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  const std::shared_ptr<Texture> font = make_imgui_font_texture();
  io.DisplaySize =
      ImVec2(static_cast<float>(picture.width()), static_cast<float>(picture.height()));
  io.DeltaTime = 1.0f / 60.0f;
  ImGui::NewFrame();
  ImDrawList* list = ImGui::GetForegroundDrawList();
  constexpr float kMargin = 6.0f, kPadding = 4.0f;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const char* text = variants[i].name.c_str();
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 at(static_cast<float>(i) * panel_width + kMargin + kPadding, kMargin + kPadding);
    list->AddRectFilled(ImVec2(at.x - kPadding, at.y - kPadding),
                        ImVec2(at.x + size.x + kPadding, at.y + size.y + kPadding),
                        IM_COL32(0, 0, 0, 170), 3.0f);
    list->AddText(at, IM_COL32(255, 255, 255, 255), text);
  }
  ImGui::Render();
  std::vector<OverlayVertex> vertices;
  std::vector<std::uint32_t> indices;
  draw_imgui(*ImGui::GetDrawData(), picture, ImVec2(0.0f, 0.0f), vertices, indices);
  ImGui::DestroyContext(context);
}

}  // namespace

std::vector<CompareVariant> parse_compare(const std::string& list, Backend backend) {
  std::vector<CompareVariant> variants;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    CompareVariant v;
    v.name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    v.backend = backend;
    if (v.name == "facet" || v.name == "gl") {
      v.backend = parse_backend("--compare", v.name);
    } else if (parse_shading_model(v.name, v.shading)) {
      v.shaded_as = true;
    } else if (v.name == "none" || v.name == "pbr-neutral" || v.name == "aces") {
      v.tone_mapping = parse_tone_mapping(v.name);
    } else {
      throw Error("--compare: '" + v.name +
                  "' is neither a shading model, a backend nor a tone mapping (" + known_names() +
                  ")");
    }
    for (const CompareVariant& earlier : variants) {
      if (earlier.name == v.name) throw Error("--compare: " + v.name + " is named twice");
    }
    variants.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (variants.size() < 2)
    throw Error("--compare: name at least two variants, separated by commas");
  return variants;
}

Framebuffer render_comparison(const std::vector<CompareVariant>& variants, const Scene& scene,
                              const Camera& camera, ImageSize size,
                              const RenderSettings& settings) {
  const int count = static_cast<int>(variants.size());
  if (size.width > kMaxWidth / count) {
    throw Error("--compare: " + std::to_string(count) + " panels of " + std::to_string(size.width) +
                " pixels are wider than " + std::to_string(kMaxWidth) + "; make --size smaller");
  }
  Framebuffer picture(count * size.width, size.height, ColorFormat::rgba8_srgb, DepthImage::none);
  Framebuffer panel(size.width, size.height, ColorFormat::rgba8_srgb, DepthImage::none);
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<GlBackend> gl;  // made when a variant asks for it
  ToneMapping made_with = settings.tone_mapping;
  for (int i = 0; i < count; ++i) {
    const CompareVariant& v = variants[i];
    // The renderers are made again for a variant of another tone mapping.
    RenderSettings own = settings;
    own.tone_mapping = v.tone_mapping.value_or(settings.tone_mapping);
    if (own.tone_mapping != made_with) renderer.reset(), gl.reset();
    made_with = own.tone_mapping;
    Scene variant = scene;  // materials copied; meshes and textures shared
    if (v.shaded_as) {
      for (Material& material : variant.materials) material.shading = v.shading;
    }
    if (v.backend == Backend::gl) {
      if (!gl) gl = make_gl_backend(own);
      gl->render(variant, camera, panel);
    } else {
      if (!renderer) renderer = std::make_unique<Renderer>(own);
      renderer->begin_frame(camera, variant.lighting);
      draw_scene(*renderer, variant);
      renderer->finish(panel);
    }
    const std::size_t row = static_cast<std::size_t>(size.width) * 4;
    for (int y = 0; y < size.height; ++y) {
      std::copy_n(panel.rgba8().data() + y * row, row,
                  picture.rgba8().data() + (static_cast<std::size_t>(y) * count + i) * row);
    }
  }
  label_panels(picture, variants, size.width);
  return picture;
}

}  // namespace facet::cli
