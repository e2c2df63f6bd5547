// The data one frame passes between pipeline stages, in the order they run:
//   renderer.cpp records DrawRecords;
//   geometry/vertex.cpp fills each draw's ClipVertex buffer (clip position + varyings);
//   geometry/primitive.cpp assembles primitives, geometry/clip.cpp clips them, setup/ appends
//   SetupTriangles/SetupLines/SetupPoints (and the triangles' varying planes) to the Frame;
//   bin/bin.cpp appends primitive references to the tile bins;
//   raster/ (render_tile.cpp, raster.hpp, line.cpp, point.cpp) reads them per tile; output/
//   resolves tiles to the framebuffer.
// Every container is cleared, not freed, between frames, so steady-state frames reuse memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <new>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/renderer.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "shading/shade_batch.hpp"
#include "shading/uniforms.hpp"
#include "shading/varyings.hpp"
#include "shading/vertex_batch.hpp"

namespace facet::pipeline {

using shading::kMaxVaryings;

struct ClipVertex {
  glm::vec4 clip;  // homogeneous clip-space position
  float varyings[kMaxVaryings];
};

// A vertex after the perspective divide and viewport transform (setup.cpp's to_screen).
struct ScreenVertex {
  std::int32_t x, y;  // fixed point, y down
  float z;            // window depth in [0, 1]
  float inv_w;
};

// ProjectedVertex::codes: outcodes against the frustum and the guard band (clip.hpp's
// ClipPlane bits, the guard band's shifted up), and whether the position is not finite.
inline constexpr int kGuardCodeShift = 8;
inline constexpr std::uint32_t kNotFinite = 1u << 16;

// What primitive assembly and setup need of a vertex, computed once per vertex by the vertex
// stage rather than once per triangle corner (a vertex of a closed mesh is a corner of about
// six triangles): the facing test's inputs, the outcodes, and the screen position.
struct ProjectedVertex {
  float clip_x, clip_y, clip_w;  // homogeneous_orientation's inputs
  std::uint32_t codes;
  ScreenVertex screen;  // meaningful only when codes say the vertex needs no clipping
};

// Floats DrawVertices::over_w holds past its last vertex: batched setup (setup_batch.cpp) reads
// a vertex's varyings in whole vectors.
inline constexpr int kOverWSlack = 16;

// A draw's transformed vertices, reused across frames.
struct DrawVertices {
  // What the clipper, the per-triangle hooks and the edges read; not written (clip_written
  // false) for a draw that reads none of them, whose planes come from over_w alone, nor for a
  // big draw with hooks, whose corners primitive assembly computes (vertex.hpp).
  std::vector<ClipVertex> clip;
  bool clip_written = true;
  std::vector<ProjectedVertex> projected;  // what culling and setup read
  // varyings[k] * screen.inv_w, `varyings` floats per vertex: the values setup's planes pass
  // through (perspective-correct interpolation interpolates v / w). Empty when the draw has
  // per-triangle hooks, which rewrite the varyings before setup.
  std::vector<float> over_w;
};

struct TileContext;
struct SetupTriangle;
struct Kernels;  // kernels.hpp
using RasterTriangleFn = void (*)(TileContext&, const SetupTriangle&);

// How a draw is shaded, fixed once per draw (record/pipeline_table.cpp).
struct DrawPipeline {
  int varyings = 0;
  int normal_slot = -1;
  using FaceFn = void (*)(glm::vec3 normal, glm::vec3 centre, const shading::DrawUniforms&,
                          float* [3]);
  FaceFn face = nullptr;                  // every triangle (flat shading)
  FaceFn face_without_normals = nullptr;  // triangles of meshes without normals (Gouraud)
  // Every triangle, with its index in the mesh (the triangle ids output), after the face hooks.
  using TriangleFn = void (*)(std::uint32_t index, float* [3]);
  TriangleFn triangle = nullptr;
  RasterTriangleFn raster = nullptr;
  // The material maps besides the base color map the batch form reads (shading::maps_read).
  unsigned maps_read = 0;
  // The model's vertex stage for a run of vertices (shading/vertex_batch.hpp), every draw's.
  void (*vertex_batch)(const shading::DrawUniforms&, const shading::VertexBatchInput&,
                       float (*)[shading::kVertexBatch]) = nullptr;
  // The model lights the back of a two-sided material (CullMode::none) as a front: setup
  // reverses the normal's planes (normal_slot) of the draw's back-facing triangles, so the
  // normal is the side seen, as the triangle's facing says, not as the interpolated normal
  // does at a smooth silhouette.
  bool lights_back_faces = false;
  // The model lights its vertices (Gouraud), shadows included: its lookups are where the
  // vertices are, not only where the view sees.
  bool lights_vertices = false;
  bool fills_triangles = true;  // false for wireframe: edges only
  bool draws_edges = false;     // wireframe: edges become lines (line.cpp)
  bool depth_tested = true;     // false for debug counters that see through everything
  bool occludes = true;         // opaque, depth-tested and depth-writing (occlusion.hpp)
  // Writes display values only (shading/models.hpp's DisplayReferred), unblended: frames of
  // such draws alone skip the sRGB encode (frame_run.cpp's display_referred_frame).
  bool display_referred = false;
};

// Object-space bounding box of a mesh's positions (draw_culling.hpp).
struct MeshBox {
  glm::vec3 low, high;
  // Corner k (bit 0: x high, bit 1: y high, bit 2: z high), as a point.
  glm::vec4 corner(int k) const {
    return {k & 1 ? high.x : low.x, k & 2 ? high.y : low.y, k & 4 ? high.z : low.z, 1.0f};
  }
  glm::vec4 centre() const { return glm::vec4((low + high) * 0.5f, 1.0f); }
};

struct DrawRecord {
  const Mesh* mesh = nullptr;
  std::optional<MeshBox> bounds;  // none for a mesh with non-finite positions
  float view_depth = 0.0f;        // of the mesh's bounds centre: blended draws sort on it
  Material material;
  shading::DrawUniforms uniforms;
  DrawPipeline pipeline;
  // The maps the raster loop samples ahead for the batch form (shading::maps_to_sample), once
  // per frame (frame_run.cpp).
  const TextureMap* maps[shading::kMaterialMaps] = {};
  // Its vertex stage writes ClipVertex (vertex.hpp's keeps_clip_vertices); also decided once
  // per frame.
  bool clip_vertices = true;
};

// The per-triangle hooks primitive assembly runs before setup: a face normal for shading
// models that need one when the mesh has none, the per-face function (flat shading, or
// Gouraud lighting of a mesh without normals) and the per-triangle function given the
// triangle's index. All rewrite the triangle's varyings.
inline bool fills_face_normal(const DrawRecord& draw) {
  return draw.pipeline.normal_slot >= 0 && draw.mesh->normals.empty();
}
inline DrawPipeline::FaceFn face_hook(const DrawRecord& draw) {
  const DrawPipeline& pipe = draw.pipeline;
  return pipe.face ? pipe.face : (draw.mesh->normals.empty() ? pipe.face_without_normals : nullptr);
}
inline bool has_triangle_hooks(const DrawRecord& draw) {
  return fills_face_normal(draw) || face_hook(draw) != nullptr || draw.pipeline.triangle != nullptr;
}

using shading::Plane;

// A triangle ready to rasterize. Edge i is E_i(X, Y) = a[i]*X + b[i]*Y + c[i] in fixed-point
// units (fixed_point.hpp), positive inside; a pixel is covered when E_i >= 0 for all three
// edges. The fill rule is folded into c: edges that are not top-left have c lowered by 1, so
// a pixel centre exactly on them (E = 0 before) fails. a and b are differences of snapped
// coordinates, within 24 bits (fixed_point.hpp), so 32 bits hold them; c needs 64.
struct SetupTriangle {
  std::int32_t a[3], b[3];
  std::int64_t c[3];
  int min_x, min_y, max_x, max_y;  // pixel bounding box, inclusive, inside the framebuffer
  float ref_x, ref_y;              // first vertex, in pixels
  Plane z;                         // window depth in [0, 1]
  Plane inv_w;                     // 1 / clip w, for perspective correction
  std::uint32_t varying_planes;    // index of the first of the draw's varying planes (v / w)
  std::uint32_t draw;              // index into Frame::draws
};

// Edge function i of triangle t at the centre of pixel (x, y): exact in 64 bits.
inline std::int64_t edge_at_centre(const SetupTriangle& t, int i, int x, int y) {
  return std::int64_t{t.a[i]} * pixel_centre(x) + std::int64_t{t.b[i]} * pixel_centre(y) + t.c[i];
}

// Bin entries: a triangle index, a line index with kLineBit set, or a point index with
// kPointBit set. Indices stay below kMaxPrimitiveIndex (primitive_sink.hpp says why that is
// no limit), clear of these bits and of the sink's kOverflowBit.
inline constexpr std::uint32_t kLineBit = 0x80000000u;
inline constexpr std::uint32_t kPointBit = 0x20000000u;
inline constexpr std::uint32_t kMaxPrimitiveIndex = kPointBit;
inline bool is_triangle_entry(std::uint32_t entry) { return !(entry & (kLineBit | kPointBit)); }

// A line segment ready to rasterize (line.cpp says how lines cover pixels).
struct SetupLine {
  std::int32_t x0, y0, x1, y1;  // fixed point
  float z0, z1;                 // window depth at the ends
  int min_x, min_y, max_x, max_y;
  glm::vec4 color;  // linear RGBA
};

// A point ready to rasterize: setup already applied the fill rule (setup.hpp's setup_point), so
// it covers exactly the pixels of its box, at one depth.
struct SetupPoint {
  int min_x, min_y, max_x, max_y;  // the pixels it covers, inclusive, inside the framebuffer
  float z;                         // window depth of its centre
  glm::vec4 color;                 // linear RGBA
};

// UninitializedAllocator's blocks: those of kMappedBlockBytes or more are mappings of their own
// (frame_memory.cpp), whatever malloc's settings (the CLI keeps blocks of up to 1 GiB in its
// heap): their untouched pages are never resident, and a freed one is given back at once rather
// than kept in the heap, resident where it was touched. Smaller ones stay in the heap, where the
// CLI backs the first 256 MiB with huge pages (fewer TLB misses for a million-triangle frame).
inline constexpr std::size_t kMappedBlockBytes = std::size_t{256} << 20;
void* allocate_block(std::size_t bytes);
void free_block(void* block, std::size_t bytes);

// Allocates without initializing: a vector of it that grows leaves its new elements unwritten.
// The frame's triangle and plane arrays are sized for every primitive of the frame (each chunk
// gets a region as big as its input), but only the primitives that survive culling are written,
// and at a million triangles to a few hundred thousand pixels most do not: pages never written
// are never made resident, so the memory the arrays cost follows what is drawn, not the input
// (BENCHMARKS.md, "Big meshes"). Only for
// aggregates of trivially copyable members (implicit-lifetime types: allocating the storage
// creates them, C++20 [intro.object]); nothing reads an element before writing it.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  static_assert(std::is_aggregate_v<T> && std::is_trivially_copyable_v<T> &&
                std::is_trivially_destructible_v<T>);
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) {}
  T* allocate(std::size_t n) {
    if (n > SIZE_MAX / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_block(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) { free_block(p, n * sizeof(T)); }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) > 0) ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template <class T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

