// The draws of a scene in the order facet's renderer runs them (pipeline/frame_run.cpp's
// order_draws): opaque and cut-out draws in submission order, then blended ones back to front.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <vector>

#include "facet/camera.hpp"
#include "facet/scene.hpp"

namespace facet::gl {

struct GlDraw {
  const std::shared_ptr<const Mesh>* mesh = nullptr;
  const Material* material = nullptr;
  glm::mat4 transform{1.0f};
  float view_depth = 0.0f;  // of the mesh's bounds centre: blended draws sort on it
};

// What draw_scene would record for this camera: every node's instances at its level of detail.
std::vector<GlDraw> ordered_draws(const Scene& scene, const Camera& camera);

// The view depths the depth debug view spans, from the draws' bounds (frame_run.cpp's
// set_depth_view_range), clamped to the camera's near and far planes; near to far when no draw
// uses the depth view.
void depth_view_range(const std::vector<GlDraw>& draws, const Camera& camera, float& nearest,
                      float& farthest);

}  // namespace facet::gl
