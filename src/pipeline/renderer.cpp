// The Renderer: begin_frame() starts recording, draw() records a draw (checked, culled whole
// when outside the view, its pipeline chosen from the table: record/), finish() runs the frame
// (frame_run.cpp). Also the internal entry for draws with their own shading models
// (record/custom_draw.hpp).
#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>
#include <memory>
#include <optional>
#include <string>

#include "core/scope_exit.hpp"
#include "facet/error.hpp"
#include "pipeline/output/debug_view.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/draw_culling.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "pipeline/renderer_impl.hpp"

namespace facet {

using pipeline::is_blended;

namespace {

// The draw's material as the frame keeps it: without its name, which nothing in a frame reads
// and which, longer than a string holds in place (glTF's often are), every copy of the draw
// (the color pass, the shadow and reflection passes) would allocate anew every frame. The
// binding lists every field: a field added to Material stops it compiling until it is copied
// here too.
Material without_name(const Material& m) {
  const auto& [name, shading, base_color, use_vertex_colors, specular_color, shininess, metallic,
               roughness, emissive, reflectivity, reflects_scene, casts_shadows, base_color_map,
               normal_map, normal_scale, specular_map, metallic_roughness_map, occlusion_map,
               occlusion_strength, emissive_map, alpha_mode, alpha_cutoff, wire_color, point_size,
               cull] = m;
  return Material{{},
                  shading,
                  base_color,
                  use_vertex_colors,
                  specular_color,
                  shininess,
                  metallic,
                  roughness,
                  emissive,
                  reflectivity,
                  reflects_scene,
                  casts_shadows,
                  base_color_map,
                  normal_map,
                  normal_scale,
                  specular_map,
                  metallic_roughness_map,
                  occlusion_map,
                  occlusion_strength,
                  emissive_map,
                  alpha_mode,
                  alpha_cutoff,
                  wire_color,
                  point_size,
                  cull};
}

}  // namespace

Renderer::Renderer(const RenderSettings& settings) {
  if (settings.threads < 0 || settings.threads > RenderSettings::kMaxThreads) {
    throw Error("renderer: threads must be 0 (all cores) or 1 to " +
                std::to_string(RenderSettings::kMaxThreads) + ", got " +
                std::to_string(settings.threads));
  }
  const int ts = settings.tile_size;
  if (ts != RenderSettings::kAutoTileSize && ts != 16 && ts != 32 && ts != 64 && ts != 128) {
    throw Error("renderer: tile size must be 16, 32, 64 or 128, or " +
                std::to_string(RenderSettings::kAutoTileSize) + " (auto), got " +
                std::to_string(ts));
  }
  const int map = settings.shadow_map_size;
  if (map < RenderSettings::kMinShadowMapSize || map > Framebuffer::kMaxSize) {
    throw Error("renderer: shadow map size must be " +
                std::to_string(RenderSettings::kMinShadowMapSize) + " to " +
                std::to_string(Framebuffer::kMaxSize) + " texels, got " + std::to_string(map));
  }
  const int cascades = settings.shadow_cascades;
  if (cascades != RenderSettings::kAutoShadowCascades &&
      (cascades < 1 || cascades > RenderSettings::kMaxShadowCascades)) {
    throw Error("renderer: shadow cascades must be 1 to " +
                std::to_string(RenderSettings::kMaxShadowCascades) + ", or " +
                std::to_string(RenderSettings::kAutoShadowCascades) +
                " (chosen from the view), got " + std::to_string(cascades));
  }
  if (!(settings.reflection_scale > 0.0f && settings.reflection_scale <= 1.0f)) {
    throw Error("renderer: reflection scale must be in (0, 1], got " +
                std::to_string(settings.reflection_scale));
  }
  const int n = settings.msaa;
  if (n != 1 && n != 2 && n != 4 && n != 8 && n != 16) {
    throw Error("renderer: msaa must be 1, 2, 4, 8 or 16 samples per pixel, got " +
                std::to_string(n));
  }
  impl_ = std::make_unique<Impl>(settings);
}

Renderer::~Renderer() = default;

const RenderSettings& Renderer::settings() const { return impl_->settings; }
const FrameStats& Renderer::stats() const { return impl_->frame.stats; }

void Renderer::begin_frame(const Camera& camera) {
  // A shared default, so a frame without lighting builds no Lighting (and allocates nothing).
  static const Lighting kDefaultLighting;
  begin_frame(camera, kDefaultLighting);
}

const Camera& Renderer::camera() const { return impl_->camera; }

void Renderer::begin_frame(const Camera& camera, const Lighting& lighting) {
  camera.validate();
  impl_->camera = camera;
  impl_->lighting = lighting;
  impl_->frame.draws.clear();
  impl_->outside_view_draws.clear();
  impl_->frame_shadows =
      impl_->settings.shadows &&
      std::any_of(lighting.lights.begin(), lighting.lights.end(), [](const Light& light) {
        return light.casts_shadows && light.type != LightType::point;
      });
  impl_->frame_reflections =
      impl_->settings.reflections && impl_->settings.debug_view == DebugView::none;
  impl_->primitives_outside = 0;
  impl_->instance_id.reset();
  impl_->draw_calls = 0;
  const std::uint64_t frame_number = ++impl_->frame_number;
  std::erase_if(impl_->checked_meshes, [frame_number](const auto& entry) {
    return entry.second.last_frame + 1 < frame_number;  // not drawn in the last frame
  });
  impl_->frame.view_projection = camera.view_projection();
  impl_->recording = true;
}

void Renderer::draw(const Mesh& mesh, const Material& material, const glm::mat4& transform) {
  impl_->check_and_record(
      mesh, material, transform,
      pipeline::pipeline_for(material, mesh, impl_->lighting, impl_->frame_shadows));
}

void Renderer::draw(const std::shared_ptr<const Mesh>& mesh, const Material& material,
                    const glm::mat4& transform) {
  const std::optional<pipeline::MeshBox>& box = impl_->checked_bounds(mesh);
  impl_->record(*mesh, box, material, transform,
                pipeline::pipeline_for(material, *mesh, impl_->lighting, impl_->frame_shadows));
}

void Renderer::set_instance_id(std::uint32_t id) {
  impl_->require_recording("set_instance_id()");
  impl_->instance_id = id;
}

void Renderer::Impl::require_recording(const char* call) const {
  if (recording) return;
  // frame_number counts begin_frame() calls: a frame was begun, and finish() ended it.
  if (frame_number > 0) {
    throw Error(std::string("renderer: ") + call +
                " called after finish(); begin_frame() starts the next frame");
  }
  throw Error(std::string("renderer: ") + call + " called before begin_frame()");
}

const std::optional<pipeline::MeshBox>& Renderer::Impl::checked_bounds(
    const std::shared_ptr<const Mesh>& mesh) {
  require_recording("draw()");
  if (!mesh) throw Error("renderer: draw() of a null mesh pointer");
  auto [entry, added] = checked_meshes.try_emplace(mesh.get());
  if (added) {
    try {
      mesh->validate();
    } catch (...) {
      checked_meshes.erase(entry);
      throw;
    }
    entry->second.mesh = mesh;
    entry->second.box = pipeline::finite_bounds(*mesh);
  }
  entry->second.last_frame = frame_number;
  return entry->second.box;
}

void Renderer::Impl::check_and_record(const Mesh& mesh, const Material& material,
                                      const glm::mat4& transform,
                                      const pipeline::DrawPipeline& pipe) {
  require_recording("draw()");
  mesh.validate();
  record(mesh, pipeline::finite_bounds(mesh), material, transform, pipe);
}

void Renderer::Impl::record(const Mesh& mesh, const std::optional<pipeline::MeshBox>& box,
                            const Material& material, const glm::mat4& transform,
                            const pipeline::DrawPipeline& pipe) {
  if (mesh.topology == Topology::points &&
      !(material.point_size > 0.0f && material.point_size <= Material::kMaxPointSize)) {
    throw Error("renderer: point_size must be in (0, " +
                std::to_string(static_cast<int>(Material::kMaxPointSize)) + "] pixels, got " +
                std::to_string(material.point_size));
  }
  ++draw_calls;
  const glm::mat4 model_view_projection = frame.view_projection * transform;
  const bool outside = box && pipeline::box_outside_frustum(*box, model_view_projection);
  if (outside) {
    primitives_outside += mesh.primitive_count();
    if (!frame_shadows && !frame_reflections) return;
  }
  pipeline::DrawRecord record;
  record.mesh = &mesh;
  record.bounds = box;
  record.material = without_name(material);
  record.pipeline = pipeline::debug_pipeline(settings.debug_view, pipe);
  if (is_blended(material.alpha_mode) && box) {
    glm::vec4 centre = camera.view() * transform * box->centre();
    record.view_depth = -centre.z;
  }
  shading::DrawUniforms& u = record.uniforms;
  u.model = transform;
  u.model_view_projection = model_view_projection;
  u.normal_matrix = glm::inverseTranspose(glm::mat3(transform));
  u.instance_id = instance_id.value_or(draw_calls);
  (outside ? outside_view_draws : frame.draws).push_back(record);
}

void Renderer::finish(Framebuffer& target) {
  if (!target.has_color()) {
    throw Error(
        "renderer: finish into a depth-only framebuffer; render depth alone into a RenderTexture "
        "whose options keep no color");
  }
  // The kept record is out of the framebuffer while the frame writes it, which it does through
  // the non-const accessors that would forget the record.
  std::unique_ptr<ClearTiles> kept = std::move(target.cleared_tiles_.tiles);
  const ScopeExit hand_back{[&] { target.cleared_tiles_.tiles = std::move(kept); }};
  impl_->finish(target, false, kept.get());
}

void Renderer::Impl::finish(Framebuffer& target, bool depth_only, ClearTiles* clear_tiles) {
  require_recording("finish()");
  if (target.extra_outputs().any()) check_extra_outputs(target);
  arena.execute([&] {
    run_shadow_passes();
    if (!depth_only) run_reflection_passes(target);
    if (depth_only) use_depth_only_models();
    depth_only_pass = depth_only;
    map_clear_tiles = clear_tiles;
    const ScopeExit restore{[&] {
      depth_only_pass = false;
      map_clear_tiles = nullptr;
    }};
    run(target);
    frame.stats.ms_shadows = shadow_ms;
    frame.stats.ms_reflections = reflection_ms;
    frame.stats.ms_total += shadow_ms + reflection_ms;
    if (target.extra_outputs().any()) run_extra_outputs(target);
  });
  shadows_ready = false;
  recording = false;
}

void Renderer::Impl::use_depth_only_models() {
  for (pipeline::DrawRecord& draw : frame.draws) {
    const pipeline::DrawPipeline& own = draw.pipeline;
    if (own.occludes && own.fills_triangles && draw.material.alpha_mode == AlphaMode::opaque &&
        draw.mesh->topology != Topology::lines && draw.mesh->topology != Topology::points) {
      pipeline::draw_depth_alone(draw);
    }
  }
}

namespace {

// Whether a material or the environment of what was recorded samples one of target's textures.
bool samples(const std::vector<pipeline::DrawRecord>& draws, const RenderTexture& target) {
  for (const pipeline::DrawRecord& draw : draws) {
    const Material& m = draw.material;
    for (const TextureMap* map : {&m.base_color_map, &m.normal_map, &m.specular_map,
                                  &m.metallic_roughness_map, &m.occlusion_map, &m.emissive_map}) {
      if (target.owns(map->texture.get())) return true;
    }
  }
  return false;
}

}  // namespace

void Renderer::finish(RenderTexture& target) {
  impl_->require_recording("finish()");
  if (samples(impl_->frame.draws, target) || samples(impl_->outside_view_draws, target) ||
      target.owns(impl_->lighting.environment.image.get())) {
    throw Error(
        "renderer: a draw samples the render texture it would be rendered into; render that "
        "texture with an earlier finish()");
  }
  impl_->finish(target.framebuffer_, !target.options().color, target.framebuffer_clear_.get());
  impl_->arena.execute([&] { target.trade_buffers(); });  // on the renderer's threads
}

struct RendererAccess {
  static Renderer::Impl& impl(Renderer& renderer) { return *renderer.impl_; }
};

namespace pipeline {

void draw_with_pipeline(Renderer& renderer, const Mesh& mesh, const Material& material,
                        const glm::mat4& transform, const DrawPipeline& pipe) {
  RendererAccess::impl(renderer).check_and_record(mesh, material, transform, pipe);
}

void draw_with_pipeline(Renderer& renderer, const std::shared_ptr<const Mesh>& mesh,
                        const Material& material, const glm::mat4& transform,
                        const DrawPipeline& pipe) {
  auto& impl = RendererAccess::impl(renderer);  // Impl is private: not named here
  const std::optional<MeshBox>& box = impl.checked_bounds(mesh);
  impl.record(*mesh, box, material, transform, pipe);
}

void set_max_triangle_region_bytes(Renderer& renderer, std::size_t bytes) {
  RendererAccess::impl(renderer).frame.max_triangle_region_bytes = bytes;
}

void set_max_clip_vertex_bytes(Renderer& renderer, std::size_t bytes) {
  RendererAccess::impl(renderer).frame.max_clip_vertex_bytes = bytes;
}

}  // namespace pipeline
}  // namespace facet
