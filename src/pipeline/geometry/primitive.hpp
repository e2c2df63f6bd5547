// Stage: primitive assembly. Reads a draw's transformed vertices (vertex.cpp), walks its
// topology, rejects and culls whole triangles, clips what needs it (clip.cpp) and passes the
// pieces to setup (setup.cpp). Edges for wireframe views are emitted here too, and the segments
// and points of line and point meshes.
#pragma once

#include <cstdint>

#include "pipeline/frame.hpp"
#include "pipeline/geometry/primitive_sink.hpp"

namespace facet::pipeline {

// Front-facing (counter-clockwise in NDC) test done in homogeneous coordinates, so that it
// is right before clipping even for vertices behind the eye (Olano & Greer, "Triangle scan
// conversion using 2D homogeneous coordinates", 1997): the sign of det[x y w] rows.
inline double homogeneous_orientation(double ax, double ay, double aw, double bx, double by,
                                      double bw, double cx, double cy, double cw) {
  // det | ax ay aw ; bx by bw ; cx cy cw |, equal to aw*bw*cw times twice the NDC area.
  return ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
}
inline double homogeneous_orientation(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
  return homogeneous_orientation(a.x, a.y, a.w, b.x, b.y, b.w, c.x, c.y, c.w);
}
inline double homogeneous_orientation(const ProjectedVertex& a, const ProjectedVertex& b,
                                      const ProjectedVertex& c) {
  return homogeneous_orientation(a.clip_x, a.clip_y, a.clip_w, b.clip_x, b.clip_y, b.clip_w,
                                 c.clip_x, c.clip_y, c.clip_w);
}

// Assembles, culls, clips and sets up primitives [begin, end) (triangles, or segments for
// line meshes, points for point meshes) of frame.draws[draw], whose transformed vertices are
// `vertices`, into out, counting what it culls and clips into counts. Reads only the frame and the
// vertices, so chunks of one draw can run in parallel, each into its own regions.
void assemble_primitives(const Frame& frame, std::uint32_t draw, const DrawVertices& vertices,
                         std::size_t begin, std::size_t end, PrimitiveSink& out,
                         PrimitiveCounts& counts);

}  // namespace facet::pipeline
