// Camera math: view and projection matrices (OpenGL conventions), first-person camera.
#include "facet/camera.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/norm.hpp>
#include <sstream>

#include "facet/error.hpp"

namespace facet {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Camera Camera::look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fov_y_degrees,
                       float aspect, float near_plane, float far_plane) {
  return Camera{eye, target, up, fov_y_degrees, aspect, near_plane, far_plane};
}

glm::mat4 Camera::view() const { return glm::lookAtRH(eye, target, up); }

float Camera::view_distance(float window_depth) const {
  // Window depth d = (ndc_z + 1) / 2, and glm's OpenGL projection gives
  // ndc_z = (f + n) / (f - n) - 2 f n / ((f - n) D) at distance D: solved for D.
  const double n = near_plane, f = far_plane;
  return static_cast<float>(n * f / (f - double{window_depth} * (f - n)));
}

glm::mat4 Camera::projection() const {
  // Maps view-space depth [-near, -far] to clip z in [-w, w] (OpenGL).
  return glm::perspectiveRH_NO(glm::radians(fov_y_degrees), aspect, near_plane, far_plane);
}

glm::vec3 Camera::forward() const { return glm::normalize(target - eye); }
glm::vec3 Camera::right() const { return glm::normalize(glm::cross(forward(), up)); }

void Camera::validate() const {
  std::ostringstream problem;
  if (!finite(eye) || !finite(target) || !finite(up)) {
    problem << "eye, target and up must be finite";
  } else if (!(fov_y_degrees > 0.0f && fov_y_degrees < 180.0f)) {
    problem << "field of view must be between 0 and 180 degrees, got " << fov_y_degrees;
  } else if (!(aspect > 0.0f) || !std::isfinite(aspect)) {
    problem << "aspect must be positive, got " << aspect;
  } else if (!(near_plane > 0.0f) || !std::isfinite(near_plane)) {
    problem << "near plane must be positive, got " << near_plane;
  } else if (!(far_plane > near_plane) || !std::isfinite(far_plane)) {
    problem << "far plane (" << far_plane << ") must be beyond the near plane (" << near_plane
            << ")";
  } else if (glm::length2(target - eye) == 0.0f) {
    problem << "eye and target are the same point";
  } else if (glm::length2(glm::cross(target - eye, up)) <=
             1e-12f * glm::length2(target - eye) * glm::length2(up)) {
    problem << "up is parallel to the view direction (or zero)";
  }
  if (!problem.str().empty()) throw Error("camera: " + problem.str());
}

glm::vec3 FirstPersonCamera::forward() const {
  float yaw = glm::radians(yaw_degrees);
  float pitch = glm::radians(glm::clamp(pitch_degrees, -89.0f, 89.0f));
  // yaw 0 looks down -Z; positive yaw turns left (counter-clockwise seen from above).
  return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::vec3 FirstPersonCamera::right() const {
  float yaw = glm::radians(yaw_degrees);
  return {std::cos(yaw), 0.0f, -std::sin(yaw)};
}

Camera FirstPersonCamera::camera(float fov_y_degrees, float aspect, float near_plane,
                                 float far_plane) const {
  return Camera::look_at(position, position + forward(), {0.0f, 1.0f, 0.0f}, fov_y_degrees, aspect,
                         near_plane, far_plane);
}

}  // namespace facet
