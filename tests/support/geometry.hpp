// Test geometry: world positions for given screen pixels, and ray casting against triangles
// for analytic expected images.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <optional>

namespace facet::test {

// World point at view distance `distance` on the ray through screen position (sx, sy) in
// pixels, for test_camera(width, height, fov): eye at the origin looking down -Z.
inline glm::vec3 at_pixel(double sx, double sy, int width, int height, double distance,
                          double fov_degrees = 60.0) {
  double t = std::tan(fov_degrees * 3.14159265358979323846 / 360.0);
  double aspect = static_cast<double>(width) / height;
  double x = (2.0 * sx / width - 1.0) * distance * t * aspect;
  double y = (1.0 - 2.0 * sy / height) * distance * t;
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(-distance)};
}

// Direction of the ray through pixel centre (px + 0.5, py + 0.5) for the same camera.
inline glm::dvec3 pixel_ray(int px, int py, int width, int height, double fov_degrees = 60.0) {
  glm::vec3 p = at_pixel(px + 0.5, py + 0.5, width, height, 1.0, fov_degrees);
  return glm::dvec3(p);
}

// Ray (from the origin) / triangle intersection distance along dir (Moller-Trumbore), with
// the barycentric margin: how far inside the triangle the hit is (negative: outside).
struct RayHit {
  double t;
  double margin;
};
inline std::optional<RayHit> intersect(glm::dvec3 dir, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  glm::dvec3 e1 = b - a, e2 = c - a;
  glm::dvec3 p = glm::cross(dir, e2);
  double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12) return std::nullopt;
  glm::dvec3 s = -a;
  double u = glm::dot(s, p) / det;
  glm::dvec3 q = glm::cross(s, e1);
  double v = glm::dot(dir, q) / det;
  double t = glm::dot(e2, q) / det;
  return RayHit{t, std::min({u, v, 1.0 - u - v})};
}

}  // namespace facet::test
