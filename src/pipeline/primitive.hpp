// Stage: primitive assembly. Reads a draw's transformed vertices (vertex.cpp), walks its
// topology, rejects and culls whole triangles, clips what needs it (clip.cpp) and passes the
// pieces to setup (setup.cpp). Edges for wireframe views are emitted here too.
#pragma once

#include <cstdint>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Front-facing (counter-clockwise in NDC) test done in homogeneous coordinates, so that it
// is right before clipping even for vertices behind the eye (Olano & Greer, "Triangle scan
// conversion using 2D homogeneous coordinates", 1997): the sign of det[x y w] rows.
double homogeneous_orientation(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c);

// Assembles, culls, clips and sets up primitives [begin, end) (triangles, or segments for
// line meshes) of frame.draws[draw] into out, counting what it culls and clips into counts.
// Reads only the frame, so chunks of one draw can run in parallel, each into its own buffer.
void assemble_primitives(const Frame& frame, std::uint32_t draw, std::size_t begin, std::size_t end,
                         PrimitiveBuffer& out, PrimitiveCounts& counts);

}  // namespace facet::pipeline
