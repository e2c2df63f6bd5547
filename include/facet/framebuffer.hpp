// Framebuffer: the render target — a color image (RGBA8 sRGB or RGBA32F linear), unless asked
// not to keep one a 32-bit float depth image of the same size, and the extra outputs asked for
// (ExtraOutputs: exact depths, normals, ids, barycentrics, albedo); from 1x1 up to 8192x8192.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

namespace facet {

struct ClearTiles;  // the renderer's record of a target's cleared tiles

enum class ColorFormat {
  rgba8_srgb,  // 8 bits per channel, sRGB-encoded color, linear alpha
  rgba32f,     // linear float
};

// Whether the renderer copies its depth out into the framebuffer. Depth is tested either way
// (in the renderer's own tile buffers); a color-only job (a PNG, a window) saves the copy, a
// sizeable share of a simple frame's time.
enum class DepthImage { keep, none };

// The space of the normals output.
enum class NormalSpace {
  none,    // no normals output
  world,   // world space
  camera,  // the camera's view space: x right, y up, z toward the viewer (OpenGL's)
};

// Images a frame can produce besides color and window depth. Each holds the exact value the
// pixel computed (a float output stores the float, never a color squeezed through 8 bits), and
// only what is asked for costs anything: each group of outputs is one more pass over the
// frame's draws (Renderer::finish; pipeline/output_passes.cpp). In these passes blended draws
// count as opaque, cut-out (masked) draws are cut out as in color, and lines (line meshes,
// wireframes) are not drawn. Where nothing was drawn every output holds 0.
struct ExtraOutputs {
  // Distance along the camera's view axis, in scene units (what Camera::view_distance gives
  // from window depth, computed here per pixel instead).
  bool view_depth = false;
  // Distance from the eye along the pixel's ray, in scene units (for an orthographic camera,
  // from the image plane: the same as view_depth).
  bool ray_distance = false;
  NormalSpace normals = NormalSpace::none;  // unit shading normals (before normal maps)
  bool instance_ids = false;                // the draw's instance id (Renderer::set_instance_id)
  // The triangle's index in its mesh plus 1 (a strip's triangles counted along it), the
  // convention of nvdiffrast: 0 is the background.
  bool triangle_ids = false;
  // Perspective-correct barycentric coordinates of the pixel centre in its triangle: the
  // weights of the triangle's first, second and third vertex, summing to 1 (a strip's odd
  // triangles have their first two vertices swapped, as drawn).
  bool barycentrics = false;
  bool albedo = false;  // linear RGBA: base color x vertex color x base color map, unlit

  bool any() const {
    return view_depth || ray_distance || normals != NormalSpace::none || instance_ids ||
           triangle_ids || barycentrics || albedo;
  }
};

class Framebuffer {
 public:
  static constexpr int kMaxSize = 8192;

