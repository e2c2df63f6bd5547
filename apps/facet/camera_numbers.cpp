// Camera values from the command line checked against float limits (camera_numbers.hpp).
// Distances are computed in double here, so the check itself cannot overflow.
#include "camera_numbers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "facet/error.hpp"

namespace facet::cli {
namespace {

double distance_between(glm::vec3 a, glm::vec3 b) {
  const double x = double(a.x) - b.x, y = double(a.y) - b.y, z = double(a.z) - b.z;
  return std::sqrt(x * x + y * y + z * z);
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

void check_camera_numbers(const SceneOptions& o, const Scene& scene, const Camera& camera) {
  const Bounds bounds = scene.bounds();
  if (o.eye && !bounds.empty()) {
    const double radius = std::max(distance_between(bounds.max, bounds.min) * 0.5, 1e-6);
    const double away = distance_between(camera.eye, bounds.centre());
    if (away > kMaxEyeDistanceInRadii * radius) {
      throw Error("--eye: " + *o.eye + " is " + number(away) + " from the scene, " +
                  number(away / radius) + " times its radius (" + number(radius) + "); at most " +
                  number(kMaxEyeDistanceInRadii) +
                  " radii leave 32-bit depth enough steps to draw it");
    }
  }
  if (o.eye || o.target) {
    const double apart = distance_between(camera.eye, camera.target);
    if (apart > kMaxEyeTargetDistance) {
      const std::string flags = o.eye && o.target ? "--eye and --target"
                                : o.eye           ? "--eye"
                                                  : "--target";
      throw Error(flags + ": the eye and the target are " + number(apart) +
                  " apart; the camera squares that distance, so it must stay below " +
                  number(kMaxEyeTargetDistance) +
                  " (a closer target on the same line looks the same way)");
    }
  }
  if ((o.near_plane || o.far_plane) && camera.projection_kind == Projection::perspective &&
      camera.near_plane > 0.0f && camera.far_plane > camera.near_plane) {
    const double ratio = double(camera.far_plane) / camera.near_plane;
    if (ratio > kMaxFarNearRatio) {
      const std::string near = o.near_plane ? "--near " + number(camera.near_plane)
                                            : "the near plane " + number(camera.near_plane);
      const std::string far = o.far_plane ? "--far " + number(camera.far_plane)
                                          : "the far plane " + number(camera.far_plane);
      throw Error(near + " and " + far + ": far is " + number(ratio) + " times near, beyond the " +
                  number(kMaxFarNearRatio) +
                  " a 32-bit depth buffer resolves (depth rounds to 1 and nothing is drawn): "
                  "raise --near or lower --far");
    }
  }
}

}  // namespace facet::cli
