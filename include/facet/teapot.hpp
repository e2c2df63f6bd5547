// The Utah teapot: Newell's 32 Bézier patches as a smooth indexed mesh, and a scene showing it.
// Y up, spout along +X, resting on y = 0, in the classic units (about 6.43 x 3.15 x 4.0).
#pragma once

#include "facet/mesh.hpp"
#include "facet/scene.hpp"

namespace facet {

// Newell's teapot (the classic 306 control points, 32 bicubic patches) tessellated with
// `subdivisions` segments along each patch edge (1..64; facet::Error otherwise). Vertices shared
// by neighbouring patches are welded; normals come from the patch derivatives; tangents follow
// +u with w = +1. Texture space gives each patch one unit square, laid out so that the
// coordinates run on across seams: u counts quarter turns counter-clockwise from +X seen from
// above (half turns around the spout and handle tubes), v climbs from the bottom centre to the
// rim, from the lid's edge to the knob top, and from the body along the spout and the handle —
// sample with Wrap::repeat to see one copy of the image per patch. The gap between lid and body,
// the open spout tip and the handle and spout ends sunk into the body are part of the model.
// Triangles: 64 * subdivisions^2 - 8 * subdivisions (the knob top and the bottom centre are
// fans, without the zero-area triangles a grid would put there).
Mesh teapot(int subdivisions = 8);

// The teapot (12 subdivisions, warm off-white Blinn-Phong) with no ground, under three-point
// lights placed relative to a camera that frames it for 16:9.
Scene make_teapot_scene();

}  // namespace facet
