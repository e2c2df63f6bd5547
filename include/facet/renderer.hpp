// Renderer: records draws for one frame, then runs the tiled pipeline
// (geometry -> binning -> raster + shade per tile -> resolve) into a Framebuffer.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <memory>

#include "facet/camera.hpp"
#include "facet/color.hpp"
#include "facet/framebuffer.hpp"
#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/render_texture.hpp"

namespace facet {

// Debug views that replace the shaded image with what the pipeline did (see
// src/pipeline/output/debug_view.cpp). Shading-model views (depth, normals, wireframe) are
// materials instead: ShadingModel.
enum class DebugView {
  none,       // the shaded image
  overdraw,   // heat map of how many triangles covered each pixel (no depth test, no culling
              // beyond the material's): black 0, blue 1, green 2, yellow 4, red 8, white 16+
  tile_bins,  // the shaded image, each tile tinted by how many primitives were binned into
              // it (same ramp: 1, 10, 100, 1000, 10000+) and outlined
};

struct RenderSettings {
  // Each worker thread has its own tile buffers and an OS thread: more than this is a mistake
  // (a typo), not a machine.
  static constexpr int kMaxThreads = 256;
  int threads = 0;  // worker threads; 0 = all cores
  // Tile edge in pixels: 16, 32, 64 or 128, or kAutoTileSize (the default) to choose it each
  // frame: 128 where the tiles hold 8-bit codes (a frame of display values at one sample:
  // docs/pipeline.md, "Binning"), else 64. Images are the same bits at every size.
  static constexpr int kAutoTileSize = 0;
  int tile_size = kAutoTileSize;
  glm::vec4 clear_color{0.0f, 0.0f, 0.0f, 1.0f};  // linear RGBA
  float exposure = 0.0f;  // in stops: colors are scaled by 2^exposure before output
  ToneMapping tone_mapping = ToneMapping::none;
  DebugView debug_view = DebugView::none;
  // Multisample anti-aliasing: samples per pixel, 1 (off), 2, 4, 8 or 16, at the D3D11 / OpenGL
  // standard sample positions. Coverage and depth are per sample, shading once per pixel per
  // triangle (at the pixel centre), and the samples are averaged in linear light before the sRGB
  // encode. The depth image takes sample 0's depth; the extra outputs (ids, normals, view depth,
  // ...) are rendered without multisampling, so each pixel holds the pixel centre's winner,
  // never a blend. Cut-out (alpha-mask) materials use alpha to coverage. Lines are one pixel
  // wide rectangles whose samples average (anti-aliased); points cover every sample of their
  // pixels. Debug views render with 1 sample. docs/pipeline.md,
  // "Anti-aliasing".
  int msaa = 1;
  // Shadow maps: each directional or spot light with Light::casts_shadows casts shadows when
  // this is on (point lights do not). Before the color pass, a depth pass from each such light
  // (orthographic along a directional light, fitted to what the camera sees; perspective over a
  // spot's cone) renders every triangle draw but the blended ones into a square map of
  // shadow_map_size texels a side (kMinShadowMapSize to Framebuffer::kMaxSize), through the
  // same tiled pipeline; the lit models (Lambert, Phong, Blinn-Phong and PBR per pixel, Gouraud
  // per vertex; not flat) scale the light by the share of a filtered 4x4-texel footprint that
  // sees it. docs/pipeline.md, "Shadows".
  bool shadows = false;
  static constexpr int kMinShadowMapSize = 16;
  int shadow_map_size = 2048;
  // A directional light's maps: 1, or up to kMaxShadowCascades maps, each fitted to a slice of
  // the view's depths (nearer slices thinner), for views whose depths span too much for one
  // map's texels to be small near the camera (a world seen from the ground). Each is a pass.
  // Where two slices meet, a band of the nearer one blends into the farther map, so no seam
  // shows. kAutoShadowCascades (the default) chooses the count each frame from the view: 1 for
  // a model seen whole, more as the depths the camera sees of the scene span more (up to 4 over
  // a world seen from the ground); docs/pipeline.md, "Shadows".
  static constexpr int kMaxShadowCascades = 4;
  static constexpr int kAutoShadowCascades = 0;
  int shadow_cascades = kAutoShadowCascades;
  // Planar reflections: before the color pass, for each plane (up to kMaxMirrorPlanes) that
  // flat draws of Material::reflects_scene lie in and the camera sees from the front, a pass
  // draws the scene mirrored through it, cut at the plane, at reflection_scale of the frame's
  // width and height (in (0, 1]), one sample a pixel, into a float texture whose mip chain
  // blurs it for rough surfaces. Off: those materials reflect the environment alone.
  // docs/pipeline.md, "Reflections".
  bool reflections = true;
  static constexpr int kMaxMirrorPlanes = 4;
  float reflection_scale = 0.5f;
};

struct FrameStats {
  // Primitives submitted: triangles, line segments and points (a line or point mesh's
  // Mesh::primitive_count()), so this is a count of primitives, not only of triangles.
  std::uint64_t triangles_in = 0;
  std::uint64_t culled = 0;        // rejected: outside the frustum, back/front-facing, degenerate
  std::uint64_t clipped = 0;       // needed clipping against a plane
  std::uint64_t drawn = 0;         // triangles set up and binned (after clipping)
  std::uint64_t lines_drawn = 0;   // line segments set up and binned: line meshes, wireframes
  std::uint64_t points_drawn = 0;  // points set up and binned (Topology::points meshes)
  // Pixels the shading model ran for, a measure of work rather than of the image: the pixels
  // of small triangles of one draw are shaded together, each having passed the depth test as
  // the tile was before the others, so a pixel that a later triangle of the batch covers
  // nearer is shaded too (and then not written). It changes with how many pixels wait
  // together, never the image.
  std::uint64_t pixels_shaded = 0;
  double ms_geometry = 0;  // vertex transform, clip, cull, setup
  double ms_binning = 0;
  double ms_raster = 0;  // raster + shade + resolve, per tile
  // The part of ms_raster spent resolving tiles to the framebuffer (the tile tasks' measured
  // resolve time as a share of their whole time, applied to ms_raster).
  double ms_resolve = 0;
  double ms_total = 0;
  // The passes of the extra outputs asked for (ExtraOutputs), included in ms_total; the
  // counts above are the color pass's.
  double ms_extra_outputs = 0;
  // The shadow maps' depth passes (RenderSettings::shadows), included in ms_total; the counts
  // above are the color pass's.
  double ms_shadows = 0;
  // The planar reflections' passes (RenderSettings::reflections), included in ms_total.
  double ms_reflections = 0;
  // Every color was a display value, an 8-bit code (as the normals, depth and texcoords
  // models write): resolve rounded them to bytes instead of sRGB-encoding them, with the same
  // result.
  bool display_referred = false;
  int tile_size = 0;  // the color pass's tile edge in pixels (RenderSettings::tile_size)
};

class Renderer {
 public:
  // Throws facet::Error for invalid settings (negative threads, unsupported tile size or
  // sample count, a shadow map size outside [kMinShadowMapSize, Framebuffer::kMaxSize], shadow
  // cascades neither kAutoShadowCascades nor in [1, kMaxShadowCascades]).
  explicit Renderer(const RenderSettings& settings = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const RenderSettings& settings() const;

  // Starts recording a frame seen from camera under lighting (default: Lighting{}, one sun).
  void begin_frame(const Camera& camera, const Lighting& lighting);
  void begin_frame(const Camera& camera);
  // The camera of the frame being recorded: the last begin_frame()'s (before the first, a
  // default Camera).
  const Camera& camera() const;
  // Records a draw. The mesh is referenced, not copied: it must live until finish(). Throws
  // facet::Error for a mesh that Mesh::validate() rejects.
  void draw(const Mesh& mesh, const Material& material, const glm::mat4& transform = glm::mat4(1));
  // A temporary mesh would be gone before finish() reads it: draw a named mesh, or hand the
  // renderer a shared pointer (below), which it keeps alive.
  void draw(Mesh&& mesh, const Material& material,
            const glm::mat4& transform = glm::mat4(1)) = delete;
  // The same for a mesh that does not change, as a Scene's: it is checked and its bounds found
  // the first time it is drawn, not in every frame. The renderer holds on to the mesh until a
  // frame after the last that drew it. To change the mesh, draw a new one in its place.
  void draw(const std::shared_ptr<const Mesh>& mesh, const Material& material,
            const glm::mat4& transform = glm::mat4(1));
  // The instance id of the draws recorded from now on in this frame, which the instance ids
  // output shows (ExtraOutputs). Before any call in a frame, a draw's id is its number among
  // the frame's draw() calls: 1, 2, ... (0 is the background). draw_scene sets each node's.
  void set_instance_id(std::uint32_t id);
  // Runs the pipeline for everything recorded since begin_frame() into target, then one pass
  // for each group of the extra outputs target asks for (Framebuffer's ExtraOutputs). Throws
  // facet::Error when triangle ids are asked of a mesh of 2^24 triangles or more, whose ids a
  // float pass cannot hold exactly, and for a target without a color image
  // (Framebuffer::depth_only: depth alone is rendered into a RenderTexture keeping no color).
  void finish(Framebuffer& target);
  // The same into an offscreen target, whose textures then hold the image (RenderTexture). A
  // frame cannot sample what it renders into: throws facet::Error, rendering nothing, when a
  // recorded draw's material or the environment uses one of target's textures.
  void finish(RenderTexture& target);

  const FrameStats& stats() const;

 private:
  friend struct RendererAccess;  // internal: tests record draws with their own shading models
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facet
