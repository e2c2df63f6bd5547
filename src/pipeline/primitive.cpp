// Stage: primitive assembly (see primitive.hpp).
#include "pipeline/primitive.hpp"

#include <cmath>

#include "pipeline/clip.hpp"
#include "pipeline/setup.hpp"

namespace facet::pipeline {
namespace {

bool finite(const glm::vec4& c) {
  return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w);
}

struct Assembler {
  PrimitiveBuffer& out;
  PrimitiveCounts& counts;
  int width, height;
  std::uint32_t draw_index;
  const DrawRecord& draw;
  const std::vector<ClipVertex>& vertices;
  ClipBounds frustum{1.0f, 1.0f};
  ClipBounds guard;

  bool cull(bool front_facing) const {
    switch (draw.material.cull) {
      case CullMode::back:
        return !front_facing;
      case CullMode::front:
        return front_facing;
      default:
        return false;
    }
  }

  // Face normal in world space from object-space positions.
  glm::vec3 face_normal(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) const {
    const auto& p = draw.mesh->positions;
    glm::vec3 n = glm::cross(p[i1] - p[i0], p[i2] - p[i0]);
    n = draw.uniforms.normal_matrix * n;
    float length = glm::length(n);
    return length > 0.0f ? n / length : glm::vec3(0.0f);
  }

  // Centre of the triangle in world space.
  glm::vec3 centre(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) const {
    const auto& p = draw.mesh->positions;
    return glm::vec3(draw.uniforms.model * glm::vec4((p[i0] + p[i1] + p[i2]) / 3.0f, 1.0f));
  }

  void edge(const glm::vec4& a, const glm::vec4& b, const glm::vec4& color) {
    glm::vec4 p = a, q = b;
    unsigned planes = outcode(p, guard) | outcode(q, guard);
    if (planes && !clip_segment(p, q, planes, guard)) return;
    setup_line(out, width, height, p, q, color);
  }

  void triangle(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) {
    // Culling reads the shared vertices in place: most rejected triangles (facing away, off
    // screen) never pay for copying their varyings.
    const ClipVertex* in[3] = {&vertices[i0], &vertices[i1], &vertices[i2]};
    if (!finite(in[0]->clip) || !finite(in[1]->clip) || !finite(in[2]->clip)) {
      ++counts.culled;  // NaN/Inf positions: skipped, never rasterized
      return;
    }
    unsigned out0 = outcode(in[0]->clip, frustum), out1 = outcode(in[1]->clip, frustum),
             out2 = outcode(in[2]->clip, frustum);
    double orientation = homogeneous_orientation(in[0]->clip, in[1]->clip, in[2]->clip);
    bool front_facing = orientation > 0.0;
    // Trivial reject: all three outside one frustum plane. Zero orientation: degenerate.
    if ((out0 & out1 & out2) || orientation == 0.0 || cull(front_facing)) {
      ++counts.culled;
      return;
    }
    const DrawPipeline& pipe = draw.pipeline;
    if (pipe.draws_edges) {
      for (int i = 0; i < 3; ++i)
        edge(in[i]->clip, in[(i + 1) % 3]->clip, draw.uniforms.wire_color);
    }
    if (!pipe.fills_triangles) return;

    // Near and far are the same planes in both bounds; the guard band's sides only need
    // checking when a vertex is outside the frustum's sides (the guard band contains them).
    unsigned any_out = out0 | out1 | out2;
    unsigned planes = any_out & (kClipNear | kClipFar);
    if (any_out & (kClipLeft | kClipRight | kClipBottom | kClipTop)) {
      planes =
          outcode(in[0]->clip, guard) | outcode(in[1]->clip, guard) | outcode(in[2]->clip, guard);
    }
    bool no_normals = draw.mesh->normals.empty();
    bool fill_normal = pipe.normal_slot >= 0 && no_normals;
    DrawPipeline::FaceFn face =
        pipe.face ? pipe.face : (no_normals ? pipe.face_without_normals : nullptr);
    if (planes == 0 && !fill_normal && !face) {  // the common case: nothing to rewrite
      if (!setup_triangle(out, width, height, draw_index, in, pipe.varyings, front_facing))
        ++counts.culled;
      return;
    }

    // The per-triangle hooks and the clipper rewrite vertices: work on copies.
    ClipPolygon polygon;
    polygon.count = 3;
    ClipVertex* v = polygon.vertices;
    for (int i = 0; i < 3; ++i) v[i] = *in[i];
    if (fill_normal || face) {
      glm::vec3 n = face_normal(i0, i1, i2);
      if (fill_normal) {
        for (int i = 0; i < 3; ++i) {
          for (int k = 0; k < 3; ++k) v[i].varyings[pipe.normal_slot + k] = n[k];
        }
      }
      if (face) {
        float* varyings[3] = {v[0].varyings, v[1].varyings, v[2].varyings};
        face(n, centre(i0, i1, i2), draw.uniforms, varyings);
      }
    }
    if (planes == 0) {
      const ClipVertex* tri[3] = {&v[0], &v[1], &v[2]};
      if (!setup_triangle(out, width, height, draw_index, tri, pipe.varyings, front_facing))
        ++counts.culled;
      return;
    }
    ++counts.clipped;
    clip_polygon(polygon, planes, guard, pipe.varyings);
    // Fan re-triangulation of the convex clipped polygon.
    for (int i = 1; i + 1 < polygon.count; ++i) {
      const ClipVertex* tri[3] = {&v[0], &v[i], &v[i + 1]};
      setup_triangle(out, width, height, draw_index, tri, pipe.varyings, front_facing);
    }
  }

