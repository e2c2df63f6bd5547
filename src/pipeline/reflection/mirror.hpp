// The geometry of a planar reflection: the plane a mirror draw lies in, the camera that sees the
// scene mirrored through it (cropped to where the mirrors are seen), and where a point's
// reflection lands in that camera's image. Read by the reflection passes
// (reflection_passes.cpp) once per mirror plane per frame.
#pragma once

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>

#include "facet/camera.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "pipeline/frame.hpp"

namespace facet::pipeline {

// The world-space plane (n, d), n unit, n . p + d = 0 on it, in which every vertex of `mesh`
// placed by `model` lies (within 1e-4 of the mesh's size), turned so that `eye` is on its
// positive side; none for a mesh that is not flat, has no triangle of non-zero area, is seen
// edge-on (the eye within 1e-6 of the mesh's size of its plane), or shows the eye the side
// `cull` culls (its first such triangle's winding says which side is the front).
std::optional<glm::vec4> mirror_plane(const Mesh& mesh, const glm::mat4& model, glm::vec3 eye,
                                      CullMode cull);

// Whether two planes of mirror_plane are the same (one pass serves both).
bool same_plane(const glm::vec4& a, const glm::vec4& b);

// The camera that sees the world as `camera` sees it in a mirror on `plane`, but flipped left
// to right: `camera` reflected through the plane (eye, target and up), its lens shift mirrored.
// A reflection reverses handedness, which a look-at camera cannot; seeing the mirrored scene
// from the mirrored eye gives that image flipped, with the faces' winding as it is.
Camera mirrored_camera(const Camera& camera, const glm::vec4& plane);

// World position -> (u w, v w, 0, w) for the image `mirrored` renders (mirrored_camera): divided
// by w, the texture coordinates (u right, v up) of where the point is seen. For a point on the
// mirror, that is what the mirror shows there: the mirrored eye's ray through the point goes on
// to what the real eye sees reflected at it (the image's flip is undone by reading it so).
glm::mat4 mirror_image_transform(const Camera& mirrored);

// The world plane as a plane of clip space under `view_projection`: inside (>= 0) where the
// world plane is.
glm::vec4 clip_space_plane(const glm::mat4& view_projection, const glm::vec4& world_plane);

// A rectangle of NDC, [low, high]; empty when low > high.
struct NdcRect {
  glm::vec2 low{1e30f}, high{-1e30f};
  bool empty() const { return !(low.x <= high.x && low.y <= high.y); }
  void add(glm::vec2 p) { low = glm::min(low, p), high = glm::max(high, p); }
};

// Adds to `rect` where a box (a draw's bounds) is seen under model_view_projection: its faces
// clipped to the view frustum, projected. A box the view does not see adds nothing.
void add_seen_box(const MeshBox& box, const glm::mat4& model_view_projection, NdcRect& rect);

// The camera that sees only `rect` of `camera`'s image (within [-1, 1]^2, not empty), filling
// its own: the same eye, its field of view (or view height), aspect and lens shift narrowed.
Camera cropped_camera(const Camera& camera, const NdcRect& rect);

}  // namespace facet::pipeline
