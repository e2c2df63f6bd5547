// Cameras from a calibration: intrinsics (K) and a camera-to-world pose in the OpenCV or OpenGL
// convention, turned into Camera's view and projection (derivation in docs/cameras.md).
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <sstream>
#include <string>

#include "facet/camera.hpp"
#include "facet/error.hpp"

namespace facet {
namespace {

// How far R^T R of a pose's rotation part may stray from the identity: loose enough for poses
// rounded to a few decimals or to float, tight enough to refuse a scaled pose.
constexpr float kRigidTolerance = 1e-3f;

// Throws unless camera_to_world is finite, has (0, 0, 0, 1) as its last row and a rotation
// (orthonormal, determinant +1) as its upper 3x3.
void check_rigid(const glm::mat4& m) {
  std::ostringstream problem;
  bool finite = true;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(m[c][r]);
  }
  const glm::mat3 rotation(m);
  const glm::mat3 gram = glm::transpose(rotation) * rotation;
  float error = 0.0f;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) error = std::max(error, std::abs(gram[c][r] - (c == r ? 1 : 0)));
  }
  if (!finite) {
    problem << "has a value that is not finite";
  } else if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f) {
    problem << "must have 0, 0, 0, 1 as its last row, got " << m[0][3] << ", " << m[1][3] << ", "
            << m[2][3] << ", " << m[3][3];
  } else if (error > kRigidTolerance) {
    problem << "must be a rotation and a translation: its 3x3 part is not orthonormal (R^T R "
               "is off the identity by "
            << error << ": a scale or shear?)";
  } else if (glm::determinant(rotation) < 0.0f) {
    problem << "is a reflection (determinant -1), not a rotation: the axes of both conventions "
               "are right-handed";
  }
  if (!problem.str().empty()) throw Error("camera pose (camera_to_world) " + problem.str());
}

}  // namespace

void Intrinsics::validate() const {
  std::ostringstream problem;
  if (!(fx > 0.0f) || !std::isfinite(fx)) {
    problem << "fx must be a positive, finite focal length in pixels, got " << fx;
  } else if (!(fy > 0.0f) || !std::isfinite(fy)) {
    problem << "fy must be a positive, finite focal length in pixels, got " << fy;
  } else if (!std::isfinite(cx) || !std::isfinite(cy)) {
    problem << "the principal point (cx, cy) must be finite, got " << cx << ", " << cy;
  } else if (width < 1 || height < 1) {
    problem << "width and height must be at least 1, got " << width << " x " << height;
  }
  if (!problem.str().empty()) throw Error("camera intrinsics: " + problem.str());
}

Camera Camera::from_intrinsics(const Intrinsics& k, const glm::mat4& camera_to_world,
                               CameraConvention convention, float near_plane, float far_plane) {
  k.validate();
  check_rigid(camera_to_world);
  // The camera's axes in the world are the pose's columns. OpenCV: z forward, y down;
  // OpenGL: -z forward, y up.
  const bool opencv = convention == CameraConvention::opencv;
  const glm::vec3 y_axis(camera_to_world[1]), z_axis(camera_to_world[2]);
  Camera camera;
  camera.eye = glm::vec3(camera_to_world[3]);
  camera.target = camera.eye + (opencv ? z_axis : -z_axis);
  camera.up = opencv ? -y_axis : y_axis;
  // With the pinhole u = fx X / Z + cx (OpenCV axes), pixel i's centre at u = i and window
  // x = u + 0.5 = (ndc_x + 1) W / 2, and window y = v + 0.5 = (1 - ndc_y) H / 2 (y down):
  //   ndc_x = (2 fx / W) X / Z + (2 cx + 1 - W) / W,
  //   ndc_y = (2 fy / H) (-Y) / Z + (H - 1 - 2 cy) / H.
  // glm's perspective scales by 1 / tan(fov / 2) vertically and that over aspect horizontally,
  // so tan(fov / 2) = H / (2 fy) and aspect = (2 fy / H) / (2 fx / W); the constant terms are
  // the lens shift.
  const double w = k.width, h = k.height;
  camera.fov_y_degrees = static_cast<float>(glm::degrees(2.0 * std::atan(h / (2.0 * k.fy))));
  camera.aspect = static_cast<float>(w * k.fy / (h * k.fx));
  if (!(camera.fov_y_degrees < 180.0f) || !std::isfinite(camera.aspect) ||
      !(camera.aspect > 0.0f)) {
    // Only focal lengths of a millionth of the image or so get here.
    throw Error("camera intrinsics: fx, fy (" + std::to_string(k.fx) + ", " + std::to_string(k.fy) +
                ") are too short for a " + std::to_string(k.width) + " x " +
                std::to_string(k.height) + " image: the view would reach 180 degrees");
  }
  camera.calibrated_size = {k.width, k.height};
  camera.lens_shift = {static_cast<float>((2.0 * k.cx + 1.0 - w) / w),
                       static_cast<float>((h - 1.0 - 2.0 * k.cy) / h)};
  camera.near_plane = near_plane;
  camera.far_plane = far_plane;
  camera.validate();
  return camera;
}

}  // namespace facet
