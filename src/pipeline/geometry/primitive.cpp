// Stage: primitive assembly (see primitive.hpp).
#include "pipeline/geometry/primitive.hpp"

#include <algorithm>
#include <cmath>

#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/cull_batch.hpp"
#include "pipeline/geometry/vertex.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/setup/sample_positions.hpp"
#include "pipeline/setup/setup.hpp"
#include "pipeline/setup/setup_batch.hpp"
#include "shading/surface.hpp"

namespace facet::pipeline {
namespace {

struct Assembler {
  PrimitiveSink& out;
  PrimitiveCounts& counts;
  int width, height;
  std::uint32_t draw_index;
  const DrawRecord& draw;
  const DrawVertices& vertices;
  ClipBounds guard;
  const Kernels& kernels;
  VertexPassInput pass_input = vertex_pass_input(draw, width, height, guard);
  bool hooks = has_triangle_hooks(draw);
  // Every triangle is set up by the setup kernel (setup_batch.hpp): those that need no clipping
  // a run of culling's survivors at a time, from the draw's projected vertices (unless
  // by_runs is false: wireframe draws, whose edges come before their triangle's fill, and draws
  // with per-triangle hooks); the others one clipped fan at a time (set_up_fan).
  SetupBatchKernel setup_kernel = nullptr;
  bool by_runs = false;
  std::int32_t sample_reach = 0;  // how far a pixel's samples lie from its centre (fixed point)
  // set_up_fan's vertices, projected here; the kernel reads indices and varyings a vector at a
  // time past their ends (kSetupBatchSlack, kOverWSlack).
  static constexpr int kMaxFan = kMaxClipVertices - 2;
  ProjectedVertex fan_vertices[kMaxClipVertices] = {};
  float fan_over_w[kMaxClipVertices * kMaxVaryings + kOverWSlack] = {};
  std::uint32_t fan_index[3][kMaxFan + kSetupBatchSlack] = {};
  std::uint32_t fan_front_facing[kMaxFan + kSetupBatchSlack] = {};

  // Two-sided draws of models that light back faces reverse those faces' normals at setup.
  int back_face_normal = draw.material.cull == CullMode::none && draw.pipeline.lights_back_faces
                             ? draw.pipeline.normal_slot
                             : -1;
  bool culls_front = draw.material.cull == CullMode::front;
  bool culls_back = draw.material.cull == CullMode::back;

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

  // The segment between vertices i0 and i1, clipped to the guard band (the planes the vertex
  // pass found either end outside of), projected and set up.
  void edge(std::uint32_t i0, std::uint32_t i1, const glm::vec4& color) {
    glm::vec4 p = vertices.clip[i0].clip, q = vertices.clip[i1].clip;
    const unsigned planes =
        (vertices.projected[i0].codes | vertices.projected[i1].codes) >> kGuardCodeShift &
        kFrustumCodes;
    if (planes && !clip_segment(p, q, planes, guard)) return;
    const glm::vec4 ends[2] = {p, q};
    ScreenVertex screen[2];
    kernels.project_to_screen(ends, 2, width, height, screen);
    setup_line(out, width, height, screen[0], screen[1], color);
  }

  // A triangle culling (cull_batch.hpp) kept.
  struct Accepted {
    std::uint32_t i0, i1, i2;
    unsigned codes;  // the three vertices' codes, or-ed
    bool front_facing;
    std::uint32_t index;  // in the mesh, when the draw has a triangle hook
  };

  // Whether a triangle culling accepted goes to the setup kernel in a run: assemble()'s common
  // case, tested without its call.
  bool kernel_sets_up(unsigned codes) const { return by_runs && planes_to_clip(codes) == 0; }

  // Sets up the fan (v[0], v[i], v[i + 1]) of a convex polygon of `count` vertices in clip
  // space, inside the guard band, with the setup kernel; returns how many triangles it dropped.
  int set_up_fan(const ClipVertex* v, int count, bool front_facing) {
    const int n = draw.pipeline.varyings;
    glm::vec4 clip[kMaxClipVertices];
    ScreenVertex screen[kMaxClipVertices];
    for (int i = 0; i < count; ++i) clip[i] = v[i].clip;
    kernels.project_to_screen(clip, count, width, height, screen);
    for (int i = 0; i < count; ++i) {
      fan_vertices[i].screen = screen[i];
      for (int k = 0; k < n; ++k)
        fan_over_w[i * n + k] = v[i].varyings[k] * fan_vertices[i].screen.inv_w;
    }
    const int triangles = count - 2;
    for (int t = 0; t < triangles; ++t) {
      fan_index[0][t] = 0;
      fan_index[1][t] = static_cast<std::uint32_t>(t + 1);
      fan_index[2][t] = static_cast<std::uint32_t>(t + 2);
      fan_front_facing[t] = front_facing ? 1u : 0u;
    }
    const SetupBatch batch{triangles, {fan_index[0], fan_index[1], fan_index[2]}, fan_front_facing};
    return setup_kernel(batch, {out, width, height, draw_index, fan_vertices, fan_over_w, n,
                                back_face_normal, shading::kPositionSlot});
  }

