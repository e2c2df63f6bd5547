// The built-in shading models as C++ types. The raster loop (pipeline/raster/raster.hpp) is a
// template over these, chosen once per draw, so the per-pixel code has no virtual calls.
//
// A shading model provides:
//   kVaryings       floats it passes from vertex to fragment (interpolated perspective-correct)
//   kNormalSlot     index of a world normal in its varyings (or -1): filled with the face
//                   normal when the mesh has no normals
//   vertex(in, uniforms, out)        per vertex: writes kVaryings floats; the vertex stage
//                   calls it a run of vertices at a time (surface.hpp's vertex_batch_from_vertex)
//                   unless the model has vertex_batch (vertex_batch.hpp), a form of its own for
//                   a run of vertices at once
//   face(normal, centre, uniforms, v[3])  optional, per triangle before clipping: may rewrite
//                                    the three vertices' varyings (flat shading)
//   and how its pixels are shaded, one of:
//   fragment(fragment, uniforms) -> linear RGBA   per pixel (the extra outputs and debug
//                   counters, a few operations each)
//   fragment_batch(uniforms, input, rgba), kMapsRead   a batch of pixels at once with SIMD, fog
//                   included, the material's maps sampled ahead, for every draw (kernels.hpp's
//                   BatchForm: the built-in models and the debug views; the glmark2 shaders of
//                   bench/scenes)
//   kDisplayReferred  optional (inherit DisplayReferred): the colors are display values
//                   (below); frames of such draws alone skip the sRGB encode
//                   (pipeline/renderer.cpp)
//   kDepthOnly      optional: the draw writes depth alone (the shadow passes' casters), which
//                   one-sample tiles do without shading (pipeline/raster/depth_only.hpp)
//   kBaseColorTexcoord  optional: the slot of the texture coordinate the base color map (and
//                   the other maps) are read at; the raster loop then samples the maps for a
//                   batch of pixels at once (SIMD), for fragment() through base_color_texel()
// Lit models with specular light are in lit_models.hpp. Per-draw options (is there a base color
// map? which fog?) are plain branches on per-draw constants: always predicted the same way,
// where template flags for each would multiply the raster loops.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "core/color.hpp"
#include "shading/fragment.hpp"
#include "shading/kernels.hpp"
#include "shading/surface.hpp"
#include "shading/uniforms.hpp"

namespace facet::shading {

// Display values: what the screen should show, as an 8-bit code (debug views show data, not
// light), stored by the tile as the code decoded to linear (which resolve's sRGB encode gives
// back exactly); in a frame whose every color is a display value (DrawUniforms::display_referred,
// pipeline/frame_run.cpp) as code / 255, which resolve turns back into the code without the sRGB
// tables (at one sample as the code itself, in a tile of codes: ShadeInput::codes, which the
// batch forms honour by storing through batch_math-inl.h's DisplayOut); in a float target
// (display_exact) as the value itself clamped to [0, 1], neither rounded nor decoded, so a
// normal's 0 is stored as 0.5. NaN shows as 0. The debug views are their SIMD kernel alone
// (shade_batch.cpp's ShadeDisplay).
// The mark of models whose colors are display values (kDisplayReferred above).
struct DisplayReferred {
  static constexpr bool kDisplayReferred = true;
};

// vertex() for a run of vertices (vertex_batch.hpp) for the models whose vertex() is
// surface_vertex<kCount>(): copies and products, so the vertex stage takes it for every draw.
template <int kCount>
struct SurfaceVertexBatch {
  static void vertex_batch(const DrawUniforms& u, const VertexBatchInput& in,
                           float (*out)[kVertexBatch]) {
    surface_vertex_batch<kCount>(u, in, out);
  }
};

// base color x vertex color x base color map, no lighting.
struct UnlitShading : BatchForm<BatchModel::unlit>, SurfaceVertexBatch<kUnlitVaryings> {
  static constexpr int kVaryings = kUnlitVaryings;
  static constexpr int kNormalSlot = -1;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
};

// Unlit for a draw whose color is the material's alone (no vertex colors:
// pipeline/record/pipeline_table.cpp decides): the texture coordinate is its only varying, and
// the color is the material's exactly, not an interpolated constant that may be off in the
// last bit. Its vertices go through the batch form (copies), so a draw inside the guard band
// keeps no clip-space vertices (80 bytes a vertex).
struct ConstantColorUnlitShading : BatchForm<BatchModel::constant_unlit> {
  static constexpr int kVaryings = 2;
  static constexpr int kNormalSlot = -1;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
  static_assert(kTexcoordSlot + 2 <= kVaryings);
  static void vertex_batch(const DrawUniforms&, const VertexBatchInput& in,
                           float (*out)[kVertexBatch]) {
    texcoords_vertex_batch(in, out);
  }
};

// The shadow passes' depth, for casters that are not cut out: no varyings, and in one-sample
// tiles (the passes' own) no shading and no color (pipeline/raster/depth_only.hpp); in a
// multisampled tile, white, which nothing reads.
struct DepthOnlyShading {
  static constexpr int kVaryings = 0;
  static constexpr int kNormalSlot = -1;
  static constexpr bool kDepthOnly = true;
  static void vertex_batch(const DrawUniforms&, const VertexBatchInput&, float (*)[kVertexBatch]) {}
  static glm::vec4 fragment(const Fragment&, const DrawUniforms&) { return glm::vec4(1.0f); }
};

// The mesh's vertex colors only (white where it has none).
struct VertexColorShading {
  static constexpr int kVaryings = 4;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    store(out, in.color);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms&) { return load4(f.v); }
};

