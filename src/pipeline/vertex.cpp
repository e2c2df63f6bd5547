// Stage: vertex transform (see vertex.hpp).
#include "pipeline/vertex.hpp"

#include <algorithm>

#include "pipeline/parallel.hpp"

namespace facet::pipeline {
namespace {

// Vertices per task: big enough to amortise scheduling, small enough to balance 2-8 cores.
constexpr std::size_t kVertexBatch = 4096;

void transform_range(const DrawRecord& draw, std::size_t begin, std::size_t end, ClipVertex* out) {
  const Mesh& mesh = *draw.mesh;
  const shading::DrawUniforms& u = draw.uniforms;
  bool has_normals = !mesh.normals.empty();
  bool has_colors = !mesh.colors.empty();
  bool has_texcoords = !mesh.texcoords.empty();
  bool has_tangents = !mesh.tangents.empty();
  glm::mat3 model3(u.model);
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
    out[i].clip = u.model_view_projection * glm::vec4(in.position, 1.0f);
    draw.pipeline.vertex(in, u, out[i].varyings);
  }
}

}  // namespace

void transform_vertices(const DrawRecord& draw, int workers, std::vector<ClipVertex>& out) {
  std::size_t count = draw.mesh->positions.size();
  out.resize(count);
  if (count <= kVertexBatch) {
    transform_range(draw, 0, count, out.data());
    return;
  }
  int batches = static_cast<int>((count + kVertexBatch - 1) / kVertexBatch);
  parallel_tasks(batches, workers, [&](int batch, int) {
    std::size_t begin = batch * kVertexBatch;
    transform_range(draw, begin, std::min(count, begin + kVertexBatch), out.data());
  });
}

}  // namespace facet::pipeline
