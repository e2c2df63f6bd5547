// Stage: draw recording (draw.cpp), before any vertex is transformed. A draw whose mesh lies
// wholly outside the view frustum is dropped there, so big worlds pay only for what is in view.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>

#include "facet/mesh.hpp"

namespace facet::pipeline {

// Object-space bounding box of a mesh's positions.
struct MeshBox {
  glm::vec3 low, high;
};

// The box, or nothing for an empty mesh or one with a non-finite position (the pipeline skips
// those triangles itself, so no box can stand for them).
std::optional<MeshBox> finite_bounds(const Mesh& mesh);

// True when all eight corners of the box are outside one and the same clip plane of
// model_view_projection: then every triangle inside it would be culled anyway.
bool box_outside_frustum(const MeshBox& box, const glm::mat4& model_view_projection);

}  // namespace facet::pipeline
