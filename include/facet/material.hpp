// Material: how a draw is shaded — a shading model, a base color and options.
// Zero-initialized fields mean sensible defaults.
#pragma once

#include <glm/vec4.hpp>
#include <string_view>

namespace facet {

enum class ShadingModel {
  unlit,         // base color x vertex color
  vertex_color,  // vertex color only
  flat,          // one lit color per triangle from its face normal
  lambert,       // per-pixel diffuse + ambient from the directional light
  depth,         // debug: linear view depth, near -> white ... far -> black
  normals,       // debug: world normal as n * 0.5 + 0.5, not sRGB-encoded
  wireframe,     // edges only
  wire_overlay,  // lambert with edges drawn on top
};

enum class CullMode { back, front, none };

struct Material {
  ShadingModel shading = ShadingModel::lambert;
  glm::vec4 base_color{1.0f, 1.0f, 1.0f, 1.0f};     // linear RGBA
  bool use_vertex_colors = true;                    // multiply by the mesh's vertex colors
  glm::vec4 wire_color{0.02f, 0.02f, 0.02f, 1.0f};  // for wireframe and wire_overlay
  CullMode cull = CullMode::back;  // front faces are counter-clockwise, as in OpenGL
};

// Names as used on the command line ("wire_overlay"), and back.
std::string_view to_string(ShadingModel model);
std::string_view to_string(CullMode mode);
// Returns false if the name is unknown.
bool parse_shading_model(std::string_view name, ShadingModel& out);
bool parse_cull_mode(std::string_view name, CullMode& out);

}  // namespace facet
