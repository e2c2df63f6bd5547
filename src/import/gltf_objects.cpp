// Node transforms, cameras and KHR_lights_punctual lights of a glTF file (gltf_internal.hpp).
// Runs once per model at load time, after the node hierarchy is built (gltf_scene.cpp).
//
// A camera or light sits at its node's origin, looking (or shining) down the node's -Z with +Y
// up (glTF 2.0 §3.10, KHR_lights_punctual). Perspective cameras keep their yfov and aspect;
// an orthographic camera's xmag and ymag are half its width and height.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <optional>
#include <string>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

constexpr float kDefaultAspect = 16.0f / 9.0f;

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

struct SceneSize {
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
};

SceneSize size_of(const Scene& scene) {
  const Bounds b = scene.bounds();
  if (b.empty()) return {};
  return {b.centre(), std::max(glm::length(b.max - b.min) * 0.5f, 1e-6f)};
}

glm::vec3 direction(const glm::mat4& world, glm::vec3 local, glm::vec3 fallback) {
  const glm::vec3 v = glm::mat3(world) * local;
  const float length = glm::length(v);
  return length > 1e-12f && std::isfinite(length) ? v / length : fallback;
}

std::optional<Camera> convert_camera(const tinygltf::Camera& c, const glm::mat4& world,
                                     const SceneSize& size) {
  const bool orthographic = c.type == "orthographic";
  const double znear = orthographic ? c.orthographic.znear : c.perspective.znear;
  const double zfar = orthographic ? c.orthographic.zfar : c.perspective.zfar;
  Camera camera;
  camera.eye = glm::vec3(world[3]);
  const glm::vec3 forward = direction(world, glm::vec3(0, 0, -1), glm::vec3(0, 0, -1));
  glm::vec3 up = direction(world, glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
  if (glm::length(glm::cross(forward, up)) < 1e-3f)
    up = std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
  // The target only fixes the direction; put it level with the model so orbiting feels right.
  const float ahead = glm::dot(size.centre - camera.eye, forward);
  camera.target = camera.eye + forward * std::max(ahead, size.radius * 0.1f);
  camera.up = up;
  if (orthographic) {
    const auto xmag = static_cast<float>(std::abs(c.orthographic.xmag));
    const auto ymag = static_cast<float>(std::abs(c.orthographic.ymag));
    if (!(xmag > 0.0f) || !(ymag > 0.0f) || !std::isfinite(xmag / ymag)) return std::nullopt;
    camera.projection_kind = Projection::orthographic;
    camera.aspect = xmag / ymag;
    camera.view_height = 2.0f * ymag;
  } else {
    const auto yfov = static_cast<float>(c.perspective.yfov);
    if (!(yfov > 0.0f) || !std::isfinite(yfov)) return std::nullopt;
    camera.fov_y_degrees = std::clamp(glm::degrees(yfov), 1.0f, 170.0f);
    const auto aspect = static_cast<float>(c.perspective.aspectRatio);
    camera.aspect = aspect > 0.0f && std::isfinite(aspect) ? aspect : kDefaultAspect;
  }
  const float distance = glm::length(size.centre - camera.eye);
  camera.near_plane = znear > 0.0 && std::isfinite(znear) ? static_cast<float>(znear)
                      : orthographic                      ? 0.0f
                                                          : size.radius * 1e-3f;
  camera.far_plane = zfar > znear && std::isfinite(zfar) ? static_cast<float>(zfar)
                                                         : (distance + size.radius) * 2.0f;
  camera.validate();
  return camera;
}

std::optional<Light> convert_light(const tinygltf::Light& l, const glm::mat4& world) {
  Light light;
  glm::vec3 color(1.0f);
  for (std::size_t i = 0; i < 3 && i < l.color.size(); ++i)
    color[static_cast<int>(i)] = static_cast<float>(l.color[i]);
  // facet keeps the color normalised and the strength apart.
  const float strength = std::max({color.r, color.g, color.b}) * static_cast<float>(l.intensity);
  if (!(strength > 0.0f) || !std::isfinite(strength)) return std::nullopt;
  light.color = glm::max(color, glm::vec3(0.0f)) / std::max({color.r, color.g, color.b});
  light.intensity = strength;
  light.direction = direction(world, glm::vec3(0, 0, -1), light.direction);
  light.position = glm::vec3(world[3]);
  if (l.type == "directional") {
    light.type = LightType::directional;
    return light;
  }
  if (l.type == "spot") {
    light.type = LightType::spot;
    const float outer = glm::degrees(static_cast<float>(l.spot.outerConeAngle));
    const float inner = glm::degrees(static_cast<float>(l.spot.innerConeAngle));
    if (outer > 0.0f && outer <= 90.0f) {
      light.outer_cone_degrees = outer;
      light.inner_cone_degrees = std::clamp(std::isfinite(inner) ? inner : 0.0f, 0.0f, outer);
    }
  } else if (l.type == "point") {
    light.type = LightType::point;
  } else {
    return std::nullopt;
  }
  if (l.range > 0.0 && std::isfinite(l.range)) light.range = static_cast<float>(l.range);
  return light;
}

int light_of(const tinygltf::Node& node) {
  auto it = node.extensions.find("KHR_lights_punctual");
  if (it == node.extensions.end()) return -1;
  const tinygltf::Value& index = it->second.Get("light");
  return index.IsInt() ? index.GetNumberAsInt() : -1;
}

}  // namespace

