// Where a light's shadow map looks from: for a directional light an orthographic view along the
// light that takes in what the camera sees of the scene and every caster between that and the
// light; for a spot light a perspective view from the light over its cone. Read by the shadow
// passes (shadow_passes.cpp) once per light per frame.
#pragma once

#include <glm/vec3.hpp>
#include <optional>

#include "facet/camera.hpp"

namespace facet::pipeline {

// An axis-aligned world-space box; empty when low > high.
struct WorldBox {
  glm::vec3 low{1e30f};
  glm::vec3 high{-1e30f};
  bool empty() const { return !(low.x <= high.x && low.y <= high.y && low.z <= high.z); }
  void add(glm::vec3 p) { low = glm::min(low, p), high = glm::max(high, p); }
  // Corner i: bit 0 picks high.x over low.x, bit 1 high.y, bit 2 high.z.
  glm::vec3 corner(int i) const {
    return {(i & 1) ? high.x : low.x, (i & 2) ? high.y : low.y, (i & 4) ? high.z : low.z};
  }
};

// The corners of `view`'s frustum: corner i on the right (bit 0) or left edge, the top (bit 1)
// or bottom, on the far (bit 2) or near plane, numbered as WorldBox::corner numbers a box's.
void frustum_corners(const Camera& view, glm::vec3 corners[8]);

// The orthographic camera of a map of map_size texels a side for a light travelling along
// `travel`, or none when the camera sees nothing of `scene` (the box around every draw).
// Across the light: the camera's frustum, cut to the view depths the scene spans, intersected
// with the scene box, squared, with two texels of margin for the lookup's filter, and its centre
// on whole texels (so the map does not shimmer as the camera turns). Along the light: the whole
// scene box, so casters outside the camera's view still cast.
std::optional<Camera> fit_directional_shadow(const Camera& view, glm::vec3 travel,
                                             const WorldBox& scene, int map_size);

// The perspective camera of a spot light's map: from `position` along `travel`, its field of
// view the cone's (outer_degrees each side) plus two texels of margin, at most 160 degrees (a
// wider cone is shadowed within the central 160), its near and far planes around `scene`; none
// when the scene is empty or the light's direction is zero.
std::optional<Camera> fit_spot_shadow(glm::vec3 position, glm::vec3 travel, float outer_degrees,
                                      const WorldBox& scene, int map_size);

}  // namespace facet::pipeline
