// Stage: draw recording (renderer.cpp), before any vertex is transformed. A draw whose mesh lies
// wholly outside the view frustum is dropped there, so big worlds pay only for what is in view.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>

#include "facet/mesh.hpp"
#include "pipeline/geometry/clip.hpp"

namespace facet::pipeline {

// The mesh's bounding box (frame.hpp's MeshBox), or nothing for an empty mesh or one with a
// non-finite position (the pipeline skips those triangles itself, so no box can stand for them).
std::optional<MeshBox> finite_bounds(const Mesh& mesh);

// True when all eight corners of the box are outside one and the same clip plane of
// model_view_projection: then every triangle inside it would be culled anyway.
bool box_outside_frustum(const MeshBox& box, const glm::mat4& model_view_projection);

// True when every point of the box transforms to inside the guard band and between the near
// and far planes, with a margin over the vertex stage's rounding: then none of the draw's
// triangles needs clipping, and the vertex stage need not keep what only the clipper reads.
bool box_inside_clip_bounds(const MeshBox& box, const glm::mat4& model_view_projection,
                            const ClipBounds& guard);

}  // namespace facet::pipeline
