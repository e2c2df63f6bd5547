// The renderer's state between draw() and finish(): what Renderer records (renderer.cpp), what
// the frame run reads and keeps (frame_run.cpp), and each worker's tile buffers, which
// render_tile (raster/render_tile.cpp) draws into.
#pragma once

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/clear_tiles.hpp"
#include "facet/render_texture.hpp"
#include "facet/renderer.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/output/output.hpp"
#include "pipeline/shadow/closed_surface.hpp"
#include "shading/planar_reflection.hpp"
#include "shading/shadow_map.hpp"

namespace facet {
namespace pipeline {

using Clock = std::chrono::steady_clock;
struct ShadowReach;

inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

inline bool is_blended(AlphaMode mode) {
  return mode == AlphaMode::blend || mode == AlphaMode::additive;
}

// A worker's tile buffers, reused for every tile it renders.
struct TileBuffers {
  std::vector<glm::vec4> color;
  std::vector<std::uint32_t> codes;  // TileContext::codes
  std::vector<float> depth;
  std::vector<float> block_max_depth;  // one per 8x8 block (raster/raster.hpp)
  // MSAA (TileContext): depth holds a plane per sample, color each pixel's sample 0 then the
  // others' samples pixel by pixel (sample_colors); one entry per pixel here.
  std::vector<std::uint8_t> split;
  std::vector<std::uint16_t> sample_mask;
};

}  // namespace pipeline

struct Renderer::Impl {
  RenderSettings settings;
  int workers;
  // oneTBB caps workers at the core count unless told otherwise; more threads than cores is
  // a legitimate request (the determinism tests make it), so raise the cap while we live.
  std::optional<tbb::global_control> allow_workers;
  tbb::task_arena arena;
  std::vector<pipeline::TileBuffers> tile_buffers;  // one per worker
  pipeline::Frame frame;
  pipeline::Kernels kernels;  // this frame's (frame.kernels points here)
  std::vector<std::uint64_t> tile_pixels_shaded;
  std::vector<std::uint64_t> tile_ticks, tile_resolve_ticks;  // per tile: its task, its resolve
  pipeline::Background background;
  pipeline::Resolve resolve;                         // set when the frame runs
  shading::IrradianceHarmonics environment_light{};  // when the environment lights the frame
  Camera camera;
  Lighting lighting;
  bool recording = false;
  // The instance id of the next draws (Renderer::set_instance_id), and how many draw() calls the
  // frame has had: each draw's id until the first set_instance_id().
  std::optional<std::uint32_t> instance_id;
  std::uint32_t draw_calls = 0;
  // The float target the extra outputs' passes render into, reused while the size stays.
  std::optional<Framebuffer> pass_target;
  std::uint64_t primitives_outside = 0;  // of draws outside the frustum, never drawn in color
  // Whether this frame renders shadow maps (RenderSettings::shadows and a light that casts
  // them), decided at begin_frame(); then the draws outside the camera's view are kept here,
  // since they may still cast shadows into it (shadow_passes.cpp).
  bool frame_shadows = false;
  std::vector<pipeline::DrawRecord> outside_view_draws;
  // Each light's shadow maps (by its index in lighting.lights): the depth targets of its passes
  // and what the lit models read of them; `maps.count` 0 when the light has none this frame.
  struct LightShadow {
    std::optional<Framebuffer> targets[shading::kMaxShadowCascades];
    ClearTiles clear_tiles[shading::kMaxShadowCascades];
    shading::ShadowMaps maps;
  };
  std::vector<LightShadow> shadows;
  bool shadows_ready = false;    // run() hands the maps to the lights (after the passes)
  bool depth_only_pass = false;  // run() writes depth alone (Background::depth_only)
  // A shadow pass's map's reach (shadow_reach.hpp): run() leaves the tiles outside it as they
  // were, since no lookup reads them. None: every tile is drawn.
  const pipeline::ShadowReach* map_reach = nullptr;
  // The target's ClearTiles (a shadow map's, a render texture's, a framebuffer's that keeps
  // them): run() fits it to the frame's tiles, skips clearing those it names again, and keeps
  // it current. None: every empty tile is cleared.
  ClearTiles* map_clear_tiles = nullptr;
  // run() stores light only, never display values, whatever the target (a reflection pass,
  // whose image the mirrors read as light).
  bool linear_pass = false;
  // The color pass's draws while a shadow or reflection pass runs.
  std::vector<pipeline::DrawRecord> set_aside_draws;
  std::vector<pipeline::DrawRecord> shadow_casters;  // every draw that casts, drawn for the maps
  double shadow_ms = 0.0;
  // Whether this frame may render planar reflections (RenderSettings::reflections, no debug
  // view), decided at begin_frame(); then the draws outside the camera's view are kept too,
  // since a mirror may show them (reflection_passes.cpp).
  bool frame_reflections = false;
  // Each mirror plane's pass of this frame: its plane, its target (cropped to where the mirrors
  // are seen), and what the draws on the plane read of it. The first mirror_count are this
  // frame's.
  struct MirrorPass {
    glm::vec4 plane{0.0f};
    bool seen = false;  // the pass ran: the camera sees a mirror on the plane
    std::optional<RenderTexture> target;
    shading::PlanarReflection reflection;
  };
  std::array<MirrorPass, RenderSettings::kMaxMirrorPlanes> mirrors;
  int mirror_count = 0;
  std::vector<int> mirror_of_draw;  // per color draw: its pass in mirrors, or -1
  double reflection_ms = 0.0;
  // Meshes drawn through shared pointers, checked once (Renderer::draw): checking every mesh again
  // in every frame costs real time in big worlds of many draws, all of it on the recording thread.
  // An entry holds its mesh, so no other mesh can take its address while it is remembered; it is
  // forgotten a frame after the last that drew it.
  struct CheckedMesh {
    std::shared_ptr<const Mesh> mesh;
    std::optional<pipeline::MeshBox> box;
    std::uint64_t last_frame = 0;
    std::optional<pipeline::Closure> closure;  // once a shadow pass asks (closed_surface.hpp)
  };
  std::unordered_map<const Mesh*, CheckedMesh> checked_meshes;
  // The faces a draw casts shadows with (shadow_passes.cpp): both, but a closed opaque mesh's
  // (pipeline::closed_surface, remembered with its check) only those whose outer side faces the
  // light. Meshes drawn by reference are not remembered, so they cast with both.
  CullMode shadow_cull(const pipeline::DrawRecord& draw);
  std::uint64_t frame_number = 0;

