// Cameras and punctual lights stored in a model file, placed in world space by their nodes.
// Runs once per model at load time (called by import_assimp.cpp after the node hierarchy).
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <optional>
#include <string>
#include <unordered_map>

#include "facet/error.hpp"
#include "import/import_assimp.hpp"

namespace facet::io {
namespace {

constexpr float kDefaultAspect = 16.0f / 9.0f;

// Where a camera or light hangs in the hierarchy (the node with its name).
struct Placement {
  glm::mat4 world{1.0f};
  glm::vec3 node_translation{0.0f};
  bool found = false;
};

Placement placement_of(const std::string& name, const Scene& scene,
                       const std::unordered_map<std::string, int>& node_by_name) {
  Placement p;
  auto it = node_by_name.find(name);
  if (it == node_by_name.end()) return p;
  p.world = scene.world_transform(it->second);
  p.node_translation = glm::vec3(scene.nodes[it->second].transform[3]);
  p.found = true;
  return p;
}

// The object's position relative to its node. glTF cameras and lights sit at their node's
// origin (glTF 2.0 §5.12); assimp before 5.3 also copies the node's translation into
// mPosition (assimp#5054), and its 3DS reader does the same, so a position equal to the node's
// own translation is taken as that copy rather than applied twice.
glm::vec3 local_position(const aiVector3D& position, const Placement& at, bool gltf) {
  glm::vec3 p(position.x, position.y, position.z);
  if (gltf) return glm::vec3(0.0f);
  if (at.found && glm::length(p - at.node_translation) <= 1e-4f * std::max(1.0f, glm::length(p)))
    return glm::vec3(0.0f);
  return p;
}

glm::vec3 world_direction(const aiVector3D& d, const Placement& at, glm::vec3 fallback) {
  glm::vec3 v = glm::mat3(at.world) * glm::vec3(d.x, d.y, d.z);
  float length = glm::length(v);
  return length > 1e-12f && std::isfinite(length) ? v / length : fallback;
}

struct SceneSize {
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
};

SceneSize size_of(const Scene& scene) {
  Bounds b = scene.bounds();
  if (b.empty()) return {};
  return {b.centre(), std::max(glm::length(b.max - b.min) * 0.5f, 1e-6f)};
}

// assimp's readers store the FULL horizontal angle in mHorizontalFOV (glTF: 2·atan(tan(yfov/2)·
// aspect); COLLADA xfov and FBX FieldOfView likewise), although aiCamera's comment says half:
// Cameras.gltf's yfov 0.7 with aspect 1 comes back as 0.7. An aspect of 0 means "unknown";
// assimp's glTF reader then stores yfov itself.
float vertical_fov_degrees(const aiCamera& c) {
  const float horizontal = c.mHorizontalFOV;
  float vertical =
      c.mAspect > 0.0f ? 2.0f * std::atan(std::tan(horizontal * 0.5f) / c.mAspect) : horizontal;
  return std::clamp(glm::degrees(vertical), 1.0f, 170.0f);
}

// aim_at_model: assimp 5.2's 3DS reader overwrites every camera's direction with its node's +Z
// (3DSConverter.cpp), which loses where a 3DS target camera looks; such cameras are aimed at the
// model's centre instead, the usual place a 3DS target sits.
std::optional<Camera> convert_camera(const aiCamera& c, const Placement& at, bool gltf,
                                     bool aim_at_model, const SceneSize& size) {
  // assimp marks an orthographic camera (glTF's "orthographic": xmag, ymag) by a half width
  // and mAspect = width / height.
  const bool orthographic = c.mOrthographicWidth > 0.0f && std::isfinite(c.mOrthographicWidth);
  if (!orthographic && (!(c.mHorizontalFOV > 0.0f) || !std::isfinite(c.mHorizontalFOV)))
    return std::nullopt;
  Camera camera;
  camera.eye = glm::vec3(at.world * glm::vec4(local_position(c.mPosition, at, gltf), 1.0f));
  glm::vec3 forward = world_direction(c.mLookAt, at, glm::vec3(0, 0, -1));
  if (aim_at_model && glm::length(size.centre - camera.eye) > size.radius * 1e-3f) {
    forward = glm::normalize(size.centre - camera.eye);
  }
  glm::vec3 up = world_direction(c.mUp, at, glm::vec3(0, 1, 0));
  if (glm::length(glm::cross(forward, up)) < 1e-3f) {
    up = std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
  }
  // The target only fixes the direction; put it level with the model so orbiting feels right.
  const float ahead = glm::dot(size.centre - camera.eye, forward);
  camera.target = camera.eye + forward * std::max(ahead, size.radius * 0.1f);
  camera.up = up;
  camera.aspect = c.mAspect > 0.0f && std::isfinite(c.mAspect) ? c.mAspect : kDefaultAspect;
  if (orthographic) {
    camera.projection_kind = Projection::orthographic;
    camera.view_height = 2.0f * c.mOrthographicWidth / camera.aspect;
  } else {
    camera.fov_y_degrees = vertical_fov_degrees(c);
  }
  const float distance = glm::length(size.centre - camera.eye);
  camera.near_plane = c.mClipPlaneNear > 0.0f ? c.mClipPlaneNear : size.radius * 1e-3f;
  camera.far_plane =
      c.mClipPlaneFar > camera.near_plane ? c.mClipPlaneFar : (distance + size.radius) * 2.0f;
  camera.validate();
  return camera;
}

bool finite_position(glm::vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Color and intensity: facet keeps the color normalised and the strength apart (glTF's
// importer has already multiplied intensity into the color).
bool split_color(const aiColor3D& c, Light& light) {
  const float strength = std::max({c.r, c.g, c.b});
  if (!(strength > 0.0f) || !std::isfinite(strength)) return false;
  light.color = glm::vec3(c.r, c.g, c.b) / strength;
  light.intensity = strength;
  return true;
}

// facet lights fall off with the inverse square of the distance. A quadratic term maps
// directly; constant or linear-only falloff is matched at the model's centre.
void match_attenuation(const aiLight& l, float distance, Light& light) {
  const float quadratic = l.mAttenuationQuadratic;
  if (quadratic > 0.0f && std::isfinite(quadratic)) {
    light.intensity /= quadratic;
    return;
  }
  float falloff = l.mAttenuationConstant + l.mAttenuationLinear * distance;
  if (!(falloff > 1e-6f) || !std::isfinite(falloff)) falloff = 1.0f;
  light.intensity *= distance * distance / falloff;
}

// glTF spot angles are half-angles and assimp passes them through; every other reader follows
// aiLight's documentation (full angles).
void set_cone(const aiLight& l, bool gltf, Light& light) {
  const float scale = gltf ? 1.0f : 0.5f;
  const float outer = glm::degrees(l.mAngleOuterCone * scale);
  const float inner = glm::degrees(l.mAngleInnerCone * scale);
  if (!(outer > 0.0f && outer <= 90.0f)) return;  // unset (assimp's default is 2 pi)
  light.outer_cone_degrees = outer;
  light.inner_cone_degrees = std::clamp(std::isfinite(inner) ? inner : outer, 0.0f, outer);
}

float gltf_range(const aiScene& ai, const aiLight& l) {
  const aiNode* node = ai.mRootNode ? ai.mRootNode->FindNode(l.mName) : nullptr;
  if (!node || !node->mMetaData) return 0.0f;
  float range = 0.0f;
  double range_double = 0.0;
  if (node->mMetaData->Get("PBR_LightRange", range) && range > 0.0f) return range;
  if (node->mMetaData->Get("PBR_LightRange", range_double) && range_double > 0.0)
    return static_cast<float>(range_double);
  return 0.0f;
}

std::optional<Light> convert_light(const aiScene& ai, const aiLight& l, const Placement& at,
                                   bool gltf, const SceneSize& size) {
  Light light;
  if (!split_color(l.mColorDiffuse, light)) return std::nullopt;
  light.direction = world_direction(l.mDirection, at, light.direction);
  light.position = glm::vec3(at.world * glm::vec4(local_position(l.mPosition, at, gltf), 1.0f));
  switch (l.mType) {
    case aiLightSource_DIRECTIONAL:
      light.type = LightType::directional;
      return light;
    case aiLightSource_SPOT:
      light.type = LightType::spot;
      set_cone(l, gltf, light);
      break;
    case aiLightSource_POINT:
    case aiLightSource_AREA:  // drawn as a point light at its centre: an approximation
      light.type = LightType::point;
      break;
    default:
      return std::nullopt;
  }
  if (!finite_position(light.position)) return std::nullopt;
  if (gltf) {
    light.range = gltf_range(ai, l);
  } else {
    match_attenuation(l, std::max(glm::length(size.centre - light.position), size.radius * 0.1f),
                      light);
  }
  return light;
}

}  // namespace

void import_cameras_and_lights(const aiScene& ai, bool gltf, const std::string& path,
                               const ImportOptions& options,
                               const std::unordered_map<std::string, int>& node_by_name,
                               Scene& scene) {
  const SceneSize size = size_of(scene);
  const bool is_3ds = lower_case(std::filesystem::path(path).extension().string()) == ".3ds";
  for (unsigned i = 0; ai.mCameras && i < ai.mNumCameras; ++i) {
    if (!ai.mCameras[i]) continue;
    const aiCamera& c = *ai.mCameras[i];
    try {
      auto camera =
          convert_camera(c, placement_of(c.mName.C_Str(), scene, node_by_name), gltf, is_3ds, size);
      if (camera)
        scene.cameras.push_back(*camera);
      else
        warn(options, path + ": camera " + std::to_string(i) +
                          " has no field of view and no orthographic size, so it is left out");
    } catch (const Error& e) {
      warn(options, path + ": camera " + std::to_string(i) + " is left out: " + e.what());
    }
  }
  scene.lighting.lights.clear();
  bool ambient_seen = false;
  for (unsigned i = 0; ai.mLights && i < ai.mNumLights; ++i) {
    if (!ai.mLights[i]) continue;
    const aiLight& l = *ai.mLights[i];
    if (l.mType == aiLightSource_AMBIENT) {
      glm::vec3 color(l.mColorAmbient.r, l.mColorAmbient.g, l.mColorAmbient.b);
      if (!ambient_seen) scene.lighting.ambient = glm::vec3(0.0f);
      if (std::isfinite(color.r + color.g + color.b)) scene.lighting.ambient += color;
      ambient_seen = true;
      continue;
    }
    auto light =
        convert_light(ai, l, placement_of(l.mName.C_Str(), scene, node_by_name), gltf, size);
    if (light) scene.lighting.lights.push_back(*light);
  }
  scene.has_file_lights = !scene.lighting.lights.empty();
}

}  // namespace facet::io
