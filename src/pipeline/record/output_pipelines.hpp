// The pipelines of the extra outputs' passes (facet/framebuffer.hpp's ExtraOutputs): which
// shading model of shading/output_models.hpp draws a draw in each pass.
#pragma once

#include "facet/framebuffer.hpp"
#include "facet/material.hpp"
#include "pipeline/frame.hpp"

namespace facet::pipeline {

// One pass over the frame's draws into a float target, four floats a pixel.
enum class OutputPass {
  depth_and_instance,  // view depth, ray distance, instance id
  normals,
  triangles,  // triangle id, barycentrics
  albedo,
};

// The pipeline of `pass` for a draw whose material cuts out at its alpha (AlphaMode::mask) or
// not (every other mode: the passes draw blended draws opaque).
DrawPipeline output_pipeline(OutputPass pass, NormalSpace normals, AlphaMode alpha);

}  // namespace facet::pipeline