  explicit Impl(const RenderSettings& s)
      : settings(s),
        workers(s.threads == 0 ? tbb::info::default_concurrency() : s.threads),
        allow_workers(workers > tbb::info::default_concurrency()
                          ? std::make_optional<tbb::global_control>(
                                tbb::global_control::max_allowed_parallelism, workers)
                          : std::nullopt),
        arena(workers),
        tile_buffers(workers) {}

  // Records a draw of a mesh that Mesh::validate() accepts, whose bounds are `box`.
  void record(const Mesh& mesh, const std::optional<pipeline::MeshBox>& box,
              const Material& material, const glm::mat4& transform,
              const pipeline::DrawPipeline& pipe);
  // The bounds of a mesh drawn through a shared pointer, checked the first time (draw()).
  const std::optional<pipeline::MeshBox>& checked_bounds(const std::shared_ptr<const Mesh>& mesh);
  // Records a draw of any mesh: checks it first.
  void check_and_record(const Mesh& mesh, const Material& material, const glm::mat4& transform,
                        const pipeline::DrawPipeline& pipe);
  // Throws facet::Error unless a frame is being recorded, saying why for `call`.
  void require_recording(const char* call) const;
  void prepare_tiles(const Framebuffer& target);
  void render_tile(int index, int worker, Framebuffer& target);
  void run(Framebuffer& target);
  // Renderer::finish: the shadow passes, then run() (writing depth alone when depth_only),
  // then the extra outputs; ends the frame.
  void finish(Framebuffer& target, bool depth_only, ClearTiles* clear_tiles = nullptr);
  // For a pass that writes depth alone: the draws whose depths are an opaque surface's (filled
  // triangles of opaque materials whose model tests and writes depth) take DepthOnlyShading,
  // as the shadow passes' casters do, and shade nothing; the others keep their models.
  void use_depth_only_models();
  // Throws facet::Error for extra outputs the frame's draws cannot give exactly (ids too big
  // for a float pass), before anything is drawn (output_passes.cpp).
  void check_extra_outputs(const Framebuffer& target) const;
  // The passes of target's extra outputs, after run() drew its color (output_passes.cpp).
  void run_extra_outputs(Framebuffer& target);
  // The shadow maps of the frame's lights, before the color pass (shadow_passes.cpp).
  void run_shadow_passes();
  // The planar reflections of the frame's mirror draws, after the shadow maps and before the
  // color pass into `target` (reflection_passes.cpp); points those draws at them.
  void run_reflection_passes(const Framebuffer& target);
  // The cameras the reflection passes of this frame will see through, before they run: each
  // mirror plane's mirrored camera, uncropped (reflection_passes.cpp). Returns how many.
  int mirror_views(Camera* views);
  // A reflection pass's draws, for mirror plane m seen by `camera` from `eye`'s mirror image:
  // the color pass's and those outside its view, into frame.draws (reflection_passes.cpp).
  void select_mirrored_draws(int m, glm::vec3 eye);
  void order_draws();
  void set_depth_view_range();
  bool draws_only_display_values() const;
  bool display_referred_frame(const Framebuffer& target) const;
  int frame_tile_size(const Framebuffer& target) const;
};

}  // namespace facet
