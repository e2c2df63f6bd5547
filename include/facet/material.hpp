// Material: how a draw is shaded — a shading model, colors, texture maps, transparency.
// Default-constructed fields mean sensible defaults: a white, opaque, Lambert-lit surface.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "facet/texture.hpp"

namespace facet {

enum class ShadingModel {
  unlit,         // base color x vertex color x base color map, no lighting
  vertex_color,  // vertex color only
  flat,          // one lit (diffuse) color per triangle from its face normal
  lambert,       // per-pixel diffuse + ambient
  gouraud,       // Blinn-Phong lighting evaluated per vertex, color interpolated
  phong,         // per-pixel Phong: ambient, diffuse, specular (reflection vector)
  blinn_phong,   // per-pixel Blinn-Phong (half vector)
  pbr,           // Cook-Torrance: GGX, Smith, Schlick; metallic-roughness
  depth,         // debug: linear view depth, near -> white ... far -> black
  normals,       // debug: world normal as n * 0.5 + 0.5, not sRGB-encoded: in an 8-bit target
                 // the code round(255 (n * 0.5 + 0.5)), in a float target the value itself
  texcoords,     // debug: texture coordinates as red/green (fractional part)
  wireframe,     // edges only
  wire_overlay,  // lambert with edges drawn on top
};

enum class CullMode { back, front, none };

// How a draw's alpha is used (glTF alphaMode, plus additive for glow and fire).
enum class AlphaMode {
  opaque,    // alpha ignored
  mask,      // cut-out: pixels with alpha < alpha_cutoff are discarded
  blend,     // "over" blending, drawn after opaque draws, back to front, no depth write
  additive,  // color x alpha added, drawn with the blended draws
};

// A texture map: the image, how it is sampled, and a transform of the texture coordinates
// (KHR_texture_transform / MTL -o -s): uv' = (transform * vec3(uv, 1)).xy; the identity (the
// default) leaves uv as it is.
struct TextureMap {
  std::shared_ptr<const Texture> texture;  // null: no map
  Sampler sampler;
  glm::mat3 transform{1.0f};
  explicit operator bool() const { return texture != nullptr; }
};

struct Material {
  std::string name;
  ShadingModel shading = ShadingModel::lambert;
  glm::vec4 base_color{1.0f, 1.0f, 1.0f, 1.0f};  // linear RGBA (diffuse color for Phong)
  bool use_vertex_colors = true;                 // multiply by the mesh's vertex colors

  // Phong / Blinn-Phong / Gouraud.
  glm::vec3 specular_color{0.25f};
  float shininess = 32.0f;

  // Physically based (metallic-roughness). Specular-glossiness materials are converted.
  float metallic = 0.0f;
  float roughness = 0.6f;

  glm::vec3 emissive{0.0f};   // linear RGB, added unlit
  float reflectivity = 0.0f;  // Phong models: mix toward the environment's reflection
  // A flat mirror (a floor, a lake, the sea): what Phong models mix in by reflectivity, and PBR
  // takes as the light from the mirror direction, is the scene itself, drawn mirrored through
  // the mesh's plane by a pass of its own (RenderSettings::reflections), blurred by the
  // roughness (PBR) or the highlight's exponent (Phong), not only the environment. A mesh that
  // is not flat reflects the environment alone.
  bool reflects_scene = false;
  // Whether the draw casts shadows (RenderSettings::shadows). Off for a surface with nothing
  // seen beneath it (a sea, the floor at the bottom of a world): as a caster it could shade only
  // what it hides, and the shadow maps' passes skip it.
  bool casts_shadows = true;

  TextureMap base_color_map;  // sRGB
  TextureMap normal_map;      // tangent space, linear
  float normal_scale = 1.0f;
  TextureMap specular_map;            // Phong: specular color (rgb), sRGB
  TextureMap metallic_roughness_map;  // glTF packing: roughness in G, metallic in B; linear
  TextureMap occlusion_map;           // R channel, linear
  float occlusion_strength = 1.0f;
  TextureMap emissive_map;  // sRGB

  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;

  glm::vec4 wire_color{0.02f, 0.02f, 0.02f, 1.0f};  // for wireframe and wire_overlay
  // Topology::points meshes: each point's square, this many pixels a side, in (0, kMaxPointSize].
  static constexpr float kMaxPointSize = 256.0f;
  float point_size = 3.0f;
  CullMode cull = CullMode::back;  // front faces are counter-clockwise, as in OpenGL
};

// Names as used on the command line ("wire_overlay"), and back.
std::string_view to_string(ShadingModel model);
std::string_view to_string(CullMode mode);
std::string_view to_string(AlphaMode mode);
// Every shading model name, in declaration order (for help texts and UI cycling).
std::vector<std::string_view> shading_model_names();
// Returns false if the name is unknown.
bool parse_shading_model(std::string_view name, ShadingModel& out);
bool parse_cull_mode(std::string_view name, CullMode& out);

}  // namespace facet
