// Stage: vertex transform. Reads a recorded draw (mesh + uniforms) and writes one ClipVertex
// per mesh vertex (clip position + the shading model's varyings) for primitive assembly.
#pragma once

#include <vector>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Transforms every vertex of the draw into out (resized to the vertex count). Large meshes
// are transformed in parallel batches; the result does not depend on how they are split.
void transform_vertices(const DrawRecord& draw, int workers, std::vector<ClipVertex>& out);

}  // namespace facet::pipeline
