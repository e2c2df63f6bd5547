// The reference rasterizer: short, scalar and obviously correct, used only by tests to check
// the tiled fast path. Same rules (pixel centres, 8-bit sub-pixel snapping, top-left fill
// rule, clipping, depth test "less"), none of the machinery: no tiles, no bins, no incremental
// stepping, no SIMD. It shades one model, Lambert with a base color map, written out plainly.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "facet/camera.hpp"
#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/setup/fixed_point.hpp"

namespace facet::pipeline {

// Bit set of the planes a clip-space position is outside of (a NaN coordinate fails every
// comparison, so it counts as outside): what the vertex pass computes for every vertex
// (geometry/vertex_pass.hpp), the same tests as clip.cpp's distance() >= 0, written out.
inline unsigned outcode(const glm::vec4& c, const ClipBounds& b) {
  unsigned code = 0;
  if (!(c.z + c.w >= 0.0f)) code |= kClipNear;
  if (!(c.w - c.z >= 0.0f)) code |= kClipFar;
  if (!(c.x + b.gx * c.w >= 0.0f)) code |= kClipLeft;
  if (!(b.gx * c.w - c.x >= 0.0f)) code |= kClipRight;
  if (!(c.y + b.gy * c.w >= 0.0f)) code |= kClipBottom;
  if (!(b.gy * c.w - c.y >= 0.0f)) code |= kClipTop;
  if (b.clips_user_plane && !(user_plane_distance(b.user_plane, c) >= 0.0f)) code |= kClipUser;
  return code;
}

// The perspective divide and viewport transform of a clip position to a screen vertex, snapped
// to fixed point (setup/fixed_point.hpp's snap): what the vertex stage's kernels compute
// (geometry/vertex_pass.hpp), written out.
inline ScreenVertex to_screen(const glm::vec4& clip, int width, int height) {
  float inv_w = 1.0f / clip.w;
  float ndc_x = clip.x * inv_w;
  float ndc_y = clip.y * inv_w;
  float ndc_z = clip.z * inv_w;
  float sx = (ndc_x * 0.5f + 0.5f) * static_cast<float>(width);
  float sy = (0.5f - ndc_y * 0.5f) * static_cast<float>(height);
  return {snap(sx), snap(sy), ndc_z * 0.5f + 0.5f, inv_w};
}

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<int> coverage;     // how many triangles covered each pixel centre
  std::vector<float> depth;      // nearest window depth (1 = far, the clear value)
  std::vector<glm::vec4> color;  // linear RGBA of the nearest fragment; empty if not shaded
};

// Rasterizes a triangle soup (every 3 positions, object space) transformed by
// model_view_projection: coverage and depth only.
ReferenceImage reference_rasterize(const std::vector<glm::vec3>& positions,
                                   const glm::mat4& model_view_projection, CullMode cull, int width,
                                   int height);

// One Lambert-shaded draw seen by a camera: what reference_render reads.
struct ReferenceScene {
  Mesh mesh;  // triangles, with a normal per vertex; texture coordinates optional ((0, 0))
  glm::mat4 model{1.0f};
  Camera camera;
  // Reads base_color, base_color_map (nearest or bilinear: no mip selection) and cull;
  // shading must be lambert, opaque, without emission.
  Material material;
  Lighting lighting;  // directional lights and the ambient term; no fog
  glm::vec4 clear_color{0.0f, 0.0f, 0.0f, 1.0f};
};

// Renders the scene: coverage, nearest depth and the nearest fragment's color (the clear color
// where none). Throws std::invalid_argument for what it does not draw (see ReferenceScene).
ReferenceImage reference_render(const ReferenceScene& scene, int width, int height);

}  // namespace facet::pipeline