// One lit color per triangle from its face normal: the face hook lights the triangle's
// average color at its centre and writes it to all three vertices, so it stays constant.
struct FlatShading {
  static constexpr int kVaryings = 4;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput& in, const DrawUniforms& u, float* out) {
    store(out, material_color(in, u));
  }
  static void face(glm::vec3 normal, glm::vec3 centre, const DrawUniforms& u, float* v[3]) {
    glm::vec4 average = (load4(v[0]) + load4(v[1]) + load4(v[2])) / 3.0f;
    // The diffuse light at the centre, by the Gouraud models' kernel (vertex_batch.hpp), without
    // shadows: one lookup at the centre would darken or light whole triangles at once.
    alignas(64) float light[6][kVertexBatch];
    u.frame->kernels->gouraud_light_batch(u, {1, &centre, &normal, false}, light);
    const glm::vec3 diffuse(light[0][0], light[1][0], light[2][0]);
    glm::vec4 lit{glm::vec3(average) * diffuse, average.a};
    for (int i = 0; i < 3; ++i) store(v[i], lit);
  }
  static glm::vec4 fragment(const Fragment& f, const DrawUniforms&) { return load4(f.v); }
};

// Per-pixel Lambert: the interpolated normal is renormalized and lit at each pixel.
// kPositioned false: without the position, for draws lit by directional lights only and from
// one side (pipeline/record/pipeline_table.cpp decides), which never read it: 9 varyings instead of
// 12 to set up and interpolate, the same colors.
template <bool kPositioned>
struct LambertShadingT
    : BatchForm<BatchModel::lambert>,
      LightsBackFaces,
      SurfaceVertexBatch<kPositioned ? kSurfaceVaryings : kUnpositionedSurfaceVaryings> {
  static constexpr int kVaryings = kPositioned ? kSurfaceVaryings : kUnpositionedSurfaceVaryings;
  static constexpr int kNormalSlot = shading::kNormalSlot;
  static constexpr int kBaseColorTexcoord = kTexcoordSlot;
};
using LambertShading = LambertShadingT<true>;
using UnpositionedLambertShading = LambertShadingT<false>;

// Lambert with the triangle edges drawn on top (the raster loop draws them; raster.hpp).
struct WireOverlayShading : LambertShading {
  static constexpr bool kEdgeOverlay = true;
};

// Debug view: linear view depth over the frame's own range (FrameUniforms::depth_view_near and
// depth_view_far), near -> white, far -> black.
struct DepthShading : BatchForm<BatchModel::depth_view>, DisplayReferred {
  static constexpr int kVaryings = 0;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput&, const DrawUniforms&, float*) {}
};

// Debug view: world-space normal, renormalized per pixel, shown as n * 0.5 + 0.5.
struct NormalsShading : BatchForm<BatchModel::normals>, DisplayReferred {
  static constexpr int kVaryings = 3;
  static constexpr int kNormalSlot = 0;
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    store(out, in.normal);
  }
};

// Debug view: texture coordinates as red (u) and green (v), fractional part.
struct TexcoordShading : BatchForm<BatchModel::texcoords_view>, DisplayReferred {
  static constexpr int kVaryings = 2;
  static constexpr int kNormalSlot = -1;
  static void vertex(const VertexInput& in, const DrawUniforms&, float* out) {
    store(out, in.texcoord);
  }
};

// Debug counter: every covered pixel centre adds 1 to red, with no depth test, so a float
// target holds how many times each pixel was hit (fill-rule tests, overdraw heat maps).
struct OverdrawCountShading {
  static constexpr int kVaryings = 0;
  static constexpr int kNormalSlot = -1;
  static constexpr bool kDepthTest = false;
  static constexpr bool kAdditive = true;
  static void vertex(const VertexInput&, const DrawUniforms&, float*) {}
  static glm::vec4 fragment(const Fragment&, const DrawUniforms&) { return {1, 0, 0, 0}; }
};

}  // namespace facet::shading
