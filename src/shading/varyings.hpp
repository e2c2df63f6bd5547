// What the shading models and the pipeline's stages both know of varyings: how many a model
// may have, and the plane equation that carries one across the screen. Setup
// (pipeline/setup) writes the planes; raster and the shading models read them.
#pragma once

namespace facet::shading {

// Largest kVaryings of any shading model; the clipper's vertices have this many slots.
inline constexpr int kMaxVaryings = 16;

// Value of an attribute across the screen: value(px, py) = at_ref + dx*(px-ref_x) +
// dy*(py-ref_y), with (px, py) a pixel centre in pixels and ref the triangle's first vertex.
struct Plane {
  float at_ref = 0;
  float dx = 0;
  float dy = 0;
};

}  // namespace facet::shading
