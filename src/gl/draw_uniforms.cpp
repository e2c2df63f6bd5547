// Uniforms of a frame and of a draw (see draw_uniforms.hpp).
#include "gl/draw_uniforms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "facet/error.hpp"
#include "gl/glsl_sources.hpp"

namespace facet::gl {
namespace {

// A uniform's name built from parts, e.g. "u_light_type[3]" or "u_normal_map.present".
struct Name {
  char text[64];
  Name(const char* array, int index) { std::snprintf(text, sizeof text, "%s[%d]", array, index); }
  Name(const char* block, const char* member) {
    std::snprintf(text, sizeof text, "%s.%s", block, member);
  }
};

// One light as facet prepares it for shading (shading/lighting.cpp's prepare_light).
void set_light(Program& p, int i, const Light& light) {
  const float length = glm::length(light.direction);
  const glm::vec3 travel = length > 0.0f ? light.direction / length : glm::vec3(0.0f, -1.0f, 0.0f);
  const float outer = std::clamp(light.outer_cone_degrees, 0.0f, 90.0f);
  const float inner = std::clamp(light.inner_cone_degrees, 0.0f, outer);
  const glm::vec3 radiance = light.color * light.intensity;
  glUniform1i(p.uniform(Name("u_light_type", i).text), static_cast<int>(light.type));
  glUniform3fv(p.uniform(Name("u_light_position", i).text), 1, glm::value_ptr(light.position));
  glUniform3fv(p.uniform(Name("u_light_to_light", i).text), 1, glm::value_ptr(-travel));
  glUniform3fv(p.uniform(Name("u_light_spot_direction", i).text), 1, glm::value_ptr(travel));
  glUniform3fv(p.uniform(Name("u_light_radiance", i).text), 1, glm::value_ptr(radiance));
  glUniform1f(p.uniform(Name("u_light_inv_range_squared", i).text),
              light.range > 0.0f ? 1.0f / (light.range * light.range) : 0.0f);
  glUniform1f(p.uniform(Name("u_light_cos_inner", i).text), std::cos(glm::radians(inner)));
  glUniform1f(p.uniform(Name("u_light_cos_outer", i).text), std::cos(glm::radians(outer)));
}

void set_vec3(Program& p, const char* name, glm::vec3 v) {
  glUniform3fv(p.uniform(name), 1, glm::value_ptr(v));
}

void set_map(Program& p, const char* name, int unit, const TextureMap& map,
             GpuResources& resources) {
  glUniform1i(p.uniform(Name(name, "present").text), map ? 1 : 0);
  glUniform1i(p.uniform(Name(name, "texture").text), unit);
  if (!map) return;
  glUniformMatrix3fv(p.uniform(Name(name, "transform").text), 1, GL_FALSE,
                     glm::value_ptr(map.transform));
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, resources.texture(map.texture));
  glBindSampler(unit, resources.sampler(map.sampler));
}

}  // namespace

