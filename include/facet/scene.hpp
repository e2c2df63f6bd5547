// Scene: meshes, materials, textures, a node hierarchy placing mesh instances, lights and
// cameras — what a model file holds once imported, and what the built-in worlds are built as.
// It is plain data: import once, then render it as often as you like.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/renderer.hpp"
#include "facet/texture.hpp"

namespace facet {

// One mesh drawn with one material, at a node.
struct MeshInstance {
  int mesh = 0;      // index into Scene::meshes
  int material = 0;  // index into Scene::materials
};

// Axis-aligned bounds; empty when min > max.
struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  bool empty() const { return min.x > max.x; }
  glm::vec3 centre() const { return (min + max) * 0.5f; }
  void add(glm::vec3 p);
};

// A coarser stand-in for a node's instances, drawn instead of them from `distance` away on.
struct DetailLevel {
  float distance = 0.0f;
  std::vector<MeshInstance> instances;
};

struct SceneNode {
  std::string name;
  glm::mat4 transform{1.0f};  // relative to the parent
  int parent = -1;            // index into Scene::nodes, or -1 for a root; parents come first
  std::vector<MeshInstance> instances;
  // Levels of detail, by increasing distance (none: `instances` from everywhere). The distance
  // is the camera's eye to the nearest point of `detail_bounds` (node space, around every
  // level: Scene::bound_detail_levels() sets it; empty, `instances` are drawn from everywhere),
  // measured as if the field of view were 60 degrees: a narrower one, which magnifies, counts
  // the node as nearer. An orthographic view, the same size at every distance, counts as the
  // distance at which a 60 degree view is as tall.
  std::vector<DetailLevel> coarser;
  Bounds detail_bounds;

  // The instances to draw for `camera`, the node's world transform being `world`.
  const std::vector<MeshInstance>& instances_seen_from(const glm::mat4& world,
                                                       const Camera& camera) const;
};

struct Scene {
  // Meshes do not change once in a scene (draw_scene has the renderer check each once): to
  // change one, put a new one in its place.
  std::vector<std::shared_ptr<const Mesh>> meshes;
  std::vector<Material> materials;
  std::vector<std::shared_ptr<const Texture>> textures;  // every texture the materials use
  std::vector<SceneNode> nodes;
  Lighting lighting;
  std::vector<Camera> cameras;   // cameras stored in the file (world space)
  Camera camera;                 // the default view
  bool has_file_lights = false;  // lighting.lights came from the file

  // Adds a mesh, a material and a root node drawing one with the other; returns the node.
  int add_object(Mesh mesh, Material material, const glm::mat4& transform = glm::mat4(1.0f),
                 std::string name = {});

  // World transform of a node (its parents' transforms applied).
  glm::mat4 world_transform(int node) const;
  // World-space bounds of every mesh instance.
  Bounds bounds() const;
  // Sets each node's detail_bounds, where it has levels of detail, to the box around the
  // meshes of all its levels (in node space).
  void bound_detail_levels();
  std::size_t triangle_count() const;  // over all instances
};

// Records every mesh instance of the scene (the scene must live until renderer.finish()), at
// the level of detail each node has for the camera of renderer.begin_frame(). Node n's draws
// have the instance id n + 1 (Renderer::set_instance_id).
void draw_scene(Renderer& renderer, const Scene& scene);

// A camera that frames the whole scene from a pleasant three-quarter view: from the front
// right, above, at a distance where the bounding sphere fills the view.
Camera frame_scene(const Scene& scene, float aspect, float fov_y_degrees = 45.0f);

// An orthographic camera that sees the whole scene along the line of sight of `view` (from its
// eye through its target; its up kept): view_height takes in every vertex with frame_scene's
// margin, and the eye and target move along that line so that the scene lies between the near
// and far planes (in a parallel projection that changes nothing else).
Camera fit_orthographic(const Scene& scene, const Camera& view, float aspect);

// frame_scene's three-quarter view with a parallel projection (fit_orthographic).
Camera frame_scene_orthographic(const Scene& scene, float aspect);

}  // namespace facet
