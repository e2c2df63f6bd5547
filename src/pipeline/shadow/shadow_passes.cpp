// The shadow maps' passes (RenderSettings::shadows): before the color pass, the frame's draws
// run once more per shadow-casting directional or spot light, seen from the light (an
// orthographic view along a directional light, a perspective one from a spot: shadow_fit.hpp),
// into a depth target of the map's size: the same tiled
// pipeline, so the maps, and the images, are the same for any thread count, tile size and SIMD
// target. A sun's passes draw only the casters, and tiles, within their maps' reach
// (shadow_reach.hpp). The color pass's lit models then read them (shading/shadow_map.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

#include "core/scope_exit.hpp"
#include "pipeline/record/draw_culling.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "pipeline/renderer_impl.hpp"
#include "pipeline/shadow/cascades.hpp"
#include "pipeline/shadow/closed_surface.hpp"
#include "pipeline/shadow/shadow_fit.hpp"
#include "pipeline/shadow/shadow_reach.hpp"
#include "shading/models.hpp"

namespace facet {

using pipeline::DrawRecord;

namespace {

// Whether a draw casts shadows: filled triangles that are not blended (a blended surface lets
// light through; how much, a depth map cannot say), of a material that casts them. Lines and
// points do not.
bool casts_shadow(const DrawRecord& draw) {
  return draw.mesh->topology != Topology::lines && draw.mesh->topology != Topology::points &&
         draw.pipeline.fills_triangles && !pipeline::is_blended(draw.material.alpha_mode) &&
         draw.material.casts_shadows;
}

// Adds the world-space box around a draw's mesh bounds to `box`.
void add_draw_bounds(const DrawRecord& draw, pipeline::WorldBox& box) {
  if (!draw.bounds) return;
  for (int corner = 0; corner < 8; ++corner) {
    box.add(glm::vec3(draw.uniforms.model * draw.bounds->corner(corner)));
  }
}

// World position -> the continuous texel coordinates of a map `size` texels a side seen by
// `light` (texel centres on integers, y down, as setup's to_screen places pixel centres at
// + 0.5) and window depth.
glm::mat4 world_to_map(const Camera& light, int size) {
  const float texels = static_cast<float>(size);
  glm::mat4 to_map(1.0f);  // from NDC
  to_map[0][0] = 0.5f * texels, to_map[3][0] = 0.5f * texels - 0.5f;
  to_map[1][1] = -0.5f * texels, to_map[3][1] = 0.5f * texels - 0.5f;
  to_map[2][2] = 0.5f, to_map[3][2] = 0.5f;
  return to_map * light.view_projection();
}

// What the lit models read of a light's map: the transform from world to the map's texels, and
// the target's depth image (window depths, top row first).
shading::ShadowMap shadow_map_of(const Camera& light, const Framebuffer& target) {
  return shading::make_shadow_map(world_to_map(light, target.width()), target.depth().data(),
                                  target.width(), light.projection_kind == Projection::perspective);
}

// The largest coordinate of `box`'s corners.
float magnitude_of(const pipeline::WorldBox& box) {
  const glm::vec3 m = glm::max(glm::abs(box.low), glm::abs(box.high));
  return std::max({m.x, m.y, m.z});
}

// The reach of each of a sun's `count` maps (shadow_reach.hpp): what `seen` (the views whose
// points look the maps up) see at the view depths that read it (ShadowVisibility): past the
// start of map k - 1's band (its far depth where it has none), up to map k's far depth; the
// first from any depth (a mirror pass sees what lies behind the camera) and the last to any.
// Each widened by the rounding of those depths.
void shadow_reaches(std::span<const Camera> seen, const Camera* maps_views,
                    const shading::ShadowMaps& maps, int count, int size, float magnitude,
                    pipeline::ShadowReach* reaches) {
  constexpr float kAny = std::numeric_limits<float>::infinity();
  for (int k = 0; k < count; ++k) {
    pipeline::LookupDepths depths{maps.eye, maps.forward, 0.0f, 0.0f};
    depths.nearest = k == 0 ? -kAny : maps.blend_from[k - 1];
    depths.farthest = k + 1 == count ? kAny : maps.far_depth[k];
    depths.nearest -= 1e-3f * std::abs(depths.nearest) + 1e-4f * magnitude;
    depths.farthest += 1e-3f * std::abs(depths.farthest) + 1e-4f * magnitude;
    reaches[k] = pipeline::shadow_reach(seen, depths, world_to_map(maps_views[k], size), magnitude);
  }
}

// The views of a light's maps this frame (none: no shadows from it): a spot's one, a sun's
// one per cascade (`cascades` of them), fitted to its slice of the view's depths, each but the
// first from the start of the blend band of the slice before (cascades.hpp). Sets `maps`' far
// depths and blend bands; returns how many maps.
int shadow_views(const Light& light, const Camera& camera, const pipeline::WorldBox& scene,
                 int cascades, int size, Camera* views, shading::ShadowMaps& maps) {
  if (!light.casts_shadows) return 0;
  if (light.type == LightType::spot) {
    const std::optional<Camera> view = pipeline::fit_spot_shadow(
        light.position, light.direction, light.outer_cone_degrees, scene, size);
    if (!view) return 0;
    views[0] = *view, maps.far_depth[0] = camera.far_plane;
    maps.blend_from[0] = camera.far_plane, maps.blend_rate[0] = 0.0f;
    return 1;
  }
  if (light.type != LightType::directional) return 0;  // point lights would need six maps
  const pipeline::ViewDepths depths = pipeline::scene_depths(camera, scene);
  if (!(depths.nearest <= depths.farthest)) return 0;
  float split[shading::kMaxShadowCascades + 1];
  pipeline::cascade_splits(depths, cascades, split);
  int count = 0;
  int slice_of[shading::kMaxShadowCascades];  // the slice each map kept serves
  for (int c = 0; c < cascades; ++c) {
    Camera slice = camera;
    slice.near_plane = c == 0 ? split[0] : pipeline::cascade_blend_start(split, c - 1);
    slice.far_plane = split[c + 1];
    if (!(slice.far_plane > slice.near_plane)) slice.far_plane = camera.far_plane;
    const std::optional<Camera> view =
        pipeline::fit_directional_shadow(slice, light.direction, scene, size);
    if (!view) continue;  // the slice sees nothing of the scene
    views[count] = *view, maps.far_depth[count] = split[c + 1], slice_of[count] = c;
    ++count;
  }
  // A map blends into the next where that serves the next slice (and so holds the band); the
  // last, and one whose next slice saw nothing, have no band.
  for (int k = 0; k < count; ++k) {
    maps.blend_from[k] = maps.far_depth[k], maps.blend_rate[k] = 0.0f;
    if (k + 1 == count || slice_of[k + 1] != slice_of[k] + 1) continue;
    const float from = pipeline::cascade_blend_start(split, slice_of[k]);
    if (!(maps.far_depth[k] > from)) continue;
    maps.blend_from[k] = from, maps.blend_rate[k] = 1.0f / (maps.far_depth[k] - from);
  }
  return count;
}

}  // namespace

void Renderer::Impl::run_shadow_passes() {
  shadow_ms = 0.0;
  shadows_ready = false;
  if (!frame_shadows) return;
  const auto start = pipeline::Clock::now();
  shadows.resize(std::max(shadows.size(), lighting.lights.size()));
  for (LightShadow& shadow : shadows) shadow.maps.count = 0;

  // The box every draw lies in: receivers across the light, casters along it.
  pipeline::WorldBox scene;
  for (const DrawRecord& draw : frame.draws) add_draw_bounds(draw, scene);
  for (const DrawRecord& draw : outside_view_draws) add_draw_bounds(draw, scene);

  // What the passes change, put back afterwards: the color pass's draws, camera and settings.
  const Camera color_camera = camera;
  const RenderSettings color_settings = settings;
  const glm::mat4 color_view_projection = frame.view_projection;
  const FogMode color_fog = lighting.fog.mode;
  const bool color_background = lighting.environment.show_as_background;
  const bool color_environment_light = lighting.environment.image_based_lighting;
  // Where every lookup is at a point a view sees, a sun's maps need only the casters within
  // their reach. Not so for models that look shadows up at their vertices, wherever those lie.
  // Under MSAA a pixel is shaded at its centre, on the plane of a triangle that may not cover it,
  // at any depth along the pixel's ray: within the view's frustum still where that depth picks
  // neither the first map (nearer than the view, or behind the eye) nor the last.
  static_assert(pipeline::ShadowReach::kMaxViews >= 1 + RenderSettings::kMaxMirrorPlanes);
  Camera seen[pipeline::ShadowReach::kMaxViews];
  seen[0] = color_camera;
  const int seen_count = 1 + mirror_views(seen + 1);
  const auto lights_vertices = [](const DrawRecord& draw) { return draw.pipeline.lights_vertices; };
  const bool lookups_seen =
      std::none_of(frame.draws.begin(), frame.draws.end(), lights_vertices) &&
      std::none_of(outside_view_draws.begin(), outside_view_draws.end(), lights_vertices);
  const bool centres_covered = color_settings.msaa == 1;
  shadow_casters.clear();
  for (const std::vector<DrawRecord>* draws : {&frame.draws, &outside_view_draws}) {
    for (const DrawRecord& draw : *draws) {
      if (!casts_shadow(draw)) continue;
      shadow_casters.push_back(draw);
      DrawRecord& caster = shadow_casters.back();
      caster.material.cull = shadow_cull(draw);
      if (caster.material.alpha_mode == AlphaMode::mask) {
        // The unlit model, whose alpha (of the base color map) cuts out as in color.
        caster.pipeline = pipeline::make_pipeline<shading::UnlitShading, AlphaMode::mask>();
        caster.material.emissive_map = {};
      } else {
        pipeline::draw_depth_alone(caster);
      }
    }
  }
  std::swap(frame.draws, set_aside_draws);
  // The color pass's state is put back however the passes end: one that throws (too many
  // primitives, memory) leaves the renderer as it was for the next frame.
  const ScopeExit restore{[&] {
    depth_only_pass = false;
    map_reach = nullptr;
    map_clear_tiles = nullptr;
    std::swap(frame.draws, set_aside_draws);
    camera = color_camera;
    settings = color_settings;
    frame.view_projection = color_view_projection;
    lighting.fog.mode = color_fog;
    lighting.environment.show_as_background = color_background;
    lighting.environment.image_based_lighting = color_environment_light;
  }};
  settings.msaa = 1;
  settings.exposure = 0.0f;
  settings.tone_mapping = ToneMapping::none;
  settings.debug_view = DebugView::none;
  lighting.fog.mode = FogMode::none;
  lighting.environment.show_as_background = false;
  lighting.environment.image_based_lighting = false;
  depth_only_pass = true;
  const int size = settings.shadow_map_size;
  const int cascades = color_settings.shadow_cascades == RenderSettings::kAutoShadowCascades
                           ? pipeline::automatic_cascade_count(color_camera, scene)
                           : color_settings.shadow_cascades;
  for (std::size_t i = 0; i < lighting.lights.size(); ++i) {
    Camera views[shading::kMaxShadowCascades];
    LightShadow& shadow = shadows[i];
    const int count =
        shadow_views(lighting.lights[i], color_camera, scene, cascades, size, views, shadow.maps);
    shadow.maps.eye = color_camera.eye;
    shadow.maps.forward = color_camera.forward();
    pipeline::ShadowReach reaches[shading::kMaxShadowCascades];
    const bool sun_reaches = lookups_seen && lighting.lights[i].type == LightType::directional;
    if (sun_reaches) {
      shadow_reaches(std::span(seen, seen_count), views, shadow.maps, count, size,
                     magnitude_of(scene), reaches);
    }
    for (int c = 0; c < count; ++c) {
      const bool reached = sun_reaches && (centres_covered || (c > 0 && c + 1 < count));
      std::optional<Framebuffer>& target = shadow.targets[c];
      ClearTiles& clear_tiles = shadow.clear_tiles[c];
      if (!target || target->width() != size) {
        target = Framebuffer::depth_only(size, size);
        clear_tiles.forget();
      }
      camera = views[c];
      frame.view_projection = views[c].view_projection();
      // Each pass draws the casters its view takes in, as recording does for the camera's.
      frame.draws.clear();
      for (const DrawRecord& caster : shadow_casters) {
        const glm::mat4 model_view_projection = frame.view_projection * caster.uniforms.model;
        if (caster.bounds &&
            (pipeline::box_outside_frustum(*caster.bounds, model_view_projection) ||
             (reached &&
              pipeline::box_outside_reach(reaches[c], caster.bounds->low, caster.bounds->high,
                                          caster.uniforms.model)))) {
          continue;
        }
        frame.draws.push_back(caster);
        frame.draws.back().uniforms.model_view_projection = model_view_projection;
      }
      map_reach = reached ? &reaches[c] : nullptr;
      map_clear_tiles = &clear_tiles;
      run(*target);
      shadow.maps.maps[c] = shadow_map_of(views[c], *target);
    }
    shadow.maps.count = count;
  }
  shadows_ready = true;
  shadow_ms = pipeline::ms_since(start);
}

CullMode Renderer::Impl::shadow_cull(const DrawRecord& draw) {
  // Open meshes cast from either side. So does a cut-out: its holes show the inner side.
  if (draw.material.alpha_mode != AlphaMode::opaque) return CullMode::none;
  const auto entry = checked_meshes.find(draw.mesh);
  if (entry == checked_meshes.end()) return CullMode::none;
  std::optional<pipeline::Closure>& closure = entry->second.closure;
  if (!closure) closure = pipeline::closed_surface(*draw.mesh);
  if (*closure == pipeline::Closure::open) return CullMode::none;
  // A mirroring transform turns the winding, and so which faces face out, around.
  const bool mirrored = glm::determinant(glm::mat3(draw.uniforms.model)) < 0.0f;
  const bool fronts_out = (*closure == pipeline::Closure::fronts_out) != mirrored;
  return fronts_out ? CullMode::back : CullMode::front;
}

}  // namespace facet
