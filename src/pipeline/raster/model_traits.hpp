// Stage: raster, what a shading model declares (shading/models.hpp lists the members), as the
// raster loops and PixelWriter (pixel_writer.hpp) read it at compile time: each trait is the
// member's value, or its default when the model does not declare it.
#pragma once

namespace facet::pipeline {

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
// Models of the extra outputs write data, not a color: their fourth channel is kept as computed
// where a color's alpha would be 1 (blend_into).
template <class Shading>
constexpr bool writes_data() {
  if constexpr (requires { Shading::kWritesData; }) return Shading::kWritesData;
  return false;
}

// Models that write depth alone (shading/models.hpp's DepthOnlyShading): their one-sample
// triangles take raster_depth_only.
template <class Shading>
constexpr bool depth_only() {
  if constexpr (requires { Shading::kDepthOnly; }) return Shading::kDepthOnly;
  return false;
}

// Models whose colors are display values (shading/models.hpp's DisplayReferred).
template <class Shading>
constexpr bool display_referred() {
  if constexpr (requires { Shading::kDisplayReferred; }) return Shading::kDisplayReferred;
  return false;
}

// Models marked shading::LightsBackFaces (DrawPipeline::lights_back_faces).
template <class Shading>
constexpr bool lights_back_faces() {
  if constexpr (requires { Shading::kLightsBackFaces; }) return Shading::kLightsBackFaces;
  return false;
}

// Models marked kLightsVertices (DrawPipeline::lights_vertices).
template <class Shading>
constexpr bool lights_vertices() {
  if constexpr (requires { Shading::kLightsVertices; }) return Shading::kLightsVertices;
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

// The varying slot of the texture coordinate a model reads its material's maps at, or -1: such
// models have the maps sampled ahead, a batch of pixels at a time (shading/texel_batch.hpp);
// fragment() reads the base color map's texel through shading::base_color_texel.
template <class Shading>
constexpr int base_color_texcoord() {
  if constexpr (requires { Shading::kBaseColorTexcoord; }) return Shading::kBaseColorTexcoord;
  return -1;
}

// Models with fragment_batch are shaded a batch of pixels at a time with SIMD (shading/
// shade_batch.hpp), for every draw and every batch size: the built-in models and the glmark2
// shaders, whose batch form is all there is. The others (the debug views, the extra outputs)
// have fragment(), called per pixel.
template <class Shading>
constexpr bool batch_shaded() {
  constexpr bool kBatch = requires { &Shading::fragment_batch; };
  static_assert(
      kBatch != requires { &Shading::fragment; },
      "a shading model has fragment() or fragment_batch(), one of them");
  return kBatch;
}

// The material maps besides the base color map a batch model reads (shading::maps_read).
template <class Shading>
constexpr unsigned maps_read() {
  if constexpr (requires { Shading::kMapsRead; }) return Shading::kMapsRead;
  return 0;
}

}  // namespace facet::pipeline
