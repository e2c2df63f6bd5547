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

// A run of at most kVertexPass vertices' attributes, each array indexed from the run's first
// vertex: a range of the mesh's arrays, or the corners of one triangle gathered.
struct VertexRun {
  std::size_t count;
  const glm::vec3* positions;
  const glm::vec3* normals;    // null: none
  const glm::vec2* texcoords;  // null: none
  const glm::vec4* colors;     // null: none
  const glm::vec4* tangents;   // null: none
};

// Where transform_run stores a run's results, each indexed from the run's first vertex; a null
// over_w or clip is not stored.
struct RunOutput {
  ProjectedVertex* projected;
  float* over_w;  // `varyings` floats a vertex
  ClipVertex* clip;
};

// The vertex stage for one run: the vertex pass (clip position, world normal, projection), then
// the shading model's varyings, a run at once by its batch form.
void transform_run(const DrawRecord& draw, const Kernels& kernels,
                   const VertexPassInput& pass_input, const VertexRun& run, const RunOutput& out) {
  const int varyings = draw.pipeline.varyings;
  const std::size_t count = run.count;
  VertexPassInput to = pass_input;
  to.positions = run.positions, to.normals = run.normals;
  VertexPass pass;
  static_assert(shading::kVertexBatch == kVertexPass);
  alignas(64) float batch_varyings[kMaxVaryings][shading::kVertexBatch];
  // First, several vertices at a time, all that needs no shading model.
  kernels.vertex_pass(to, 0, count, pass);
  // Then the shading model.
  draw.pipeline.vertex_batch(draw.uniforms,
                             {static_cast<int>(count),
                              run.positions,
                              {pass.nx, pass.ny, pass.nz},
                              run.texcoords,
                              run.colors,
                              run.tangents},
                             batch_varyings);
  kernels.store_projected(pass, count, out.projected);
  // What setup's planes pass through (perspective-correct interpolation of v / w; to_screen's
  // 1 / w is the pass's: the same division).
  if (out.over_w) kernels.store_over_w(batch_varyings, pass.inv_w, count, varyings, out.over_w);
  if (!out.clip) return;  // a draw whose triangles only the setup kernel reads
  for (std::size_t j = 0; j < count; ++j) {
    ClipVertex& v = out.clip[j];
    v.clip = glm::vec4(pass.x[j], pass.y[j], pass.z[j], pass.w[j]);
    for (int k = 0; k < varyings; ++k) v.varyings[k] = batch_varyings[k][j];
  }
}

// The mesh's attribute array from vertex `first` on, or null when the mesh has none.
template <class T>
const T* from(const std::vector<T>& attribute, std::size_t first) {
  return attribute.empty() ? nullptr : attribute.data() + first;
}

void transform_range(const DrawRecord& draw, const Kernels& kernels,
                     const VertexPassInput& pass_input, std::size_t begin, std::size_t end,
                     DrawVertices& out) {
  const Mesh& mesh = *draw.mesh;
  const std::size_t varyings = static_cast<std::size_t>(draw.pipeline.varyings);
  float* over_w = out.over_w.empty() ? nullptr : out.over_w.data();
  for (std::size_t first = begin; first < end; first += kVertexPass) {
    const VertexRun run{std::min(kVertexPass, end - first), &mesh.positions[first],
                        from(mesh.normals, first),          from(mesh.texcoords, first),
                        from(mesh.colors, first),           from(mesh.tangents, first)};
    transform_run(draw, kernels, pass_input, run,
                  {&out.projected[first], over_w ? over_w + first * varyings : nullptr,
                   out.clip_written ? &out.clip[first] : nullptr});
  }
}

}  // namespace

bool keeps_clip_vertices(const DrawRecord& draw, const ClipBounds& guard,
                         std::size_t max_clip_vertex_bytes) {
  // Cheapest tests first: the bounds are looked at only where nothing else asks for them.
  if (draw.pipeline.draws_edges || draw.mesh->topology == Topology::lines) return true;
  if (has_triangle_hooks(draw)) {
    return draw.mesh->positions.size() * sizeof(ClipVertex) <= max_clip_vertex_bytes;
  }
  return !draw.bounds ||
         !box_inside_clip_bounds(*draw.bounds, draw.uniforms.model_view_projection, guard);
}

VertexPassInput vertex_pass_input(const DrawRecord& draw, int width, int height,
                                  const ClipBounds& guard) {
  const Mesh& mesh = *draw.mesh;
  return {mesh.positions.data(),
          mesh.normals.empty() ? nullptr : mesh.normals.data(),
          draw.uniforms.model_view_projection,
          draw.uniforms.normal_matrix,
          width,
          height,
          {1.0f, 1.0f, guard.clips_user_plane, guard.user_plane},
          guard};
}

void transform_corners(const DrawRecord& draw, const Kernels& kernels,
                       const VertexPassInput& pass_input, const std::uint32_t corner[3],
                       ClipVertex out[3]) {
  const Mesh& mesh = *draw.mesh;
  glm::vec3 positions[3], normals[3];
  glm::vec2 texcoords[3];
  glm::vec4 colors[3], tangents[3];
  for (int j = 0; j < 3; ++j) {
    const std::uint32_t i = corner[j];
    positions[j] = mesh.positions[i];
    if (!mesh.normals.empty()) normals[j] = mesh.normals[i];
    if (!mesh.texcoords.empty()) texcoords[j] = mesh.texcoords[i];
    if (!mesh.colors.empty()) colors[j] = mesh.colors[i];
    if (!mesh.tangents.empty()) tangents[j] = mesh.tangents[i];
  }
  const VertexRun run{3,
                      positions,
                      mesh.normals.empty() ? nullptr : normals,
                      mesh.texcoords.empty() ? nullptr : texcoords,
                      mesh.colors.empty() ? nullptr : colors,
                      mesh.tangents.empty() ? nullptr : tangents};
  ProjectedVertex projected[3];
  transform_run(draw, kernels, pass_input, run, {projected, nullptr, out});
}

void transform_vertices(const DrawRecord& draw, const Kernels& kernels, int width, int height,
                        const ClipBounds& guard, int workers, DrawVertices& out) {
  std::size_t count = draw.mesh->positions.size();
  out.clip_written = draw.clip_vertices;
  if (out.clip_written) out.clip.resize(count);
  out.projected.resize(count);
  // Only setup's fast path reads over_w, and it never runs for draws with hooks.
  out.over_w.resize(has_triangle_hooks(draw) ? 0 : count * draw.pipeline.varyings + kOverWSlack);
  const VertexPassInput to = vertex_pass_input(draw, width, height, guard);
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
