// A map's reach and the caster test (see shadow_reach.hpp).
#include "pipeline/shadow/shadow_reach.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "pipeline/shadow/shadow_fit.hpp"

namespace facet::pipeline {
namespace {

// Writes the corners of `view`'s frustum cut to `depths`: its own corners within them and where
// its edges cross their two planes (every corner of the cut solid, since the planes are
// parallel and so never meet on an edge). Returns how many, at most 32.
int cut_frustum(const Camera& view, const LookupDepths& depths, glm::vec3* points) {
  glm::vec3 corner[8];
  frustum_corners(view, corner);
  float depth[8];
  for (int i = 0; i < 8; ++i) depth[i] = glm::dot(corner[i] - depths.eye, depths.forward);
  int count = 0;
  for (int i = 0; i < 8; ++i) {
    if (depth[i] >= depths.nearest && depth[i] <= depths.farthest) points[count++] = corner[i];
  }
  // The twelve edges join corners that differ in one bit.
  for (int i = 0; i < 8; ++i) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (i & bit) continue;
      const int j = i | bit;
      for (const float plane : {depths.nearest, depths.farthest}) {
        const float a = depth[i] - plane, b = depth[j] - plane;
        if (!((a < 0.0f && b > 0.0f) || (a > 0.0f && b < 0.0f))) continue;
        points[count++] = corner[i] + (corner[j] - corner[i]) * (a / (a - b));
      }
    }
  }
  return count;
}

// b - a cross c - a: positive when a, b, c turn counter-clockwise.
float turn(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The convex outline of points[0, count) (reordered), counter-clockwise, into `outline` (room
// for count + 1); returns its corners (Andrew's monotone chain).
int convex_outline(glm::vec2* points, int count, glm::vec2* outline) {
  std::sort(points, points + count,
            [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (count < 3) {
    std::copy_n(points, count, outline);
    return count;
  }
  int k = 0;
  for (int i = 0; i < count; ++i) {  // the lower chain, left to right
    while (k >= 2 && turn(outline[k - 2], outline[k - 1], points[i]) <= 0.0f) --k;
    outline[k++] = points[i];
  }
  for (int i = count - 2, lower = k + 1; i >= 0; --i) {  // the upper chain, right to left
    while (k >= lower && turn(outline[k - 2], outline[k - 1], points[i]) <= 0.0f) --k;
    outline[k++] = points[i];
  }
  return k - 1;  // the last is the first again
}

// Whether the points[0, count) lie wholly outside `reach` along the normal of one of its edges,
// by more than the margin.
bool beyond_an_edge(const ShadowReach& reach, const glm::vec2* points, int count) {
  // Along an edge's outward normal the outline reaches no further than the edge itself.
  for (int i = 0; reach.corners >= 3 && i < reach.corners; ++i) {
    const glm::vec2 normal(reach.edge_lines[i]);
    float nearest = 1e30f;
    for (int k = 0; k < count; ++k) nearest = std::min(nearest, glm::dot(normal, points[k]));
    if (nearest > reach.edge_lines[i].z) return true;
  }
  return false;
}

// Whether `reach` and points[0, count) are apart along the normal of `edge` by more than the
// margin.
bool apart_across(const ShadowReach& reach, const glm::vec2* points, int count, glm::vec2 edge) {
  const glm::vec2 axis(-edge.y, edge.x);
  float outline_low = 1e30f, outline_high = -1e30f, low = 1e30f, high = -1e30f;
  for (int i = 0; i < reach.corners; ++i) {
    const float d = glm::dot(axis, reach.outline[i]);
    outline_low = std::min(outline_low, d), outline_high = std::max(outline_high, d);
  }
  for (int k = 0; k < count; ++k) {
    const float d = glm::dot(axis, points[k]);
    low = std::min(low, d), high = std::max(high, d);
  }
  const float margin = reach.margin * glm::length(axis);
  return low > outline_high + margin || high < outline_low - margin;
}

}  // namespace

ShadowReach shadow_reach(std::span<const Camera> views, const LookupDepths& depths,
                         const glm::mat4& world_to_texels, float magnitude) {
  ShadowReach reach;
  reach.world_to_texels = world_to_texels;
  glm::vec3 points[ShadowReach::kMaxCorners];
  int count = 0;
  for (const Camera& view :
       views.first(std::min<std::size_t>(views.size(), ShadowReach::kMaxViews))) {
    count += cut_frustum(view, depths, points + count);
  }
  glm::vec2 across[ShadowReach::kMaxCorners];
  for (int i = 0; i < count; ++i)
    across[i] = glm::vec2(world_to_texels * glm::vec4(points[i], 1.0f));
  glm::vec2 outline[ShadowReach::kMaxCorners + 1];
  reach.corners = convex_outline(across, count, outline);
  std::copy_n(outline, reach.corners, reach.outline);
  // The lookup reads the 4 x 4 texels from floor(p) - 1 around a point p: texel centres at
  // most 2 texels from it along each axis, so less than 3 away; 4 texels of margin hold them.
  // The lookup and this outline round the same positions differently, by a few ulp of the
  // largest coordinate; 1e-4 of that (in texels: times the texels per world unit) is far above.
  const float texels_per_unit =
      glm::length(glm::vec3(world_to_texels[0][0], world_to_texels[1][0], world_to_texels[2][0]));
  reach.margin = 4.0f + 1e-4f * magnitude * texels_per_unit;
  for (int i = 0; reach.corners >= 3 && i < reach.corners; ++i) {
    const glm::vec2 edge = reach.outline[(i + 1) % reach.corners] - reach.outline[i];
    const glm::vec2 normal = glm::normalize(glm::vec2(edge.y, -edge.x));
    reach.edge_lines[i] = {normal, glm::dot(normal, reach.outline[i]) + reach.margin};
  }
  return reach;
}

bool box_outside_reach(const ShadowReach& reach, glm::vec3 low, glm::vec3 high,
                       const glm::mat4& model) {
  if (reach.corners == 0) return true;
  const glm::mat4 to_texels = reach.world_to_texels * model;
  glm::vec2 box[8];
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 p((i & 1) ? high.x : low.x, (i & 2) ? high.y : low.y, (i & 4) ? high.z : low.z,
                      1.0f);
    box[i] = glm::vec2(to_texels * p);
  }
  // The box's outline runs along its three axes seen across the light.
  return beyond_an_edge(reach, box, 8) || apart_across(reach, box, 8, box[1] - box[0]) ||
         apart_across(reach, box, 8, box[2] - box[0]) ||
         apart_across(reach, box, 8, box[4] - box[0]);
}

bool texels_outside_reach(const ShadowReach& reach, int x0, int y0, int x1, int y1) {
  if (reach.corners == 0) return true;
  const glm::vec2 low(static_cast<float>(x0), static_cast<float>(y0));
  const glm::vec2 high(static_cast<float>(x1 - 1), static_cast<float>(y1 - 1));
  const glm::vec2 rect[4] = {low, {high.x, low.y}, {low.x, high.y}, high};
  return beyond_an_edge(reach, rect, 4) || apart_across(reach, rect, 4, {1.0f, 0.0f}) ||
         apart_across(reach, rect, 4, {0.0f, 1.0f});
}

}  // namespace facet::pipeline