void set_frame_uniforms(Program& p, const FrameState& frame) {
  if (p.frame == frame.number) return;
  p.frame = frame.number;
  const Lighting& lighting = *frame.lighting;
  const int count = static_cast<int>(lighting.lights.size());
  if (count > kMaxLights) {
    throw Error("OpenGL backend: " + std::to_string(count) + " lights; it draws at most " +
                std::to_string(kMaxLights));
  }
  glUniform1i(p.uniform("u_light_count"), count);
  for (int i = 0; i < count; ++i) set_light(p, i, lighting.lights[i]);
  set_vec3(p, "u_ambient", lighting.ambient);
  set_vec3(p, "u_eye", frame.eye);
  const Fog& fog = lighting.fog;
  glUniform1i(p.uniform("u_fog_mode"), fog.mode == FogMode::linear        ? 1
                                       : fog.mode == FogMode::exponential ? 2
                                                                          : 0);
  set_vec3(p, "u_fog_color", frame.fog_color);
  glUniform1f(p.uniform("u_fog_start"), fog.start);
  glUniform1f(p.uniform("u_fog_end"), fog.end);
  glUniform1f(p.uniform("u_fog_density"), fog.density);
  set_vec3(p, "u_view_depth", frame.view_depth);
  glUniform1f(p.uniform("u_depth_view_near"), frame.depth_view_near);
  glUniform1f(p.uniform("u_depth_view_far"), frame.depth_view_far);
  glUniform1i(p.uniform("u_display_exact"), frame.display_exact ? 1 : 0);
  const Environment& env = lighting.environment;
  glUniform1i(p.uniform("u_env_has_image"), env.image ? 1 : 0);
  glUniform1i(p.uniform("u_env_sphere_map"),
              env.projection == EnvironmentProjection::sphere_map ? 1 : 0);
  glUniform1f(p.uniform("u_env_intensity"), env.intensity);
  glUniform1i(p.uniform("u_env_reflections"), env.reflections ? 1 : 0);
  set_vec3(p, "u_sky_zenith", env.sky_zenith);
  set_vec3(p, "u_sky_horizon", env.sky_horizon);
  set_vec3(p, "u_sky_ground", env.ground);
  glUniform1i(p.uniform("u_env_map"), kEnvironmentUnit);
  glm::mat4 inverse = glm::inverse(frame.view_projection);
  glUniform2f(p.uniform("u_viewport"), float(frame.viewport.x), float(frame.viewport.y));
  glUniformMatrix4fv(p.uniform("u_inverse_view_projection"), 1, GL_FALSE, glm::value_ptr(inverse));
}

void set_draw_uniforms(Program& p, const GlDraw& draw, const Material& m, const FrameState& frame,
                       bool has_normals, GpuResources& resources) {
  const glm::mat4 mvp = frame.view_projection * draw.transform;
  const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(draw.transform));
  glUniformMatrix4fv(p.uniform("u_model"), 1, GL_FALSE, glm::value_ptr(draw.transform));
  glUniformMatrix4fv(p.uniform("u_model_view_projection"), 1, GL_FALSE, glm::value_ptr(mvp));
  glUniformMatrix3fv(p.uniform("u_normal_matrix"), 1, GL_FALSE, glm::value_ptr(normal_matrix));
  glUniform1f(p.uniform("u_model_handedness"),
              glm::determinant(glm::mat3(draw.transform)) < 0.0f ? -1.0f : 1.0f);
  glUniform1i(p.uniform("u_has_normals"), has_normals ? 1 : 0);
  glUniform4fv(p.uniform("u_base_color"), 1, glm::value_ptr(m.base_color));
  glUniform1i(p.uniform("u_use_vertex_colors"), m.use_vertex_colors ? 1 : 0);
  set_vec3(p, "u_specular_color", m.specular_color);
  glUniform1f(p.uniform("u_shininess"), m.shininess);
  glUniform1f(p.uniform("u_metallic"), m.metallic);
  glUniform1f(p.uniform("u_roughness"), m.roughness);
  set_vec3(p, "u_emissive", m.emissive);
  glUniform1f(p.uniform("u_reflectivity"), m.reflectivity);
  glUniform1f(p.uniform("u_normal_scale"), m.normal_scale);
  glUniform1f(p.uniform("u_occlusion_strength"), m.occlusion_strength);
  glUniform1f(p.uniform("u_alpha_cutoff"), m.alpha_cutoff);
  glUniform4fv(p.uniform("u_wire_color"), 1, glm::value_ptr(m.wire_color));
  glUniform1f(p.uniform("u_point_size"), m.point_size);
  glUniform1i(p.uniform("u_two_sided"), m.cull == CullMode::none ? 1 : 0);
  set_map(p, "u_base_color_map", 0, m.base_color_map, resources);
  set_map(p, "u_normal_map", 1, m.normal_map, resources);
  set_map(p, "u_specular_map", 2, m.specular_map, resources);
  set_map(p, "u_metallic_roughness_map", 3, m.metallic_roughness_map, resources);
  set_map(p, "u_occlusion_map", 4, m.occlusion_map, resources);
  set_map(p, "u_emissive_map", 5, m.emissive_map, resources);
}

}  // namespace facet::gl
