// Which casters a directional light's map needs: the part of the map the frame's shadow lookups
// can read (its reach), and whether a caster's box can cover any texel of it. Built by the
// shadow passes (shadow_passes.cpp) once per map; a caster outside the reach changes no texel
// the lookups read, so its pass skips it and the images stay the same.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>

#include "facet/camera.hpp"

namespace facet::pipeline {

// The points whose lookups read a map: those with view depth (p - eye) . forward within
// [nearest, farthest] (the depths the lookup picks the map for: ShadowVisibility) that some
// view of the frame sees (the color camera's, and each mirror pass's).
struct LookupDepths {
  glm::vec3 eye, forward;
  float nearest, farthest;
};

// The reach of a map: the convex outline, in the map's texels, of what `views` see at `depths`
// seen along the light, and a margin around it.
struct ShadowReach {
  // One view's frustum cut to the depths has at most 8 corners and 24 edge crossings.
  static constexpr int kMaxViews = 5;
  static constexpr int kMaxCorners = kMaxViews * 32;
  glm::mat4 world_to_texels{1.0f};  // x and y: the map's continuous texel coordinates
  glm::vec2 outline[kMaxCorners];   // counter-clockwise
  int corners = 0;                  // 0: no view sees those depths, so nothing reads the map
  float margin = 0.0f;              // the filter's reach and the rounding's, in texels
  // Edge i (outline[i] to the next) as a line n . p = d, n its outward unit normal, with the
  // margin added to d: (n.x, n.y, d). Set where the outline has three corners or more.
  glm::vec3 edge_lines[kMaxCorners];
};

// The reach of a directional light's map, whose texel coordinates are world_to_texels' x and y
// (an orthographic view along the light), for the points `views` (at most kMaxViews) see at
// `depths`. `magnitude`: the largest world coordinate in play (the scene's), whose rounding the
// margin covers too.
ShadowReach shadow_reach(std::span<const Camera> views, const LookupDepths& depths,
                         const glm::mat4& world_to_texels, float magnitude);

// True when the box [low, high], placed by `model`, lies wholly outside `reach`: separated from
// it, across the light, along the normal of one of the two convex outlines' edges (the
// separating axis theorem), by more than the margin.
bool box_outside_reach(const ShadowReach& reach, glm::vec3 low, glm::vec3 high,
                       const glm::mat4& model);

// True when no texel centre of [x0, x1) x [y0, y1) lies within `reach`: a pass may leave those
// texels as they were.
bool texels_outside_reach(const ShadowReach& reach, int x0, int y0, int x1, int y1);

}  // namespace facet::pipeline
