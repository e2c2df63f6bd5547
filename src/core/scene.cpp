// Scene: node transforms, bounds, drawing, automatic framing.
#include "facet/scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "facet/error.hpp"

namespace facet {
namespace {

// Calls visit(p) for every finite world-space vertex position of every mesh instance.
template <class Visit>
void for_each_world_vertex(const Scene& scene, Visit&& visit) {
  for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
    if (scene.nodes[n].instances.empty()) continue;
    glm::mat4 m = scene.world_transform(static_cast<int>(n));
    for (const MeshInstance& instance : scene.nodes[n].instances) {
      for (const glm::vec3& p : scene.meshes[instance.mesh]->positions) {
        glm::vec3 w = glm::vec3(m * glm::vec4(p, 1.0f));
        if (std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) visit(w);
      }
    }
  }
}

}  // namespace

void Bounds::add(glm::vec3 p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

int Scene::add_object(Mesh mesh, Material material, const glm::mat4& transform, std::string name) {
  meshes.push_back(std::make_shared<const Mesh>(std::move(mesh)));
  materials.push_back(std::move(material));
  SceneNode node;
  node.name = std::move(name);
  node.transform = transform;
  node.instances.push_back(
      {static_cast<int>(meshes.size()) - 1, static_cast<int>(materials.size()) - 1});
  nodes.push_back(std::move(node));
  return static_cast<int>(nodes.size()) - 1;
}

glm::mat4 Scene::world_transform(int node) const {
  glm::mat4 m = nodes[node].transform;
  for (int p = nodes[node].parent; p >= 0; p = nodes[p].parent) m = nodes[p].transform * m;
  return m;
}

Bounds Scene::bounds() const {
  Bounds b;
  for_each_world_vertex(*this, [&b](glm::vec3 p) { b.add(p); });
  return b;
}

void Scene::bound_detail_levels() {
  for (SceneNode& node : nodes) {
    if (node.coarser.empty()) continue;
    node.detail_bounds = Bounds{};
    auto add = [&](const std::vector<MeshInstance>& instances) {
      for (const MeshInstance& instance : instances) {
        for (const glm::vec3& p : meshes[instance.mesh]->positions) node.detail_bounds.add(p);
      }
    };
    add(node.instances);
    for (const DetailLevel& level : node.coarser) add(level.instances);
  }
}

std::size_t Scene::triangle_count() const {
  std::size_t count = 0;
  for (const SceneNode& node : nodes) {
    for (const MeshInstance& instance : node.instances) {
      const Mesh& mesh = *meshes[instance.mesh];
      if (mesh.topology != Topology::lines && mesh.topology != Topology::points) {
        count += mesh.primitive_count();
      }
    }
  }
  return count;
}

const std::vector<MeshInstance>& SceneNode::instances_seen_from(const glm::mat4& world,
                                                                const Camera& camera) const {
  if (coarser.empty() || detail_bounds.empty()) return instances;
  constexpr float kTanHalf60 = 0.57735026919f;  // tan(30 degrees) = 1 / sqrt(3)
  float distance;
  if (camera.projection_kind == Projection::orthographic) {
    // Where a 60 degree view is view_height tall: things look as large there as in this view.
    distance = camera.view_height * 0.5f / kTanHalf60;
  } else {
    // The world-space box around the node-space one; the eye's nearest point in it.
    Bounds box;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p((corner & 1) ? detail_bounds.max.x : detail_bounds.min.x,
                        (corner & 2) ? detail_bounds.max.y : detail_bounds.min.y,
                        (corner & 4) ? detail_bounds.max.z : detail_bounds.min.z);
      box.add(glm::vec3(world * glm::vec4(p, 1.0f)));
    }
    const glm::vec3 eye = camera.eye;
    distance = glm::length(eye - glm::clamp(eye, box.min, box.max)) *
               std::tan(glm::radians(camera.fov_y_degrees) * 0.5f) / kTanHalf60;
  }
  const std::vector<MeshInstance>* chosen = &instances;
  for (const DetailLevel& level : coarser) {
    if (distance >= level.distance) chosen = &level.instances;
  }
  return *chosen;
}

void draw_scene(Renderer& renderer, const Scene& scene) {
  const Camera& camera = renderer.camera();
  for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
    const SceneNode& node = scene.nodes[n];
    if (node.instances.empty() && node.coarser.empty()) continue;
    glm::mat4 m = scene.world_transform(static_cast<int>(n));
    renderer.set_instance_id(static_cast<std::uint32_t>(n + 1));
    for (const MeshInstance& instance : node.instances_seen_from(m, camera)) {
      renderer.draw(scene.meshes[instance.mesh], scene.materials[instance.material], m);
    }
  }
}

void Framing::validate() const {
  const glm::vec3 a = glm::abs(up);
  const bool axis = (a.x == 1.0f && a.y == 0.0f && a.z == 0.0f) ||
                    (a.x == 0.0f && a.y == 1.0f && a.z == 0.0f) ||
                    (a.x == 0.0f && a.y == 0.0f && a.z == 1.0f);
  if (!axis) throw Error("framing: up must be one of +X, -X, +Y, -Y, +Z, -Z");
  if (!std::isfinite(azimuth_degrees)) throw Error("framing: azimuth must be finite");
  if (elevation_degrees && !(std::abs(*elevation_degrees) <= 90.0f))
    throw Error("framing: elevation must be within -90 .. 90 degrees");
  if (!(fov_y_degrees > 0.0f && fov_y_degrees < 180.0f))
    throw Error("framing: the field of view must be within (0, 180) degrees");
}

