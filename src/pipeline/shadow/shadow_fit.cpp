// The shadow map's view (see shadow_fit.hpp).
#include "pipeline/shadow/shadow_fit.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace facet::pipeline {
namespace {

// An interval on one axis; empty when low > high.
struct Span {
  float low = 1e30f, high = -1e30f;
  void add(float v) { low = std::min(low, v), high = std::max(high, v); }
};

// A unit vector across `forward` (unit): the up of a light's view.
glm::vec3 up_across(glm::vec3 forward) {
  const glm::vec3 hint = std::abs(forward.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
  return glm::normalize(glm::cross(glm::cross(forward, hint), forward));
}

}  // namespace

void frustum_corners(const Camera& view, glm::vec3 corners[8]) {
  const glm::mat4 inverse = glm::inverse(view.view_projection());
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 p = inverse * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f,
                                            (i & 4) ? 1.0f : -1.0f, 1.0f);
    corners[i] = glm::vec3(p) / p.w;
  }
}

std::optional<Camera> fit_directional_shadow(const Camera& view, glm::vec3 travel,
                                             const WorldBox& scene, int map_size) {
  if (scene.empty() || !(glm::length(travel) > 0.0f)) return std::nullopt;
  const glm::vec3 forward = glm::normalize(travel);
  const glm::vec3 up = up_across(forward);
  const glm::vec3 right = glm::cross(forward, up);

  // The scene across and along the light, and the view depths it spans.
  Span scene_x, scene_y, scene_z, depths;
  const glm::mat4 camera_view = view.view();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p = scene.corner(corner);
    scene_x.add(glm::dot(p, right)), scene_y.add(glm::dot(p, up));
    scene_z.add(glm::dot(p, forward));
    depths.add(-(camera_view * glm::vec4(p, 1.0f)).z);
  }
  const float nearest = std::max(depths.low, view.near_plane);
  const float farthest = std::min(depths.high, view.far_plane);
  if (!(nearest <= farthest)) return std::nullopt;

  // The frustum between those depths: along each corner ray from the near plane to the far,
  // view depth grows linearly, for either projection.
  glm::vec3 frustum[8];
  frustum_corners(view, frustum);
  const float span = view.far_plane - view.near_plane;
  Span seen_x, seen_y;
  for (int corner = 0; corner < 4; ++corner) {
    const glm::vec3 on_near = frustum[corner], on_far = frustum[corner + 4];
    for (const float depth : {nearest, farthest}) {
      const float t = span > 0.0f ? (depth - view.near_plane) / span : 0.0f;
      const glm::vec3 p = on_near + (on_far - on_near) * t;
      seen_x.add(glm::dot(p, right)), seen_y.add(glm::dot(p, up));
    }
  }
  const Span x{std::max(seen_x.low, scene_x.low), std::min(seen_x.high, scene_x.high)};
  const Span y{std::max(seen_y.low, scene_y.low), std::min(seen_y.high, scene_y.high)};
  if (!(x.low <= x.high && y.low <= y.high)) return std::nullopt;

  // Square, two texels of margin each side, the centre on the texel grid.
  const float size = static_cast<float>(map_size);
  const float side =
      std::max({x.high - x.low, y.high - y.low, 1e-6f * (scene_z.high - scene_z.low), 1e-20f}) *
      size / (size - 4.0f);
  const float texel = side / size;
  const float centre_x = std::round((x.low + x.high) * 0.5f / texel) * texel;
  const float centre_y = std::round((y.low + y.high) * 0.5f / texel) * texel;
  // The near plane a little before the first caster, the far a little past the last receiver.
  const float margin = std::max(texel, 1e-3f * (scene_z.high - scene_z.low));
  const glm::vec3 eye = right * centre_x + up * centre_y + forward * (scene_z.low - margin);
  const float depth_range = scene_z.high - scene_z.low + 2.0f * margin;
  Camera light = Camera::orthographic(eye, eye + forward, up, side, 1.0f, 0.0f, depth_range);
  if (!std::isfinite(side) || !std::isfinite(depth_range) ||
      !std::isfinite(eye.x + eye.y + eye.z)) {
    return std::nullopt;
  }
  return light;
}

std::optional<Camera> fit_spot_shadow(glm::vec3 position, glm::vec3 travel, float outer_degrees,
                                      const WorldBox& scene, int map_size) {
  if (scene.empty() || !(glm::length(travel) > 0.0f)) return std::nullopt;
  const glm::vec3 forward = glm::normalize(travel);
  // Far: past the farthest corner of the scene. Near: just before the scene box (at most a
  // thousandth of far, which keeps the depths' precision at the far end within a texel).
  float farthest = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    farthest = std::max(farthest, glm::length(scene.corner(corner) - position));
  }
  const glm::vec3 outside = glm::max(glm::max(scene.low - position, position - scene.high), 0.0f);
  const float far_plane = farthest * 1.01f;
  const float near_plane = std::max(glm::length(outside) * 0.9f, far_plane * 1e-3f);
  if (!(far_plane > near_plane) || !std::isfinite(far_plane)) return std::nullopt;
  const float half = std::clamp(outer_degrees, 0.0f, 90.0f);
  const float half_radians = glm::radians(std::min(half, 80.0f));
  // Two texels more each side: the lookup's filter reaches two texels past the cone.
  const float margin = 4.0f / static_cast<float>(map_size);
  const float fov = glm::degrees(2.0f * std::atan(std::tan(half_radians) * (1.0f + margin)));
  return Camera::look_at(position, position + forward, up_across(forward), fov, 1.0f, near_plane,
                         far_plane);
}

}  // namespace facet::pipeline