// Set-up primitives: what setup produces and raster reads. SetupTriangle::varying_planes
// indexes planes.
struct PrimitiveBuffer {
  UninitializedVector<SetupTriangle> triangles;
  std::vector<SetupLine> lines;
  std::vector<SetupPoint> points;  // never in a chunk's overflow: one point per input point
  UninitializedVector<Plane> planes;

  void clear() { triangles.clear(), lines.clear(), points.clear(), planes.clear(); }
};

// A set-up primitive as binning reads it (bin.hpp's binning_entry makes it while setup still
// has the primitive in cache): its index (a bin entry: kLineBit, kPointBit), the rectangle of tiles
// its pixel bounding box touches (inclusive; at most 8192 / 16 tiles a side,
// Framebuffer::kMaxSize), and which of those tiles it may cover: bit (ty - tile_y0) * (tile_x1 -
// tile_x0 + 1) + (tx - tile_x0), for rectangles of at most kMaskedTiles tiles. Binning edge-tests
// bigger rectangles' tiles itself.
inline constexpr int kMaskedTiles = 32;
struct SequenceEntry {
  std::uint32_t index;
  std::uint16_t tile_x0, tile_y0, tile_x1, tile_y1;
  std::uint32_t tiles;
};

// What primitive assembly counts for FrameStats, per chunk.
struct PrimitiveCounts {
  std::uint64_t culled = 0;   // rejected: outside the frustum, facing away, degenerate
  std::uint64_t clipped = 0;  // needed clipping
};