Camera frame_scene(const Scene& scene, float aspect, const Framing& framing) {
  framing.validate();
  Bounds b = scene.bounds();
  if (b.empty()) b.add(glm::vec3(-1.0f)), b.add(glm::vec3(1.0f));
  glm::vec3 centre = b.centre();
  float radius = std::max(glm::length(b.max - b.min) * 0.5f, 1e-6f);
  // The model's own axes: up, right and front (front = right x up, as +Z is for +Y up).
  const glm::vec3 model_up = framing.up;
  const glm::vec3 model_right = model_up.z != 0.0f
                                    ? glm::vec3(1.0f, 0.0f, 0.0f)
                                    : glm::cross(model_up, glm::vec3(0.0f, 0.0f, 1.0f));
  const glm::vec3 model_front = glm::cross(model_right, model_up);
  // The eye's direction from the centre: the three-quarter view from the front right, above,
  // turned about the up axis by the azimuth (right-handed about up: front toward right).
  float r = 0.55f, f = 0.85f;
  if (framing.azimuth_degrees != 0.0f) {
    const float a = glm::radians(framing.azimuth_degrees);
    const float r0 = r, f0 = f;
    r = r0 * std::cos(a) + f0 * std::sin(a);
    f = f0 * std::cos(a) - r0 * std::sin(a);
  }
  glm::vec3 back, right, up, camera_up = model_up;
  if (!framing.elevation_degrees) {
    back = glm::normalize(model_right * r + model_up * 0.45f + model_front * f);
    right = glm::normalize(glm::cross(model_up, back));
    up = glm::cross(back, right);
  } else {
    // Right comes from the level direction, never from the eye's, which straight above is the
    // up axis itself; the camera's up is the view's own, so the side the eye rose from stays
    // at the bottom of the picture up to the pole.
    const glm::vec3 level = glm::normalize(model_right * r + model_front * f);
    const float e = glm::radians(*framing.elevation_degrees);
    back = glm::normalize(level * std::cos(e) + model_up * std::sin(e));
    right = glm::normalize(glm::cross(model_up, level));
    up = glm::cross(back, right);
    camera_up = up;
  }
  // Back off until every vertex is in view: a point at (x, y, z) in view axes (z toward the
  // eye) needs distance >= z + |x| / tan(half fov x), and the same for y. Fitting the
  // vertices, not the bounding box, frames round models tightly.
  float tan_y = std::tan(glm::radians(framing.fov_y_degrees) * 0.5f), tan_x = tan_y * aspect;
  float distance = 0.0f;
  for_each_world_vertex(scene, [&](glm::vec3 p) {
    glm::vec3 d = p - centre;
    float z = glm::dot(d, back);
    distance = std::max({distance, z + std::abs(glm::dot(d, right)) / tan_x,
                         z + std::abs(glm::dot(d, up)) / tan_y});
  });
  if (!(distance > 0.0f)) distance = radius / tan_y;
  distance *= 1.08f;  // a margin around the model
  Camera camera;
  camera.eye = centre + back * distance;
  camera.target = centre;
  camera.up = camera_up;
  camera.fov_y_degrees = framing.fov_y_degrees;
  camera.aspect = aspect;
  camera.near_plane = std::max(distance - radius * 1.5f, distance * 0.001f);
  camera.far_plane = distance + radius * 2.0f;
  return camera;
}

Camera frame_scene(const Scene& scene, float aspect, float fov_y_degrees) {
  Framing framing;
  framing.fov_y_degrees = fov_y_degrees;
  return frame_scene(scene, aspect, framing);
}

Camera scene_camera(const Scene& scene, float aspect) {
  if (scene.framing && aspect != scene.camera.aspect) {
    return frame_scene(scene, aspect, *scene.framing);
  }
  return scene.camera;
}

Camera fit_orthographic(const Scene& scene, const Camera& view, float aspect) {
  const glm::vec3 forward = view.forward();
  const glm::vec3 right = glm::normalize(glm::cross(forward, view.up));
  const glm::vec3 up = glm::cross(right, forward);
  // Every vertex's offsets from the view axis (through the target) set the view's half height,
  // and its depths along the axis where the eye and the clip planes go.
  float half_height = 0.0f, nearest = 1e30f, farthest = -1e30f;
  auto fit = [&](glm::vec3 p) {
    const glm::vec3 d = p - view.target;
    half_height =
        std::max({half_height, std::abs(glm::dot(d, up)), std::abs(glm::dot(d, right)) / aspect});
    nearest = std::min(nearest, glm::dot(d, forward));
    farthest = std::max(farthest, glm::dot(d, forward));
  };
  for_each_world_vertex(scene, fit);
  if (nearest > farthest) {  // no vertices: the box frame_scene frames
    for (int corner = 0; corner < 8; ++corner) {
      fit(glm::vec3(corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f,
                    corner & 4 ? 1.0f : -1.0f));
    }
  }
  const float depth = farthest - nearest;
  const float gap = std::max(0.1f * std::max(depth, half_height), 1e-6f);
  Camera camera = view;
  camera.projection_kind = Projection::orthographic;
  // frame_scene's margin around the model; a point or a line along the axis still gets a view.
  camera.view_height = 2.0f * std::max(half_height * 1.08f, gap * 1e-3f);
  camera.aspect = aspect;
  camera.lens_shift = {};
  camera.eye = view.target + forward * (nearest - gap);
  camera.target = view.target + forward * (nearest + farthest) * 0.5f;
  camera.near_plane = gap * 0.5f;
  camera.far_plane = depth + gap * 1.5f;
  return camera;
}

Camera frame_scene_orthographic(const Scene& scene, float aspect) {
  return fit_orthographic(scene, frame_scene(scene, aspect), aspect);
}

}  // namespace facet
