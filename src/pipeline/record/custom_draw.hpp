// Internal access to the renderer for tests and built-in tools: record a draw with an
// explicit DrawPipeline (e.g. a test's own shading model) instead of the material's.
#pragma once

#include <memory>

#include "facet/renderer.hpp"
#include "pipeline/frame.hpp"

namespace facet::pipeline {

void draw_with_pipeline(Renderer& renderer, const Mesh& mesh, const Material& material,
                        const glm::mat4& transform, const DrawPipeline& pipeline);
// The same for a mesh that does not change (as Renderer::draw's shared-pointer form).
void draw_with_pipeline(Renderer& renderer, const std::shared_ptr<const Mesh>& mesh,
                        const Material& material, const glm::mat4& transform,
                        const DrawPipeline& pipeline);

// The renderer's Frame::max_triangle_region_bytes (tests: the big-frame setup on small frames).
void set_max_triangle_region_bytes(Renderer& renderer, std::size_t bytes);
// The renderer's Frame::max_clip_vertex_bytes (tests: corners computed in primitive assembly on
// small meshes).
void set_max_clip_vertex_bytes(Renderer& renderer, std::size_t bytes);

}  // namespace facet::pipeline