glm::mat4 gltf_node_transform(const tinygltf::Node& node, const std::string& where) {
  glm::mat4 m(1.0f);
  if (node.matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = static_cast<float>(node.matrix[i]);  // columns
  } else {
    glm::vec3 t(0.0f), s(1.0f);
    glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
    if (node.translation.size() == 3)
      t = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
    if (node.scale.size() == 3) s = glm::vec3(node.scale[0], node.scale[1], node.scale[2]);
    if (node.rotation.size() == 4) {  // x, y, z, w
      r = glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                    static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
      const float length = glm::length(r);
      if (length > 1e-12f) r /= length;
    }
    m = glm::mat4_cast(r);
    m[0] *= s.x;
    m[1] *= s.y;
    m[2] *= s.z;
    m[3] = glm::vec4(t, 1.0f);
  }
  if (!finite(m)) throw Error(where + ": its transform is not finite");
  return m;
}

void import_gltf_cameras_and_lights(const GltfFile& file, const std::vector<int>& node_of,
                                    const ImportOptions& options, Scene& scene) {
  const SceneSize size = size_of(scene);
  const auto& model = file.model;
  const std::size_t nodes = std::min(model.nodes.size(), node_of.size());
  // In the file's order of cameras and lights, each once for every node in the scene using it.
  for (std::size_t c = 0; c < model.cameras.size(); ++c) {
    for (std::size_t i = 0; i < nodes; ++i) {
      if (node_of[i] < 0 || model.nodes[i].camera != static_cast<int>(c)) continue;
      const std::string what = file.path + ": camera " + std::to_string(c);
      try {
        auto camera = convert_camera(model.cameras[c], scene.world_transform(node_of[i]), size);
        if (camera)
          scene.cameras.push_back(*camera);
        else
          warn(options, what + " has no field of view or no orthographic size, so it is left out");
      } catch (const Error& e) {
        warn(options, what + " is left out: " + e.what());
      }
    }
  }
  scene.lighting.lights.clear();
  for (std::size_t l = 0; l < model.lights.size(); ++l) {
    for (std::size_t i = 0; i < nodes; ++i) {
      if (node_of[i] < 0 || light_of(model.nodes[i]) != static_cast<int>(l)) continue;
      if (auto light = convert_light(model.lights[l], scene.world_transform(node_of[i])))
        scene.lighting.lights.push_back(*light);
    }
  }
  scene.has_file_lights = !scene.lighting.lights.empty();
}

}  // namespace facet::io
