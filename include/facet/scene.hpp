// Scene: meshes, materials, textures, a node hierarchy placing mesh instances, lights and
// cameras — what a model file holds once imported, and what the built-in worlds are built as.
// It is plain data: import once, then render it as often as you like.
#pragma once

#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>
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

// How the automatic view (frame_scene) looks at a scene. The default is a three-quarter view from
// the front right, above, for a model whose up is +Y (glTF's convention).
struct Framing {
  // The model's up axis, a unit vector along a world axis (+X, -X, +Y, -Y, +Z or -Z): the view
  // keeps it pointing up. Its front, which the default view faces from the right, is +Z for
  // the X and Y axes and -Y for +Z (+Y for -Z), as Blender and 3ds Max place a Z-up model.
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  // Turns the eye about the up axis through the model's centre, from the three-quarter view:
  // positive counter-clockwise seen from above (toward the model's right side); 180 shows the
  // other side.
  float azimuth_degrees = 0.0f;
  // The eye's angle above the model's horizontal plane, seen from its centre, in [-90, 90]:
  // 0 level, 90 straight down from above. Unset: the three-quarter view's (about 24 degrees).
  std::optional<float> elevation_degrees;
  float fov_y_degrees = 45.0f;

  // Throws facet::Error naming the field: an up that is not a unit world axis, a non-finite
  // angle, an elevation outside [-90, 90], a field of view outside (0, 180).
  void validate() const;
};

struct Scene {
  // Meshes do not change once in a scene (draw_scene has the renderer check each once): to
  // change one, put a new one in its place.
  std::vector<std::shared_ptr<const Mesh>> meshes;
  std::vector<Material> materials;
  std::vector<std::shared_ptr<const Texture>> textures;  // every texture the materials use
  std::vector<SceneNode> nodes;
  Lighting lighting;
  std::vector<Camera> cameras;  // cameras stored in the file (world space)
  Camera camera;                // the default view
  // Set while `camera` is the automatic view (frame_scene with this framing), as import sets
  // it: an image of another aspect than camera.aspect is framed again for its own aspect
  // (scene_camera), since a 16:9 framing stretched to a square or tall image cuts the model.
  // Empty for a camera someone placed (a built-in world's, one set by hand).
  std::optional<Framing> framing;
  bool has_file_lights = false;  // lighting.lights came from the file
  // What one scene unit is in the real world, when known (the built-in worlds are in metres:
  // 1); 0 when unknown, as for most model files. The viewer walks at a human pace where it is
  // known and scales its pace by the scene's size where it is not.
  float metres_per_unit = 0.0f;

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
// right, above, at a distance where every vertex is in view with a small margin, for an image
// of this aspect (width / height). The framing turns the view (Framing); it throws
// facet::Error if the framing is not valid. With an elevation the camera's up is the view's own
// (perpendicular to the line of sight), so at +-90 degrees, looking along the up axis, the view
// does not degenerate: the side the eye rose from is at the bottom of the picture.
Camera frame_scene(const Scene& scene, float aspect, const Framing& framing);
Camera frame_scene(const Scene& scene, float aspect, float fov_y_degrees = 45.0f);

// The scene's default view for an image of this aspect: when scene.framing is set and the
// aspect differs from scene.camera's, the framing made again for it; otherwise scene.camera
// (whose aspect the caller sets, as it does for any camera).
Camera scene_camera(const Scene& scene, float aspect);

// An orthographic camera that sees the whole scene along the line of sight of `view` (from its
// eye through its target; its up kept): view_height takes in every vertex with frame_scene's
// margin, and the eye and target move along that line so that the scene lies between the near
// and far planes (in a parallel projection that changes nothing else).
Camera fit_orthographic(const Scene& scene, const Camera& view, float aspect);

// frame_scene's three-quarter view with a parallel projection (fit_orthographic).
Camera frame_scene_orthographic(const Scene& scene, float aspect);

}  // namespace facet
