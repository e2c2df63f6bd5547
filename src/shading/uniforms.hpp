// The constants the shading models read, per frame and per draw: written by the renderer
// (pipeline/renderer.cpp when a draw is recorded, pipeline/frame_run.cpp when the frame runs),
// read by vertex and fragment functions (shading/models.hpp) and the batch kernels.
#pragma once

#include <algorithm>
#include <cstdint>
#include <glm/glm.hpp>
#include <iterator>
#include <span>

#include "facet/light.hpp"
#include "facet/material.hpp"
#include "shading/environment_light.hpp"

namespace facet::shading {

struct ShadowMaps;        // shadow_map.hpp
struct PlanarReflection;  // planar_reflection.hpp

// A light prepared for shading: directions normalized, cone angles as cosines.
struct LightData {
  LightType type = LightType::directional;
  glm::vec3 position{0.0f};
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};         // directional: unit vector toward the light
  glm::vec3 spot_direction{0.0f, -1.0f, 0.0f};  // spot: unit, where the light travels
  glm::vec3 radiance{1.0f};                     // color * intensity
  float inv_range_squared = 0.0f;               // 0: unlimited
  float cos_inner = 1.0f;
  float cos_outer = 0.0f;
  // The light's shadow maps in a frame that renders them (pipeline/shadow_passes.cpp), else
  // null.
  const ShadowMaps* shadow = nullptr;
};

struct ShadingKernels;  // kernels.hpp

// A fragment's distance along the view axis, for fog and the depth view, from its clip w and
// window depth z: w itself under a perspective projection (from_w 1, the rest 0: exactly w's
// bits), near + z (far - near) under an orthographic one, whose w is always 1.
struct ViewDepth {
  float from_w = 1.0f;
  float from_z = 0.0f;
  float offset = 0.0f;
  float operator()(float w, float z) const { return from_w * w + from_z * z + offset; }
};

// What every draw of a frame shares, set once when the frame runs.
struct FrameUniforms {
  glm::vec3 eye{0.0f};  // where view directions point to, world space (Camera::shading_eye)
  glm::vec3 ambient{0.1f};
  const LightData* lights = nullptr;
  int light_count = 0;
  const Lighting* lighting = nullptr;  // fog and environment
  // The environment's light (environment_light.hpp) when it lights PBR materials, else null.
  const IrradianceHarmonics* environment_light = nullptr;
  float near_plane = 0.1f;
  float far_plane = 100.0f;
  glm::mat4 view{1.0f};        // the camera's view matrix (what the extra outputs measure in)
  glm::mat4 projection{1.0f};  // the camera's projection matrix
  int width = 0, height = 0;   // the target's size in pixels
  bool orthographic = false;   // the camera's projection is parallel
  ViewDepth view_depth;
  // Display values (models.hpp) are stored as code / 255, not decoded to
  // linear: in frames whose every color is one (8-bit targets), and in every float target.
  bool display_referred = false;
  // The target holds floats: the debug views' display values are stored as they are (the
  // normals view's n * 0.5 + 0.5 itself), not rounded to 8-bit codes.
  bool display_exact = false;
  // The view depths the depth view spans, white to black: the frame's draws' (their bounds'
  // nearest and farthest, within the near and far planes).
  float depth_view_near = 0.1f;
  float depth_view_far = 100.0f;
  const ShadingKernels* kernels = nullptr;  // the batch kernels of the frame's SIMD target
};

// What is the draw's own: its transforms and its material. The frame's are a pointer away.
struct DrawUniforms {
  glm::mat4 model{1.0f};
  glm::mat4 model_view_projection{1.0f};
  glm::mat3 normal_matrix{1.0f};       // inverse transpose of model's upper 3x3
  const Material* material = nullptr;  // the draw's own copy
  const FrameUniforms* frame = nullptr;
  std::uint32_t instance_id = 0;  // what the instance ids output shows (Renderer::set_instance_id)
  // The planar reflection of the draw's plane (Material::reflects_scene) in the color pass of a
  // frame that renders it; else null, and the draw reflects the environment alone.
  const PlanarReflection* reflection = nullptr;
};

// Whether every light (Light or LightData) is directional: then no light's direction depends on
// where the surface is (the Lambert form without the position, pipeline_for, and the batch
// kernel's reading of positions).
template <class Lights>
bool all_directional(const Lights& lights) {
  return std::all_of(std::begin(lights), std::end(lights),
                     [](const auto& light) { return light.type == LightType::directional; });
}
inline bool only_directional_lights(const DrawUniforms& u) {
  return all_directional(
      std::span(u.frame->lights, static_cast<std::size_t>(u.frame->light_count)));
}
// Whether a light of the frame has a shadow map: then the models lit per pixel read the pixels'
// positions, and the Lambert form without them is not taken.
inline bool any_shadowed_light(const DrawUniforms& u) {
  const std::span lights(u.frame->lights, static_cast<std::size_t>(u.frame->light_count));
  return std::any_of(lights.begin(), lights.end(),
                     [](const LightData& light) { return light.shadow != nullptr; });
}

// One vertex as the vertex functions see it: object-space attributes already fetched.
struct VertexInput {
  glm::vec3 position;  // object space
  glm::vec3 normal;    // world space, unit; zero when the mesh has none
  glm::vec4 color;     // linear RGBA (white when the mesh has none)
  glm::vec2 texcoord;
  glm::vec4 tangent;  // world space xyz, w handedness; zero when the mesh has none
};

}  // namespace facet::shading
