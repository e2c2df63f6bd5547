// Stage: output. Clears a tile's local buffers (lazily: the framebuffer is never read) and
// resolves the finished tile into the framebuffer once, converting to the target format.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

#include "core/srgb_row.hpp"
#include "facet/framebuffer.hpp"
#include "facet/light.hpp"
#include "facet/renderer.hpp"
#include "pipeline/raster/raster.hpp"

namespace facet::pipeline {

// What a pixel shows where nothing is drawn: the clear color, or the environment (image or
// sky gradient) seen through that pixel.
struct Background {
  glm::vec4 clear_color{0.0f};
  // The tiles hold display values (frame_run.cpp's display_referred_frame): clear_color is one
  // (display_value_of), and resolve_tile rounds instead of encoding.
  bool display_referred = false;
  std::uint32_t clear_codes = 0;  // then clear_color's codes, for tiles of codes (display_codes)
  const Environment* environment = nullptr;  // non-null: draw the environment
  glm::mat4 inverse_view_projection{1.0f};
  glm::vec3 eye{0.0f};
  int width = 1, height = 1;  // framebuffer size
  // A depth-only pass (a shadow map's): only the tiles' depth is written out (resolve_depth_tile);
  // their color is neither cleared nor resolved, since nothing reads it.
  bool depth_only = false;
};

// How resolve turns a tile's linear colors into the target's.
struct Resolve {
  float scale = 1.0f;  // the exposure, 2^stops
  // The tiles hold display values (Background::display_referred): rounded, never mapped.
  bool display_referred = false;
  ToneMapping tone_mapping = ToneMapping::none;
  // The background is the environment, mapped as what is drawn is; else only the pixels drawn
  // (their depth no longer the clear depth) are mapped, never the clear color.
  bool maps_background = false;
  // The linear color an undrawn pixel brings to the encode (the clear color, scaled and never
  // mapped when tone mapped) and its codes, when the background is that plain color and the
  // target 8-bit sRGB: its pixels take the codes without being encoded again.
  std::optional<shading::KnownCodes> background;
};

// The depth a tile starts at: the far plane.
inline constexpr float kClearDepth = 1.0f;

// Clears depth to the far plane and color to the clear color, unless color_hidden (the first
// triangle drawn writes every pixel: occlusion.hpp's hides_clear). An environment background
// is not drawn here but by fill_background, later, into the pixels nothing covered.
void clear_tile(TileContext& tile, const Background& background, bool color_hidden);
// Draws the environment into the pixels whose depth is still the clear depth. Exact once
// drawing has only run opaque, depth-writing triangles, which write color exactly where they
// write depth (render_tile calls it before anything else, and at the end): most of the sky
// behind a scene then costs nothing.
void fill_background(TileContext& tile, const Background& background);
// A linear color as the display value a display-referred tile holds for it: its sRGB codes
// (the frame's encode kernel) / 255; alpha is never encoded.
glm::vec4 display_value_of(const Kernels& kernels, const glm::vec4& linear);
// Resolve::background for a plain clear color: the color an undrawn pixel brings to the encode
// (scaled, never mapped, when tone mapped) and its codes at the row's scale.
shading::KnownCodes background_codes(const Kernels& kernels, const Resolve& resolve,
                                     const glm::vec4& clear);
// Writes the tile to the framebuffer; colors are scaled by the exposure and tone mapped first
// (tone_map_row.hpp). A multisampled tile's samples are averaged in linear light, each
// mapped first (the depth image takes sample 0's depth). In a display-referred frame the tile
// holds display values, which an 8-bit target takes as they are, rounded to 8 bits, instead
// of sRGB-encoded (scale is then 1).
void resolve_tile(const TileContext& tile, const Resolve& resolve, Framebuffer& target);
// Writes only the tile's depth to the framebuffer's depth image (a depth-only pass); `cleared`:
// the tile drew nothing, every pixel is at the clear depth.
void resolve_depth_tile(const TileContext& tile, bool cleared, Framebuffer& target);
// A tile with an empty bin under a plain clear color is written straight from it.
void resolve_cleared_tile(const TileContext& tile, const glm::vec4& color, float scale,
                          Framebuffer& target);

}  // namespace facet::pipeline
