// Internal access to the renderer for tests and built-in tools: record a draw with an
// explicit DrawPipeline (e.g. a test's own shading model) instead of the material's.
#pragma once

#include "facet/renderer.hpp"
#include "pipeline/frame.hpp"

namespace facet::pipeline {

void draw_with_pipeline(Renderer& renderer, const Mesh& mesh, const Material& material,
                        const glm::mat4& transform, const DrawPipeline& pipeline);

}  // namespace facet::pipeline