  // Edges, clipping and setup of a triangle culling accepted that the setup kernel does not
  // take (kernel_sets_up).
  void assemble(const Accepted& a) {
    const std::uint32_t i0 = a.i0, i1 = a.i1, i2 = a.i2;
    const bool front_facing = a.front_facing;
    const DrawPipeline& pipe = draw.pipeline;
    if (pipe.draws_edges) {
      const std::uint32_t corner[3] = {i0, i1, i2};
      for (int i = 0; i < 3; ++i) edge(corner[i], corner[(i + 1) % 3], draw.material.wire_color);
    }
    if (!pipe.fills_triangles) return;

    const unsigned planes = planes_to_clip(a.codes);
    if (planes == 0 && !hooks) {  // set up from the projected vertices (wireframe draws)
      const std::uint32_t index[3][1 + kSetupBatchSlack] = {{i0}, {i1}, {i2}};
      const std::uint32_t front[1 + kSetupBatchSlack] = {front_facing ? 1u : 0u};
      const SetupBatch batch{1, {index[0], index[1], index[2]}, front};
      counts.culled += setup_kernel(
          batch, {out, width, height, draw_index, vertices.projected.data(), vertices.over_w.data(),
                  pipe.varyings, back_face_normal, shading::kPositionSlot});
      return;
    }

    // The per-triangle hooks and the clipper rewrite vertices: work on copies, or on the
    // corners computed now for a draw whose vertex stage kept none (keeps_clip_vertices).
    ClipPolygon polygon;
    polygon.count = 3;
    ClipVertex* v = polygon.vertices;
    if (vertices.clip_written) {
      const ClipVertex* in[3] = {&vertices.clip[i0], &vertices.clip[i1], &vertices.clip[i2]};
      for (int i = 0; i < 3; ++i) v[i] = *in[i];
    } else {
      const std::uint32_t corner[3] = {i0, i1, i2};
      transform_corners(draw, kernels, pass_input, corner, v);
    }
    const bool fill_normal = fills_face_normal(draw);
    const DrawPipeline::FaceFn face = face_hook(draw);
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
    if (pipe.triangle) {
      float* varyings[3] = {v[0].varyings, v[1].varyings, v[2].varyings};
      pipe.triangle(a.index, varyings);
    }
    if (planes == 0) {
      counts.culled += set_up_fan(v, 3, front_facing);
      return;
    }
    ++counts.clipped;
    clip_polygon(polygon, planes, guard, pipe.varyings);
    // Fan re-triangulation of the convex clipped polygon (its triangles dropped at setup are
    // not counted as culled: the triangle was drawn, in part or not).
    if (polygon.count >= 3) set_up_fan(v, polygon.count, front_facing);
  }

  // Sets up survivors [first, end), which need no clipping, with the kernel.
  void set_up_run(const CullSurvivors& survivors, int first, int end) {
    if (first == end) return;
    const SetupBatch batch{end - first,
                           {survivors.i0 + first, survivors.i1 + first, survivors.i2 + first},
                           survivors.front_facing + first};
    counts.culled += setup_kernel(
        batch, {out, width, height, draw_index, vertices.projected.data(), vertices.over_w.data(),
                draw.pipeline.varyings, back_face_normal, shading::kPositionSlot});
  }

  void line(std::uint32_t i0, std::uint32_t i1) {
    const unsigned code0 = vertices.projected[i0].codes, code1 = vertices.projected[i1].codes;
    if (((code0 | code1) & kNotFinite) || (code0 & code1 & kFrustumCodes)) {
      ++counts.culled;
      return;
    }
    edge(i0, i1, draw.material.base_color);
  }

