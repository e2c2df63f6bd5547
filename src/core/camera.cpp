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

Camera Camera::orthographic(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float view_height,
                            float aspect, float near_plane, float far_plane) {
  Camera camera{eye, target, up};
  camera.projection_kind = Projection::orthographic;
  camera.view_height = view_height;
  camera.aspect = aspect;
  camera.near_plane = near_plane;
  camera.far_plane = far_plane;
  return camera;
}

glm::mat4 Camera::view() const { return glm::lookAtRH(eye, target, up); }

float Camera::view_distance(float window_depth) const {
  // Window depth d = (ndc_z + 1) / 2. An orthographic projection's ndc_z is linear in the
  // distance D, -1 at near and 1 at far; glm's perspective one is
  // ndc_z = (f + n) / (f - n) - 2 f n / ((f - n) D). Each solved for D.
  const double n = near_plane, f = far_plane, d = window_depth;
  if (projection_kind == Projection::orthographic) return static_cast<float>(n + d * (f - n));
  return static_cast<float>(n * f / (f - d * (f - n)));
}

glm::mat4 Camera::projection() const {
  // Both map view-space depth [-near, -far] to clip z in [-w, w] (OpenGL). The lens shift moves
  // where the view axis lands in NDC: clip w is -z in perspective, so a shift s needs -s z
  // added to clip x (column 2), and w is 1 in orthographic, so s itself (column 3).
  glm::mat4 p;
  if (projection_kind == Projection::orthographic) {
    const float half_height = view_height * 0.5f, half_width = half_height * aspect;
    p = glm::orthoRH_NO(-half_width, half_width, -half_height, half_height, near_plane, far_plane);
    p[3][0] += lens_shift.x;
    p[3][1] += lens_shift.y;
  } else {
    p = glm::perspectiveRH_NO(glm::radians(fov_y_degrees), aspect, near_plane, far_plane);
    p[2][0] -= lens_shift.x;
    p[2][1] -= lens_shift.y;
  }
  return p;
}

glm::vec3 Camera::forward() const { return glm::normalize(target - eye); }
glm::vec3 Camera::right() const { return glm::normalize(glm::cross(forward(), up)); }

glm::vec3 Camera::shading_eye() const {
  if (projection_kind != Projection::orthographic) return eye;
  // Every point in view lies within `size` of the eye: far_plane along the axis, and the
  // view's half height and half width (more with a lens shift) across it.
  const float size = far_plane + view_height * (1.0f + std::abs(lens_shift.y) +
                                                aspect * (1.0f + std::abs(lens_shift.x)));
  return eye - forward() * (1e4f * size);
}

void Camera::validate() const {
  const bool orthographic = projection_kind == Projection::orthographic;
  std::ostringstream problem;
  if (!finite(eye) || !finite(target) || !finite(up)) {
    problem << "eye, target and up must be finite";
  } else if (projection_kind != Projection::perspective && !orthographic) {
    problem << "projection_kind " << static_cast<int>(projection_kind) << " is not a projection";
  } else if (!orthographic && !(fov_y_degrees > 0.0f && fov_y_degrees < 180.0f)) {
    problem << "field of view must be between 0 and 180 degrees, got " << fov_y_degrees;
  } else if (orthographic && (!(view_height > 0.0f) || !std::isfinite(view_height))) {
    problem << "view_height must be positive, got " << view_height;
  } else if (!(aspect > 0.0f) || !std::isfinite(aspect)) {
    problem << "aspect must be positive, got " << aspect;
  } else if (!orthographic && (!(near_plane > 0.0f) || !std::isfinite(near_plane))) {
    problem << "near plane must be positive, got " << near_plane;
  } else if (orthographic && (!(near_plane >= 0.0f) || !std::isfinite(near_plane))) {
    problem << "near plane must not be negative, got " << near_plane;
  } else if (!(far_plane > near_plane) || !std::isfinite(far_plane)) {
    problem << "far plane (" << far_plane << ") must be beyond the near plane (" << near_plane
            << ")";
  } else if (!std::isfinite(lens_shift.x) || !std::isfinite(lens_shift.y)) {
    problem << "lens_shift must be finite";
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
