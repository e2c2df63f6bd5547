// Stage: vertex transform (see vertex.hpp).
#include "pipeline/geometry/vertex.hpp"

#include <algorithm>

#include "core/parallel.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/record/draw_culling.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {
namespace {

void transform_range(const DrawRecord& draw, const Kernels& kernels,
                     const VertexPassInput& pass_input, std::size_t begin, std::size_t end,
                     DrawVertices& out) {
  const Mesh& mesh = *draw.mesh;
  const shading::DrawUniforms& u = draw.uniforms;
  bool has_colors = !mesh.colors.empty();
  bool has_texcoords = !mesh.texcoords.empty();
  bool has_tangents = !mesh.tangents.empty();
  glm::mat3 model3(u.model);
  const int varyings = draw.pipeline.varyings;
  float* over_w = out.over_w.empty() ? nullptr : out.over_w.data();
  // In a local: the stores below may alias the draw.
  const bool batch = draw.pipeline.vertex_batch != nullptr;
  VertexPass pass;
  static_assert(shading::kVertexBatch == kVertexPass);
  alignas(64) float batch_varyings[kMaxVaryings][shading::kVertexBatch];
  const bool write_clip = out.clip_written;
  for (std::size_t first = begin; first < end; first += kVertexPass) {
    const std::size_t count = std::min(kVertexPass, end - first);
    // First, several vertices at a time, all that needs no shading model.
    kernels.vertex_pass(pass_input, first, count, pass);
    // Then the shading model: all of them at once if it has a batch form.
    if (batch) {
      draw.pipeline.vertex_batch(u,
                                 {static_cast<int>(count),
                                  &mesh.positions[first],
                                  {pass.nx, pass.ny, pass.nz},
                                  has_texcoords ? &mesh.texcoords[first] : nullptr,
                                  has_colors ? &mesh.colors[first] : nullptr},
                                 batch_varyings);
    }
    kernels.store_projected(pass, count, &out.projected[first]);
    // What setup's planes pass through (perspective-correct interpolation of v / w; to_screen's
    // 1 / w is the pass's: the same division).
    if (batch && over_w) {
      kernels.store_over_w(batch_varyings, pass.inv_w, count, varyings, over_w + first * varyings);
    }
    if (!write_clip) continue;  // a batch-form draw whose triangles only the setup kernel reads
    for (std::size_t j = 0; j < count; ++j) {
      const std::size_t i = first + j;
      ClipVertex& v = out.clip[i];
      v.clip = glm::vec4(pass.x[j], pass.y[j], pass.z[j], pass.w[j]);
      if (batch) {
        for (int k = 0; k < varyings; ++k) v.varyings[k] = batch_varyings[k][j];
        continue;
      }

      shading::VertexInput in;
      in.position = mesh.positions[i];
      in.normal = {pass.nx[j], pass.ny[j], pass.nz[j]};
      in.color = has_colors ? mesh.colors[i] : glm::vec4(1.0f);
      in.texcoord = has_texcoords ? mesh.texcoords[i] : glm::vec2(0.0f);
      in.tangent = has_tangents
                       ? glm::vec4(model3 * glm::vec3(mesh.tangents[i]), mesh.tangents[i].w)
                       : glm::vec4(0.0f);
      draw.pipeline.vertex(in, u, v.varyings);
    }
    // The same for the varyings vertex() wrote, a vertex at a time. A loop of its own: read
    // right after the shading model's narrow stores, the varyings' vector loads would stall on
    // store forwarding.
    for (std::size_t i = first; over_w && !batch && i < first + count; ++i) {
      const float inv_w = out.projected[i].screen.inv_w;
      const float* v = out.clip[i].varyings;
      float* o = over_w + i * varyings;
      for (int k = 0; k < varyings; ++k) o[k] = v[k] * inv_w;
    }
  }
}

}  // namespace

bool keeps_clip_vertices(const DrawRecord& draw, const ClipBounds& guard) {
  // Cheapest tests first: the bounds are looked at only where nothing else asks for them.
  return draw.pipeline.vertex_batch == nullptr || has_triangle_hooks(draw) ||
         draw.pipeline.draws_edges || draw.mesh->topology == Topology::lines || !draw.bounds ||
         !box_inside_clip_bounds(*draw.bounds, draw.uniforms.model_view_projection, guard);
}

void transform_vertices(const DrawRecord& draw, const Kernels& kernels, int width, int height,
                        const ClipBounds& guard, int workers, DrawVertices& out) {
  std::size_t count = draw.mesh->positions.size();
  const Mesh& mesh = *draw.mesh;
  out.clip_written = draw.clip_vertices;
  if (out.clip_written) out.clip.resize(count);
  out.projected.resize(count);
  // Only setup's fast path reads over_w, and it never runs for draws with hooks.
  out.over_w.resize(has_triangle_hooks(draw) ? 0 : count * draw.pipeline.varyings + kOverWSlack);
  const VertexPassInput to{mesh.positions.data(),
                           mesh.normals.empty() ? nullptr : mesh.normals.data(),
                           draw.uniforms.model_view_projection,
                           draw.uniforms.normal_matrix,
                           width,
                           height,
                           {1.0f, 1.0f, guard.clips_user_plane, guard.user_plane},
                           guard};
  if (count <= kVerticesPerTask) {
    transform_range(draw, kernels, to, 0, count, out);
    return;
  }
  int batches = static_cast<int>((count + kVerticesPerTask - 1) / kVerticesPerTask);
  parallel_tasks(batches, workers, [&](int batch, int) {
    std::size_t begin = batch * kVerticesPerTask;
    transform_range(draw, kernels, to, begin, std::min(count, begin + kVerticesPerTask), out);
  });
}

}  // namespace facet::pipeline