  // Throws facet::Error if a size is outside [1, kMaxSize].
  Framebuffer(int width, int height, ColorFormat format = ColorFormat::rgba8_srgb,
              DepthImage depth = DepthImage::keep, const ExtraOutputs& extra = {});
  // Window depth alone, no color image (rgba8() and rgba32f() empty, has_color() false): what
  // depth-only passes draw into (the shadow maps; a RenderTexture whose options keep no color).
  // Renderer::finish(Framebuffer&), GlRenderer::render, pixel(), images written from it and
  // overlays drawn onto it throw facet::Error. Throws facet::Error if a size is outside [1,
  // kMaxSize].
  static Framebuffer depth_only(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  ColorFormat format() const { return format_; }
  bool has_color() const {
    return format_ == ColorFormat::rgba8_srgb ? !rgba8_.empty() : !rgba32f_.empty();
  }

  // Row-major, top row first, 4 values per pixel. Only the one matching format() is non-empty
  // (neither, for depth_only()).
  std::vector<std::uint8_t>& rgba8() {
    forget_cleared_tiles();
    return rgba8_;
  }
  const std::vector<std::uint8_t>& rgba8() const { return rgba8_; }
  std::vector<float>& rgba32f() {
    forget_cleared_tiles();
    return rgba32f_;
  }
  const std::vector<float>& rgba32f() const { return rgba32f_; }
  // Window depth per pixel, row-major, top row first; empty for DepthImage::none. 0 is the
  // camera's near plane and 1 its far plane (OpenGL's glDepthRange(0, 1)), not linear in
  // distance: Camera::view_distance turns it into scene units. 1 where nothing was drawn.
  std::vector<float>& depth() {
    forget_cleared_tiles();
    return depth_;
  }
  const std::vector<float>& depth() const { return depth_; }
  bool has_depth() const { return !depth_.empty(); }

  // For a framebuffer rendered into frame after frame that nothing else writes (a viewer's, a
  // benchmark's): with keep true, each frame leaves alone the tiles that an earlier frame
  // cleared and that get nothing drawn again, instead of clearing them again. The non-const
  // rgba8(), rgba32f() and depth() forget which tiles those are, since you may write through
  // them: write the images only through such a call made after the last render, never through
  // a reference or pointer kept from before it. Off by default; a copy knows no tiles.
  void keep_cleared_tiles(bool keep);
  bool keeps_cleared_tiles() const { return cleared_tiles_.tiles != nullptr; }

  // The extra outputs asked for when the framebuffer was made; each image below is empty
  // unless asked for. Row-major, top row first, the count of values per pixel given.
  const ExtraOutputs& extra_outputs() const { return extra_; }
  std::vector<float>& view_depth() { return view_depth_; }  // 1
  const std::vector<float>& view_depth() const { return view_depth_; }
  std::vector<float>& ray_distance() { return ray_distance_; }  // 1
  const std::vector<float>& ray_distance() const { return ray_distance_; }
  std::vector<float>& normals() { return normals_; }  // 3: x, y, z
  const std::vector<float>& normals() const { return normals_; }
  std::vector<std::uint32_t>& instance_ids() { return instance_ids_; }  // 1
  const std::vector<std::uint32_t>& instance_ids() const { return instance_ids_; }
  std::vector<std::uint32_t>& triangle_ids() { return triangle_ids_; }  // 1
  const std::vector<std::uint32_t>& triangle_ids() const { return triangle_ids_; }
  std::vector<float>& barycentrics() { return barycentrics_; }  // 3
  const std::vector<float>& barycentrics() const { return barycentrics_; }
  std::vector<float>& albedo() { return albedo_; }  // 4: linear RGBA
  const std::vector<float>& albedo() const { return albedo_; }

  // Linear color of one pixel, whatever the format (sRGB decoded). Throws facet::Error if
  // (x, y) is outside the image or there is no color image (depth_only()).
  glm::vec4 pixel(int x, int y) const;
  // Depth of one pixel. Throws facet::Error if (x, y) is outside the image or there is no
  // depth image (DepthImage::none).
  float depth_at(int x, int y) const;

 private:
  friend class Renderer;  // renders with the cleared tiles taken out, then hands them back
  // The record of keep_cleared_tiles(), or null; a copy gets an empty record.
  struct KeptTiles {
    std::unique_ptr<ClearTiles> tiles;
    KeptTiles();
    KeptTiles(const KeptTiles& other);
    KeptTiles(KeptTiles&& other) noexcept;
    KeptTiles& operator=(const KeptTiles& other);
    KeptTiles& operator=(KeptTiles&& other) noexcept;
    ~KeptTiles();
  };
  void forget_cleared_tiles() {
    if (cleared_tiles_.tiles) forget_kept_tiles();
  }
  void forget_kept_tiles();

  KeptTiles cleared_tiles_;
  int width_;
  int height_;
  ColorFormat format_;
  std::vector<std::uint8_t> rgba8_;
  std::vector<float> rgba32f_;
  std::vector<float> depth_;
  ExtraOutputs extra_;
  std::vector<float> view_depth_, ray_distance_, normals_, barycentrics_, albedo_;
  std::vector<std::uint32_t> instance_ids_, triangle_ids_;

  enum class ColorImage { keep, none };
  Framebuffer(int width, int height, ColorFormat format, ColorImage color, DepthImage depth,
              const ExtraOutputs& extra);
  // Index of pixel (x, y); throws facet::Error naming `what` if it is outside the image.
  std::size_t checked_index(int x, int y, const char* what) const;
};

}  // namespace facet