// A run of one draw's primitives [begin, end) set up by one task, straight into its regions
// of the frame's primitive arrays (primitive_sink.hpp).
struct GeometryChunk {
  std::uint32_t draw = 0;
  std::size_t begin = 0, end = 0;
  // A region of one of the frame's arrays: [begin, begin + capacity), the first `used` set.
  struct Region {
    std::uint32_t begin = 0, capacity = 0, used = 0;
  };
  Region triangles, lines, points;
  std::uint32_t planes_begin = 0;  // triangle region slot i has planes_begin + i * varyings
  PrimitiveBuffer overflow;        // what did not fit in the regions (clipped fans)
  // Every primitive's sequence entry, in submission order: in the chunk's region `entries` of
  // the frame's `sequence` (room for one per primitive the regions above hold), then, past it,
  // those of the clipped fans' extra pieces. Binning walks the chunks' entries in order, so bins
  // keep submission order. In the frame's array rather than the chunk's own: chunk k holds
  // another draw's primitives in each pass (the shadow passes draw other subsets), and a buffer
  // of its own would grow, allocating, whenever a pass put a bigger one there.
  Region entries;
  std::vector<SequenceEntry> more_entries;
  std::size_t sequence_at = 0;  // where its entries start in the frame's concatenation
  std::size_t entry_count() const { return entries.used + more_entries.size(); }
  PrimitiveCounts counts;
};