  void line(std::uint32_t i0, std::uint32_t i1) {
    const glm::vec4& a = vertices[i0].clip;
    const glm::vec4& b = vertices[i1].clip;
    if (!finite(a) || !finite(b) || (outcode(a, frustum) & outcode(b, frustum))) {
      ++counts.culled;
      return;
    }
    edge(a, b, draw.uniforms.base_color);
  }
};

}  // namespace

double homogeneous_orientation(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
  // det | ax ay aw ; bx by bw ; cx cy cw |, equal to aw*bw*cw times twice the NDC area.
  double ax = a.x, ay = a.y, aw = a.w, bx = b.x, by = b.y, bw = b.w, cx = c.x, cy = c.y, cw = c.w;
  return ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
}

void assemble_primitives(const Frame& frame, std::uint32_t draw_index, std::size_t begin,
                         std::size_t end, PrimitiveBuffer& out, PrimitiveCounts& counts) {
  const DrawRecord& draw = frame.draws[draw_index];
  const Mesh& mesh = *draw.mesh;
  Assembler assembler{out,
                      counts,
                      frame.width,
                      frame.height,
                      draw_index,
                      draw,
                      frame.vertices[draw_index],
                      {1.0f, 1.0f},
                      guard_band_bounds(frame.width, frame.height)};
  auto index = [&](std::size_t i) {
    return mesh.indices.empty() ? static_cast<std::uint32_t>(i) : mesh.indices[i];
  };
  for (std::size_t p = begin; p < end; ++p) {
    switch (mesh.topology) {
      case Topology::triangles:
        assembler.triangle(index(3 * p), index(3 * p + 1), index(3 * p + 2));
        break;
      case Topology::triangle_strip:
        // Odd triangles swap their first two vertices so every triangle keeps the strip's
        // winding.
        if (p % 2 == 0) {
          assembler.triangle(index(p), index(p + 1), index(p + 2));
        } else {
          assembler.triangle(index(p + 1), index(p), index(p + 2));
        }
        break;
      case Topology::lines:
        assembler.line(index(2 * p), index(2 * p + 1));
        break;
    }
  }
}

}  // namespace facet::pipeline
