// Stage: draw recording (draw.cpp), before any vertex is transformed. A draw whose mesh lies
// wholly outside the view frustum is dropped there, so big worlds pay only for what is in view.
#pragma once

#include <glm/mat4x4.hpp>

#include "facet/mesh.hpp"

namespace facet::pipeline {

// True when all eight corners of the mesh's bounding box are outside one and the same clip
// plane of model_view_projection (then every triangle would be culled anyway). False when in
// doubt: an empty mesh, or a non-finite position (the pipeline skips those triangles itself).
bool draw_outside_frustum(const Mesh& mesh, const glm::mat4& model_view_projection);

}  // namespace facet::pipeline