// The default of Frame::max_triangle_region_bytes: a quarter of the machine's memory (1 GiB if
// unknown). Regions are reserved, and only the survivors' part is ever touched, so a frame
// whose regions fit costs no memory for its culled triangles; past it the reservation itself
// would fail (geometry.cpp).
std::size_t triangle_region_budget();

// The default of Frame::max_clip_vertex_bytes: meshes of up to about 3 million vertices keep
// their ClipVertex, each computed once rather than once for every surviving triangle it is a
// corner of; bigger ones save 80 bytes a vertex for about twice the vertex work.
inline constexpr std::size_t kMaxClipVertexBytes = std::size_t{256} << 20;

// The frame: everything above, and the set-up primitives (in the chunks' regions and then
// their overflow; only the chunks' sequences say which slots hold one).
struct Frame : PrimitiveBuffer {
  int width = 0;
  int height = 0;
  int tile_size = 64;
  // Samples per pixel (RenderSettings::msaa; 1 for debug views and the extra outputs' passes):
  // setup widens pixel boxes and binning its tile tests to the samples' reach (raster/msaa.hpp).
  int samples = 1;
  int tiles_x = 0;
  int tiles_y = 0;
  glm::mat4 view_projection{1.0f};
  // A plane in clip space the frame's primitives are cut at, keeping where (a x + b y) +
  // (c z + d w) >= 0 (geometry/clip.hpp's ClipBounds::user_plane): a reflection pass's mirror.
  std::optional<glm::vec4> clip_plane;
  std::vector<DrawRecord> draws;
  std::vector<std::uint32_t> draw_order;  // opaque in submission order, then blended far-first
  std::vector<shading::LightData> lights;
  shading::FrameUniforms uniforms;            // every draw's uniforms point here
  const Kernels* kernels = nullptr;           // the SIMD kernels, fetched when the frame runs
  std::vector<DrawVertices> vertices;         // per draw slot (big draws), reused
  std::vector<DrawVertices> worker_vertices;  // per worker (small draws, one at a time)
  // Reused across frames: the first chunk_count are this frame's.
  std::vector<GeometryChunk> chunks;
  std::size_t chunk_count = 0;
  UninitializedVector<SequenceEntry> sequence;  // the chunks' entries regions
  // Frames whose triangles' regions of `triangles` and `planes` would take more bytes than this
  // set their triangles up without regions (geometry.cpp's plan_chunks; tests lower it).
  std::size_t max_triangle_region_bytes = triangle_region_budget();
  // Draws with per-triangle hooks whose ClipVertex would take more bytes than this keep none:
  // their triangles' corners are computed when culling keeps them (vertex.hpp's
  // keeps_clip_vertices; tests lower it).
  std::size_t max_clip_vertex_bytes = kMaxClipVertexBytes;
  // Geometry's parallel tasks: chunks [first_chunk, end_chunk), after transforming their draw's
  // vertices when `transform` says so (geometry.cpp).
  struct GeometryTask {
    std::uint32_t first_chunk, end_chunk;
    bool transform;
  };
  std::vector<GeometryTask> geometry_tasks;
  std::size_t primitives = 0;  // set-up primitives: the chunks' sequences, concatenated
  // One bin per tile, in submission order. An entry is a triangle index, a line index with
  // kLineBit set or a point index with kPointBit set.
  // The bins, one flat arena: tile i's entries are bin_entries[bin_start[i] .. bin_start[i+1]).
  std::vector<std::uint32_t> bin_start;  // tiles + 1
  std::vector<std::uint32_t> bin_entries;
  std::vector<std::uint32_t> bin_cursors;  // binning's per-run counts, then write cursors
  // Per tile: whether some entry of its bin may hide the whole tile (an occluding draw's
  // triangle whose box holds the tile: occlusion.hpp), so that its hidden work is worth
  // looking for. bin_hiders: the same per binning run and tile, before they are merged.
  std::vector<std::uint8_t> bin_may_hide;
  std::vector<std::uint8_t> bin_hiders;
  FrameStats stats;
};

}  // namespace facet::pipeline
