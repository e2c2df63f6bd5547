// Scene traversal and draw order (see draw_list.hpp).
#include "gl/draw_list.hpp"

#include <algorithm>

namespace facet::gl {
namespace {

Bounds mesh_bounds(const Mesh& mesh) {
  Bounds b;
  for (const glm::vec3& p : mesh.positions) b.add(p);
  return b;
}

bool is_blended(AlphaMode mode) { return mode == AlphaMode::blend || mode == AlphaMode::additive; }

}  // namespace

std::vector<GlDraw> ordered_draws(const Scene& scene, const Camera& camera) {
  std::vector<GlDraw> opaque, blended;
  const glm::mat4 view = camera.view();
  for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
    const SceneNode& node = scene.nodes[n];
    if (node.instances.empty() && node.coarser.empty()) continue;
    const glm::mat4 world = scene.world_transform(static_cast<int>(n));
    for (const MeshInstance& instance : node.instances_seen_from(world, camera)) {
      GlDraw draw{&scene.meshes[instance.mesh], &scene.materials[instance.material], world, 0.0f};
      if (!is_blended(draw.material->alpha_mode)) {
        opaque.push_back(draw);
        continue;
      }
      const Bounds b = mesh_bounds(**draw.mesh);
      if (!b.empty()) draw.view_depth = -(view * world * glm::vec4(b.centre(), 1.0f)).z;
      blended.push_back(draw);
    }
  }
  std::stable_sort(blended.begin(), blended.end(),
                   [](const GlDraw& a, const GlDraw& b) { return a.view_depth > b.view_depth; });
  opaque.insert(opaque.end(), blended.begin(), blended.end());
  return opaque;
}

void depth_view_range(const std::vector<GlDraw>& draws, const Camera& camera, float& nearest,
                      float& farthest) {
  const bool depth_view = std::any_of(draws.begin(), draws.end(), [](const GlDraw& d) {
    return d.material->shading == ShadingModel::depth;
  });
  if (!depth_view) {  // nothing reads the range: no pass over the meshes
    nearest = camera.near_plane, farthest = camera.far_plane;
    return;
  }
  nearest = camera.far_plane, farthest = camera.near_plane;
  const glm::mat4 view = camera.view();
  for (const GlDraw& draw : draws) {
    const Bounds b = mesh_bounds(**draw.mesh);
    if (b.empty()) continue;
    const glm::mat4 model_view = view * draw.transform;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                        (corner & 4) ? b.max.z : b.min.z);
      const float depth = -(model_view * glm::vec4(p, 1.0f)).z;
      nearest = std::min(nearest, depth), farthest = std::max(farthest, depth);
    }
  }
  nearest = std::clamp(nearest, camera.near_plane, camera.far_plane);
  farthest = std::clamp(farthest, camera.near_plane, camera.far_plane);
}

}  // namespace facet::gl
