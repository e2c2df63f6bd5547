// The planar reflections' passes (RenderSettings::reflections): after the shadow maps and before
// the color pass, the frame's draws run once more per mirror plane, seen by the camera mirrored
// through the plane (mirror.hpp) and cut at it, into a float render texture whose mip chain then
// blurs it for rough surfaces: the same tiled pipeline, so the reflections, and the images, are
// the same for any thread count, tile size and SIMD target. The mirror draws' Phong and PBR
// kernels then read them (shading/planar_reflection-inl.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/scope_exit.hpp"
#include "facet/color.hpp"
#include "pipeline/record/draw_culling.hpp"
#include "pipeline/reflection/mirror.hpp"
#include "pipeline/renderer_impl.hpp"

namespace facet {

using pipeline::DrawRecord;

namespace {

// The blur of a surface of roughness alpha spans about alpha times this share of the image's
// height (PlanarReflection::blur_texels).
constexpr float kBlurShare = 0.05f;

// Whether a draw's model reads a planar reflection (shade_batch.cpp, pbr_batch-inl.h).
bool reads_reflection(const DrawRecord& draw) {
  const Material& m = draw.material;
  if (!m.reflects_scene) return false;
  if (m.shading == ShadingModel::pbr) return true;
  return (m.shading == ShadingModel::phong || m.shading == ShadingModel::blinn_phong) &&
         m.reflectivity > 0.0f;
}

// A mirror draw's plane as the eye sees it (mirror.hpp).
std::optional<glm::vec4> own_plane(const DrawRecord& draw, glm::vec3 eye) {
  return pipeline::mirror_plane(*draw.mesh, draw.uniforms.model, eye, draw.material.cull);
}

// Whether a draw is a mirror on `plane` (as the eye sees it).
bool mirror_on_plane(const DrawRecord& draw, const glm::vec4& plane, glm::vec3 eye) {
  if (!reads_reflection(draw)) return false;
  const std::optional<glm::vec4> own = own_plane(draw, eye);
  return own && pipeline::same_plane(*own, plane);
}

// Whether every corner of a draw's bounds lies behind the plane (a pass cuts it away whole).
bool behind_plane(const DrawRecord& draw, const glm::vec4& plane) {
  if (!draw.bounds) return false;
  for (int corner = 0; corner < 8; ++corner) {
    // The plane as a row vector: plane . (model corner).
    if (!(glm::dot(plane, draw.uniforms.model * draw.bounds->corner(corner)) < 0.0f)) return false;
  }
  return true;
}

// A cropped pass's pixels are those of the full pass (the mirrored camera's whole view at the
// reflection scale) in a rectangle whose edges lie on whole blocks of this many pixels (or on
// the full pass's edges), and whose sides are whole steps of an eighth of the full pass's (so
// its target is made anew only when the mirrors' extent crosses a step): its texels sit where
// the full pass's would. Both depend on this frame's view alone, never on earlier frames.
constexpr int kBlock = 32;
constexpr int kSizeSteps = 8;

// Pixels [low, high) of the full pass along one axis.
struct Span {
  int low, high;
  int size() const { return high - low; }
};

// The span of NDC [from, to] widened by `margin` pixels, out to whole blocks, then to a whole
// step (within the full pass's `full` pixels).
Span span_of(float from, float to, int full, float margin) {
  const float scale = 0.5f * static_cast<float>(full);
  Span span{static_cast<int>(std::floor(((from + 1.0f) * scale - margin) / kBlock)) * kBlock,
            static_cast<int>(std::ceil(((to + 1.0f) * scale + margin) / kBlock)) * kBlock};
  span.low = std::clamp(span.low, 0, full), span.high = std::clamp(span.high, 0, full);
  const int step = (full / kSizeSteps + kBlock - 1) / kBlock * kBlock;
  const int size = std::min(full, (span.size() + step - 1) / step * step);
  span.high = span.low + size;
  if (span.high > full) span.low -= span.high - full, span.high = full;
  return span;
}

// A pass's view and size: `full` (the mirrored camera) cropped to where the mirrors on plane m
// are seen, widened by `margin` pixels of the full pass (the blur's reach); none when no mirror
// is seen.
struct PassView {
  Camera camera;
  int width, height;
};
std::optional<PassView> pass_view(const Camera& full, const std::vector<DrawRecord>& draws,
                                  const std::vector<int>& mirror_of_draw, int m, int full_width,
                                  int full_height, float margin) {
  const glm::mat4 view_projection = full.view_projection();
  pipeline::NdcRect seen;
  for (std::size_t d = 0; d < draws.size(); ++d) {
    if (mirror_of_draw[d] != m) continue;
    if (!draws[d].bounds) return PassView{full, full_width, full_height};
    pipeline::add_seen_box(*draws[d].bounds, view_projection * draws[d].uniforms.model, seen);
  }
  if (seen.empty()) return std::nullopt;
  const Span x = span_of(seen.low.x, seen.high.x, full_width, margin);
  const Span y = span_of(seen.low.y, seen.high.y, full_height, margin);
  if (x.size() <= 0 || y.size() <= 0) return std::nullopt;
  pipeline::NdcRect rect;
  rect.low = {2.0f * static_cast<float>(x.low) / static_cast<float>(full_width) - 1.0f,
              2.0f * static_cast<float>(y.low) / static_cast<float>(full_height) - 1.0f};
  rect.high = {2.0f * static_cast<float>(x.high) / static_cast<float>(full_width) - 1.0f,
               2.0f * static_cast<float>(y.high) / static_cast<float>(full_height) - 1.0f};
  return PassView{pipeline::cropped_camera(full, rect), x.size(), y.size()};
}

// Sorts the draws that read a planar reflection by their plane: mirror_of_draw[d] is draw d's
// plane's index in `planes` (-1: none, or beyond the kMaxMirrorPlanes first); returns how many.
int find_mirror_planes(const std::vector<DrawRecord>& draws, glm::vec3 eye,
                       std::vector<int>& mirror_of_draw, glm::vec4* planes) {
  int count = 0;
  mirror_of_draw.assign(draws.size(), -1);
  for (std::size_t d = 0; d < draws.size(); ++d) {
    if (!reads_reflection(draws[d])) continue;
    const std::optional<glm::vec4> plane = own_plane(draws[d], eye);
    if (!plane) continue;
    int m = 0;
    while (m < count && !pipeline::same_plane(planes[m], *plane)) ++m;
    if (m == count) {
      if (count == RenderSettings::kMaxMirrorPlanes) continue;  // the environment's
      planes[count++] = *plane;
    }
    mirror_of_draw[d] = m;
  }
  return count;
}

}  // namespace

void Renderer::Impl::select_mirrored_draws(int m, glm::vec3 eye) {
  const glm::vec4& plane = mirrors[m].plane;
  const glm::mat4 view = camera.view();
  frame.draws.clear();
  // What the pass's view takes in in front of the plane, but not the mirrors on it.
  for (const std::vector<DrawRecord>* draws : {&set_aside_draws, &outside_view_draws}) {
    for (std::size_t d = 0; d < draws->size(); ++d) {
      const DrawRecord& draw = (*draws)[d];
      const bool is_mirror =
          draws == &set_aside_draws ? mirror_of_draw[d] == m : mirror_on_plane(draw, plane, eye);
      if (is_mirror || behind_plane(draw, plane)) continue;
      const glm::mat4 model_view_projection = frame.view_projection * draw.uniforms.model;
      if (draw.bounds && pipeline::box_outside_frustum(*draw.bounds, model_view_projection)) {
        continue;
      }
      frame.draws.push_back(draw);
      DrawRecord& mirrored = frame.draws.back();
      mirrored.uniforms.model_view_projection = model_view_projection;
      mirrored.uniforms.reflection = nullptr;  // another plane's mirror shows the environment
      if (pipeline::is_blended(draw.material.alpha_mode) && draw.bounds) {
        mirrored.view_depth = -(view * draw.uniforms.model * draw.bounds->centre()).z;
      }
    }
  }
}

int Renderer::Impl::mirror_views(Camera* views) {
  if (!frame_reflections) return 0;
  glm::vec4 planes[RenderSettings::kMaxMirrorPlanes];
  const int count = find_mirror_planes(frame.draws, camera.shading_eye(), mirror_of_draw, planes);
  for (int m = 0; m < count; ++m) views[m] = pipeline::mirrored_camera(camera, planes[m]);
  return count;
}

void Renderer::Impl::run_reflection_passes(const Framebuffer& target) {
  reflection_ms = 0.0;
  mirror_count = 0;
  if (!frame_reflections) return;
  const auto start = pipeline::Clock::now();
  const glm::vec3 eye = camera.shading_eye();
  glm::vec4 planes[RenderSettings::kMaxMirrorPlanes];
  mirror_count = find_mirror_planes(frame.draws, eye, mirror_of_draw, planes);
  if (mirror_count == 0) return;

  // What the passes change, put back afterwards: the color pass's draws, camera, settings and
  // fog color.
  const Camera color_camera = camera;
  const RenderSettings color_settings = settings;
  const glm::mat4 color_view_projection = frame.view_projection;
  const glm::vec3 color_fog = lighting.fog.color;
  std::swap(frame.draws, set_aside_draws);
  const ScopeExit restore{[&] {
    std::swap(frame.draws, set_aside_draws);
    camera = color_camera;
    settings = color_settings;
    frame.view_projection = color_view_projection;
    frame.clip_plane.reset();
    lighting.fog.color = color_fog;
    linear_pass = false;
  }};
  // The passes hold light (no display values), with no exposure and no tone curve: the color
  // pass applies both to what the mirrors show. Their fog fades to the color pass's fog color.
  linear_pass = true;
  settings.msaa = 1;
  settings.exposure = 0.0f;
  settings.tone_mapping = ToneMapping::none;
  lighting.fog.color =
      fog_color_under(color_settings.tone_mapping, color_fog, std::exp2(color_settings.exposure));
  const int full_width =
      std::max(1, static_cast<int>(std::lround(target.width() * color_settings.reflection_scale)));
  const int full_height =
      std::max(1, static_cast<int>(std::lround(target.height() * color_settings.reflection_scale)));
  const float blur_texels = kBlurShare * static_cast<float>(full_height);
  for (int m = 0; m < mirror_count; ++m) {
    MirrorPass& mirror = mirrors[m];
    mirror.plane = planes[m];
    mirror.seen = false;
    const std::optional<PassView> pass =
        pass_view(pipeline::mirrored_camera(color_camera, mirror.plane), set_aside_draws,
                  mirror_of_draw, m, full_width, full_height, blur_texels + 2.0f);
    if (!pass) continue;
    camera = pass->camera;
    frame.view_projection = camera.view_projection();
    frame.clip_plane = pipeline::clip_space_plane(frame.view_projection, mirror.plane);
    select_mirrored_draws(m, eye);
    if (!mirror.target || mirror.target->width() != pass->width ||
        mirror.target->height() != pass->height) {
      RenderTextureOptions options;
      options.format = ColorFormat::rgba32f;
      options.mipmaps = true;
      mirror.target.emplace(pass->width, pass->height, options);
    }
    run(mirror.target->framebuffer());
    mirror.target->update();
    mirror.reflection.image = mirror.target->texture().get();
    mirror.reflection.world_to_image = pipeline::mirror_image_transform(camera);
    mirror.reflection.blur_texels = blur_texels;
    mirror.seen = true;
  }
  // The color pass's mirror draws read their plane's pass.
  for (std::size_t d = 0; d < set_aside_draws.size(); ++d) {
    const int m = mirror_of_draw[d];
    set_aside_draws[d].uniforms.reflection =
        m >= 0 && mirrors[m].seen ? &mirrors[m].reflection : nullptr;
  }
  reflection_ms = pipeline::ms_since(start);
}

}  // namespace facet
