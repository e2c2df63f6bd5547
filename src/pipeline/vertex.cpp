// Stage: vertex transform (see vertex.hpp).
#include "pipeline/vertex.hpp"

#include <algorithm>
#include <cmath>

#include "pipeline/clip.hpp"
#include "pipeline/parallel.hpp"
#include "pipeline/setup.hpp"

namespace facet::pipeline {
namespace {

struct Projection {
  int width, height;
  ClipBounds frustum{1.0f, 1.0f};
  ClipBounds guard;
};

bool finite(const glm::vec4& c) {
  return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w);
}

// What setup would otherwise compute at each of the vertex's triangle corners.
void project(const ClipVertex& in, const Projection& to, int varyings, ProjectedVertex& out,
             float* over_w) {
  const glm::vec4& c = in.clip;
  out.clip_x = c.x, out.clip_y = c.y, out.clip_w = c.w;
  out.codes = outcode(c, to.frustum) | outcode(c, to.guard) << kGuardCodeShift |
              (finite(c) ? 0u : kNotFinite);
  out.screen = to_screen(c, to.width, to.height);
  if (over_w) {
    for (int k = 0; k < varyings; ++k) over_w[k] = in.varyings[k] * out.screen.inv_w;
  }
}

void transform_range(const DrawRecord& draw, const Projection& to, std::size_t begin,
                     std::size_t end, DrawVertices& out) {
  const Mesh& mesh = *draw.mesh;
  const shading::DrawUniforms& u = draw.uniforms;
  bool has_normals = !mesh.normals.empty();
  bool has_colors = !mesh.colors.empty();
  bool has_texcoords = !mesh.texcoords.empty();
  bool has_tangents = !mesh.tangents.empty();
  glm::mat3 model3(u.model);
  const int varyings = draw.pipeline.varyings;
  float* over_w = out.over_w.empty() ? nullptr : out.over_w.data();
  for (std::size_t i = begin; i < end; ++i) {
    shading::VertexInput in;
    in.position = mesh.positions[i];
    in.normal = has_normals ? u.normal_matrix * mesh.normals[i] : glm::vec3(0.0f);
    float length = glm::length(in.normal);
    if (length > 0.0f) in.normal /= length;
    in.color = has_colors ? mesh.colors[i] : glm::vec4(1.0f);
    in.texcoord = has_texcoords ? mesh.texcoords[i] : glm::vec2(0.0f);
    in.tangent = has_tangents ? glm::vec4(model3 * glm::vec3(mesh.tangents[i]), mesh.tangents[i].w)
                              : glm::vec4(0.0f);
    ClipVertex& v = out.clip[i];
    v.clip = u.model_view_projection * glm::vec4(in.position, 1.0f);
    draw.pipeline.vertex(in, u, v.varyings);
    project(v, to, varyings, out.projected[i], over_w ? over_w + i * varyings : nullptr);
  }
}

}  // namespace

void transform_vertices(const DrawRecord& draw, int width, int height, int workers,
                        DrawVertices& out) {
  std::size_t count = draw.mesh->positions.size();
  out.clip.resize(count);
  out.projected.resize(count);
  // Only setup's fast path reads over_w, and it never runs for draws with hooks.
  out.over_w.resize(has_triangle_hooks(draw) ? 0 : count * draw.pipeline.varyings);
  const Projection to{width, height, {1.0f, 1.0f}, guard_band_bounds(width, height)};
  if (count <= kVertexBatch) {
    transform_range(draw, to, 0, count, out);
    return;
  }
  int batches = static_cast<int>((count + kVertexBatch - 1) / kVertexBatch);
  parallel_tasks(batches, workers, [&](int batch, int) {
    std::size_t begin = batch * kVertexBatch;
    transform_range(draw, to, begin, std::min(count, begin + kVertexBatch), out);
  });
}

}  // namespace facet::pipeline
