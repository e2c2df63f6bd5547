// How a sun's shadow maps share the view (RenderSettings::shadow_cascades): how many maps the
// view needs, where their slices of the view's depths meet, and the band before each meeting
// where the lookup blends a map into the next. Read by the shadow passes (shadow_passes.cpp)
// once per frame; the lookup (shading/shadow_batch-inl.h) reads the result in ShadowMaps.
#pragma once

#include "facet/camera.hpp"
#include "pipeline/shadow/shadow_fit.hpp"

namespace facet::pipeline {

// A range of view depths; empty when nearest > farthest.
struct ViewDepths {
  float nearest, farthest;
};

// The view depths of `scene` (the box around every draw) within the camera's near and far
// planes: where a sun's cascades split. Empty when the scene lies outside those planes.
ViewDepths scene_depths(const Camera& view, const WorldBox& scene);

// The view depths of what the camera sees of `scene`: the nearest and farthest points of the
// box's intersection with the view frustum. Tighter than scene_depths when the camera looks
// down on a box it is above (a ground plane seen from over it). Empty when the frustum misses
// the box.
ViewDepths seen_depths(const Camera& view, const WorldBox& scene);

// A map fitted to depths [near, far] spans the frustum's width at `far`, so its texels, near
// the camera, are about far / near times the size on screen they are at the far end. The
// automatic count is the fewest cascades n, at most kMaxShadowCascades, with
// far <= near * kCascadeDepthRatio^n over the depths the camera sees of the scene
// (seen_depths): logarithmic slices of that range would each keep the ratio within
// kCascadeDepthRatio. 32 keeps one map for the views one map serves well: a model seen whole
// spans two or three times its nearest depth, objects on a ground seen from above it a few
// tens; a world seen from the ground spans thousands. An orthographic view's texels are the
// same size on screen at every depth: one map.
inline constexpr float kCascadeDepthRatio = 32.0f;
int automatic_cascade_count(const Camera& view, const WorldBox& scene);

// Where `count` cascades over `depths` meet: split[0] = nearest, split[count] = farthest, and
// between them the practical split scheme (Zhang et al., "Parallel-split shadow maps"): a blend
// of logarithmic steps (each map's texels the same size on screen) and even ones, weighted
// 0.8 toward logarithmic. split holds count + 1 values.
void cascade_splits(ViewDepths depths, int count, float* split);

// The blend band of cascade i (of slice split[i] to split[i + 1]): its last kCascadeBlendShare
// of depths, from cascade_blend_start(split, i) to split[i + 1], where the lookup moves from
// map i's visibility to map i + 1's. Map i + 1 is fitted from the band's start, so both maps
// hold the band.
inline constexpr float kCascadeBlendShare = 0.1f;
float cascade_blend_start(const float* split, int i);

}  // namespace facet::pipeline
