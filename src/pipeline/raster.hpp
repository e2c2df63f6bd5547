// Stage: raster + shade. Reads one tile's bin (bin.cpp) and, for each triangle in submission
// order, finds the covered pixel centres with the fixed-point edge functions set up in
// setup.cpp, tests depth early, shades with the draw's shading model and writes the tile's
// own color and depth buffers; output.cpp then resolves the tile to the framebuffer.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/vec4.hpp>

#include "pipeline/fixed_point.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/setup.hpp"
#include "shading/fragment.hpp"

namespace facet::pipeline {

// Largest tile edge the renderer accepts (RenderSettings::tile_size).
inline constexpr int kMaxTileSize = 128;

// One tile being rendered: owned by one task for the whole frame, so nothing here is shared.
struct TileContext {
  const Frame* frame = nullptr;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixel rectangle [x0, x1) x [y0, y1)
  int stride = 0;                      // pixels per row of the tile buffers
  glm::vec4* color = nullptr;          // linear RGBA
  float* depth = nullptr;
  std::uint64_t pixels_shaded = 0;
};

// Shading models may opt out of the depth test (debug counters) and blend additively.
template <class Shading>
constexpr bool depth_tested() {
  if constexpr (requires { Shading::kDepthTest; }) return Shading::kDepthTest;
  return true;
}
template <class Shading>
constexpr bool additive() {
  if constexpr (requires { Shading::kAdditive; }) return Shading::kAdditive;
  return false;
}

// Models with kEdgeOverlay draw the triangle's edges over their shading: pixels closer to an
// edge than kOverlayHalfWidth pixels take the draw's wire color. Measured from the edge
// functions, so the edges sit exactly on the surface: no depth fighting with the fill.
template <class Shading>
constexpr bool edge_overlay() {
  if constexpr (requires { Shading::kEdgeOverlay; }) return Shading::kEdgeOverlay;
  return false;
}
inline constexpr float kOverlayHalfWidth = 0.5f;

// Distance fog (the classic darkening with distance): a per-draw constant decides the mode,
// so this branch is perfectly predicted; a template flag would double every raster loop.
inline glm::vec4 apply_fog(glm::vec4 color, float view_depth, const Fog& fog) {
  if (fog.mode == FogMode::none) return color;
  float keep = fog.mode == FogMode::linear
                   ? (fog.end - view_depth) / std::max(fog.end - fog.start, 1e-6f)
                   : std::exp(-fog.density * view_depth);
  keep = std::clamp(keep, 0.0f, 1.0f);
  return {glm::mix(fog.color, glm::vec3(color), keep), color.a};
}

// Rasterizes one triangle into the tile; a template over the shading model and the alpha
// mode so that the per-pixel loop is specialised once per draw state (shade.cpp builds the
// table).
template <class Shading, AlphaMode kAlpha = AlphaMode::opaque>
void raster_triangle(TileContext& tile, const SetupTriangle& t) {
  const int x0 = std::max(t.min_x, tile.x0), x1 = std::min(t.max_x, tile.x1 - 1);
  const int y0 = std::max(t.min_y, tile.y0), y1 = std::min(t.max_y, tile.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  const shading::DrawUniforms& uniforms = tile.frame->draws[t.draw].uniforms;
  const Fog& fog = uniforms.lighting->fog;
  const float alpha_cutoff = uniforms.material->alpha_cutoff;
  constexpr bool kDepthTest = depth_tested<Shading>();
  // Blended draws test depth but do not write it (they are sorted back to front instead).
  constexpr bool kDepthWrite =
      kDepthTest && (kAlpha == AlphaMode::opaque || kAlpha == AlphaMode::mask);
  constexpr int kVaryings = Shading::kVaryings;
  shading::Fragment f;
  f.planes = tile.frame->planes.data() + t.varying_planes;
  f.inv_w = &t.inv_w;
  const std::int64_t step[3] = {std::int64_t{t.a[0]} * kSubpixelScale,
                                std::int64_t{t.a[1]} * kSubpixelScale,
                                std::int64_t{t.a[2]} * kSubpixelScale};
  std::uint64_t shaded = 0;
  for (int y = y0; y <= y1; ++y) {
    const std::int64_t cy = pixel_centre(y);
    const std::int64_t cx = pixel_centre(x0);
    // Each row starts from an exact evaluation, then steps by a (integer, so exact too).
    std::int64_t e0 = t.a[0] * cx + t.b[0] * cy + t.c[0];
    std::int64_t e1 = t.a[1] * cx + t.b[1] * cy + t.c[1];
    std::int64_t e2 = t.a[2] * cx + t.b[2] * cy + t.c[2];
    const float py = static_cast<float>(y) + 0.5f;
    // Plane values at the row, once per row (the same float operations as evaluate()).
    const float z_row = evaluate_row(t.z, t.ref_y, py);
    const float inv_w_row = evaluate_row(t.inv_w, t.ref_y, py);
    float varying_rows[kVaryings > 0 ? kVaryings : 1];
    for (int k = 0; k < kVaryings; ++k) varying_rows[k] = evaluate_row(f.planes[k], t.ref_y, py);
    float* depth_row =
        tile.depth + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride - tile.x0;
    glm::vec4* color_row =
        tile.color + static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride - tile.x0;
    for (int x = x0; x <= x1; ++x, e0 += step[0], e1 += step[1], e2 += step[2]) {
      if ((e0 | e1 | e2) < 0) continue;  // outside some edge (sign bit set)
      const float px = static_cast<float>(x) + 0.5f;
      const float z = evaluate_in_row(z_row, t.z, t.ref_x, px);
      if constexpr (kDepthTest) {
        if (!(z < depth_row[x])) continue;  // early depth test (less); NaN fails
      }
      f.w = 1.0f / evaluate_in_row(inv_w_row, t.inv_w, t.ref_x, px);
      for (int k = 0; k < kVaryings; ++k) {
        f.v[k] = evaluate_in_row(varying_rows[k], f.planes[k], t.ref_x, px) * f.w;
      }
      glm::vec4 color = Shading::fragment(f, uniforms);
      if constexpr (kAlpha == AlphaMode::mask) {
        if (!(color.a >= alpha_cutoff)) continue;  // cut-out: no color, no depth
      }
      if constexpr (edge_overlay<Shading>()) {
        float distance = std::min({static_cast<float>(e0) * t.edge_scale[0],
                                   static_cast<float>(e1) * t.edge_scale[1],
                                   static_cast<float>(e2) * t.edge_scale[2]});
        if (distance < kOverlayHalfWidth) color = uniforms.wire_color;
      }
      color = apply_fog(color, f.w, fog);
      glm::vec4& out = color_row[x];
      if constexpr (additive<Shading>()) {
        out += color;
      } else if constexpr (kAlpha == AlphaMode::blend) {  // "over", straight alpha
        out = glm::vec4(glm::vec3(color) * color.a + glm::vec3(out) * (1.0f - color.a),
                        color.a + out.a * (1.0f - color.a));
      } else if constexpr (kAlpha == AlphaMode::additive) {
        out += glm::vec4(glm::vec3(color) * color.a, 0.0f);
      } else {
        out = color;
      }
      if constexpr (kDepthWrite) depth_row[x] = z;
      ++shaded;
    }
  }
  tile.pixels_shaded += shaded;
}

// Rasterizes one segment into the tile (line.cpp).
void raster_line(TileContext& tile, const SetupLine& line);

}  // namespace facet::pipeline
