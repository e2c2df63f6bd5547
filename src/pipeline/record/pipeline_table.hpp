// The table of specialised pipelines, read once per draw when it is recorded. Each draw's shading
// model selects, once per draw, a DrawPipeline: the vertex function, the per-triangle face hook and
// the raster loop instantiated for that model (raster.hpp). No per-pixel dispatch remains.
#pragma once

#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/raster/raster.hpp"
#include "shading/surface.hpp"

namespace facet::pipeline {

// The pipeline for a built-in shading model and alpha mode.
DrawPipeline pipeline_for(ShadingModel model, AlphaMode alpha = AlphaMode::opaque);

// The pipeline for a draw: its material's shading model and alpha mode, where the mesh,
// material and the frame's lights allow in a cheaper form (Gouraud of one constant surface
// color interpolates only its light, and under gray light one channel of it; Lambert lit from one
// side by directional lights only, no position, unless `shadowed`: the frame renders shadows, which
// are looked up at the position). Point meshes ignore the shading model (unlit: primitive.cpp).
DrawPipeline pipeline_for(const Material& material, const Mesh& mesh, const Lighting& lighting,
                          bool shadowed = false);

// Makes the draw one of a pass that writes depth alone (the shadow maps, a render texture that
// keeps no color): DepthOnlyShading, which shades nothing, and no maps to sample. For draws whose
// depths are an opaque surface's, which the caller checks.
void draw_depth_alone(DrawRecord& draw);

// The pipeline for any shading model type (see shading/models.hpp for what it provides);
// also how tests plug in their own models.
template <class Shading, AlphaMode kAlpha = AlphaMode::opaque>
DrawPipeline make_pipeline() {
  static_assert(Shading::kVaryings <= kMaxVaryings, "raise kMaxVaryings");
  DrawPipeline p;
  p.varyings = Shading::kVaryings;
  p.normal_slot = Shading::kNormalSlot;
  // Every vertex through a batch form (vertex.cpp): the model's own, else one from its vertex().
  if constexpr (requires { &Shading::vertex_batch; }) {
    p.vertex_batch = &Shading::vertex_batch;
  } else {
    p.vertex_batch = &shading::vertex_batch_from_vertex<Shading>;
  }
  if constexpr (requires { &Shading::face; }) p.face = &Shading::face;
  if constexpr (requires { &Shading::face_without_normals; }) {
    p.face_without_normals = &Shading::face_without_normals;
  }
  if constexpr (requires { &Shading::triangle; }) p.triangle = &Shading::triangle;
  p.lights_back_faces = lights_back_faces<Shading>();
  p.lights_vertices = lights_vertices<Shading>();
  p.raster = &raster_triangle<Shading, kAlpha>;
  p.maps_read = maps_read<Shading>();
  p.depth_tested = depth_tested<Shading>();
  p.occludes = p.depth_tested && kAlpha == AlphaMode::opaque && !additive<Shading>();
  p.display_referred = display_referred<Shading>() && !additive<Shading>() &&
                       (kAlpha == AlphaMode::opaque || kAlpha == AlphaMode::mask);
  return p;
}

}  // namespace facet::pipeline
