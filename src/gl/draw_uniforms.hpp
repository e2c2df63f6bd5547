// Setting a program's uniforms: what every draw of a frame shares (camera, lights, fog,
// environment) and what is the draw's own (transforms, material, texture maps). The names are
// the GLSL's (glsl_common.cpp, glsl_stages.cpp, glsl_fragment.cpp).
#pragma once

#include <glm/glm.hpp>

#include "facet/light.hpp"
#include "facet/material.hpp"
#include "gl/draw_list.hpp"
#include "gl/gl_program.hpp"
#include "gl/gpu_resources.hpp"

namespace facet::gl {

// Texture units: one per material map, then the environment.
inline constexpr int kEnvironmentUnit = 6;

struct FrameState {
  std::uint64_t number = 0;  // counts frames from 1, so a program knows whose constants it holds
  const Lighting* lighting = nullptr;
  // The fog color drawn: the lighting's, or under tone mapping what the curve shows as it
  // (facet::inverse_tone_map), as facet's frame fogs.
  glm::vec3 fog_color{0.0f};
  glm::vec3 eye{0.0f};            // Camera::shading_eye
  glm::vec3 view_depth{1, 0, 0};  // from_w, from_z, offset (shading/uniforms.hpp's ViewDepth)
  float depth_view_near = 0.1f, depth_view_far = 100.0f;
  bool display_exact = false;  // a float target
  glm::mat4 view_projection{1.0f};
  glm::ivec2 viewport{1, 1};  // the target's size in pixels
};

// Sets the frame's constants unless the program holds them already.
void set_frame_uniforms(Program& program, const FrameState& frame);
// material is the one the program shades with (a vertex-color draw gets a white base color).
void set_draw_uniforms(Program& program, const GlDraw& draw, const Material& material,
                       const FrameState& frame, bool has_normals, GpuResources& resources);

}  // namespace facet::gl