  // A point is kept whole or dropped by its centre: one outside the frustum (or not finite) is
  // dropped, one inside is drawn, its square cut at the frame's edges by setup. Unlit: the
  // vertex color (white without one) times the material's base color, opaque.
  void point(std::uint32_t i, std::int32_t half, bool vertex_colors) {
    const ProjectedVertex& v = vertices.projected[i];
    if (v.codes & (kNotFinite | kFrustumCodes)) {
      ++counts.culled;
      return;
    }
    glm::vec4 color = draw.material.base_color;
    if (vertex_colors) color *= draw.mesh->colors[i];
    color.a = 1.0f;
    if (!setup_point(out, width, height, v.screen, half, color)) ++counts.culled;
  }
};

// The mesh's i-th index (its i-th vertex when it has none).
std::uint32_t vertex_index(const Mesh& mesh, std::size_t i) {
  return mesh.indices.empty() ? static_cast<std::uint32_t>(i) : mesh.indices[i];
}

// Lists the vertex indices of triangles [first, first + count): a list's three a triangle, a
// strip's with odd triangles' first two vertices swapped so every triangle keeps the strip's
// winding. Returns where they are (a list with indices is read in place).
const std::uint32_t* list_triangles(const Mesh& mesh, std::size_t first, int count,
                                    std::uint32_t* listed) {
  if (mesh.topology == Topology::triangles && !mesh.indices.empty()) {
    return mesh.indices.data() + 3 * first;
  }
  for (int k = 0; k < count; ++k) {
    const std::size_t p = first + static_cast<std::size_t>(k);
    std::uint32_t* t = listed + 3 * k;
    if (mesh.topology == Topology::triangles) {
      t[0] = vertex_index(mesh, 3 * p), t[1] = vertex_index(mesh, 3 * p + 1);
      t[2] = vertex_index(mesh, 3 * p + 2);
    } else {
      t[0] = vertex_index(mesh, p % 2 == 0 ? p : p + 1);
      t[1] = vertex_index(mesh, p % 2 == 0 ? p + 1 : p);
      t[2] = vertex_index(mesh, p + 2);
    }
  }
  return listed;
}

// Triangles [begin, end), culled a run at a time, several triangles a vector (cull_batch.hpp),
// then assembled in order.
void assemble_triangles(Assembler& assembler, const Mesh& mesh, std::size_t begin,
                        std::size_t end) {
  const CullKernel cull = assembler.kernels.cull;
  CullSurvivors survivors;
  // The setup kernel reads a run's indices a vector at a time, past the run's end.
  static_assert(CullSurvivors::kRoom >= kCullBatch + kSetupBatchSlack);
  std::uint32_t listed[3 * kCullBatch];
  for (std::size_t first = begin; first < end; first += kCullBatch) {
    const int count = static_cast<int>(std::min<std::size_t>(end - first, kCullBatch));
    cull({list_triangles(mesh, first, count, listed), count, assembler.vertices.projected.data(),
          assembler.culls_front, assembler.culls_back, assembler.draw.pipeline.triangle != nullptr,
          assembler.by_runs, assembler.width, assembler.height, assembler.sample_reach},
         survivors);
    assembler.counts.culled += static_cast<std::uint64_t>(count - survivors.count);
    // Runs of survivors that need no clipping go to the setup kernel whole; the others, in
    // between, one at a time, so the sink keeps submission order.
    int run = 0;
    for (int k = 0; k < survivors.count; ++k) {
      if (assembler.kernel_sets_up(survivors.codes[k])) continue;
      assembler.set_up_run(survivors, run, k);
      run = k + 1;
      const bool indexed = assembler.draw.pipeline.triangle != nullptr;
      const auto index = static_cast<std::uint32_t>(indexed ? first + survivors.position[k] : 0);
      assembler.assemble({survivors.i0[k], survivors.i1[k], survivors.i2[k], survivors.codes[k],
                          survivors.front_facing[k] != 0, index});
    }
    assembler.set_up_run(survivors, run, survivors.count);
  }
}

}  // namespace

void assemble_primitives(const Frame& frame, std::uint32_t draw_index, const DrawVertices& vertices,
                         std::size_t begin, std::size_t end, PrimitiveSink& out,
                         PrimitiveCounts& counts) {
  const DrawRecord& draw = frame.draws[draw_index];
  const Mesh& mesh = *draw.mesh;
  Assembler assembler{out,           counts, frame.width, frame.height,
                      draw_index,    draw,   vertices,    guard_band_bounds(frame),
                      *frame.kernels};
  if (mesh.topology == Topology::lines) {
    for (std::size_t p = begin; p < end; ++p) {
      assembler.line(vertex_index(mesh, 2 * p), vertex_index(mesh, 2 * p + 1));
    }
    return;
  }
  if (mesh.topology == Topology::points) {
    const std::int32_t half = point_half_side(draw.material.point_size);
    const bool vertex_colors = draw.material.use_vertex_colors && !mesh.colors.empty();
    for (std::size_t p = begin; p < end; ++p)
      assembler.point(vertex_index(mesh, p), half, vertex_colors);
    return;
  }
  // Edges come before their triangle's fill, so wireframe draws set up one at a time (and draws
  // of edges only set up no triangle).
  assembler.setup_kernel = frame.kernels->setup;
  assembler.sample_reach = sample_reach(frame.samples);
  assembler.by_runs =
      !assembler.hooks && !draw.pipeline.draws_edges && draw.pipeline.fills_triangles;
  assemble_triangles(assembler, mesh, begin, end);
}

}  // namespace facet::pipeline
