// Cameras from intrinsics (Camera::from_intrinsics): known 3D points, projected by hand with K
// (u = fx X / Z + cx, v = fy Y / Z + cy, OpenCV's pixel centres), are drawn in the pixels
// (round(u), round(v)) under both conventions, with a rotated and translated pose, an
// off-centre principal point and fx != fy; bad intrinsics and poses are named in the error.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/mesh.hpp"
#include "facet/renderer.hpp"

namespace facet::test {
namespace {

constexpr Intrinsics kIntrinsics{180.0f, 150.0f, 70.3f, 41.6f, 160, 96};

// Points in the camera's own frame, OpenCV axes (x right, y down, z forward), all in view.
const std::vector<glm::vec3> kCameraPoints = {
    {0.0f, 0.0f, 4.0f},  {1.0f, 0.5f, 5.0f},  {-0.9f, -0.6f, 3.5f}, {0.3f, 0.8f, 8.0f},
    {-1.5f, 0.9f, 6.0f}, {2.0f, -1.1f, 7.5f}, {2.9f, 1.3f, 6.5f}};

// The pose: turned 30 degrees about y, -20 about x and 10 about z, and moved.
glm::mat4 opencv_pose() {
  glm::mat4 pose = glm::translate(glm::mat4(1.0f), {1.5f, -0.7f, 2.0f});
  pose = glm::rotate(pose, glm::radians(30.0f), {0.0f, 1.0f, 0.0f});
  pose = glm::rotate(pose, glm::radians(-20.0f), {1.0f, 0.0f, 0.0f});
  return glm::rotate(pose, glm::radians(10.0f), {0.0f, 0.0f, 1.0f});
}

// The same camera with OpenGL axes: its y and z axes are OpenCV's negated.
glm::mat4 opengl_pose() {
  return opencv_pose() * glm::scale(glm::mat4(1.0f), {1.0f, -1.0f, -1.0f});
}

glm::vec3 to_world(glm::vec3 camera_point) {
  return glm::vec3(opencv_pose() * glm::vec4(camera_point, 1.0f));
}

// (u, v) of a camera-frame point, by K.
glm::dvec2 project_by_hand(const Intrinsics& k, glm::vec3 p) {
  return {double{k.fx} * p.x / p.z + k.cx, double{k.fy} * p.y / p.z + k.cy};
}

// A marker 3 x 3 pixels around camera-frame point p: the square facing the camera at p's depth
// whose image is [u - 1.5, u + 1.5] x [v - 1.5, v + 1.5]. Its pixel centres, i + 0.5 in window
// coordinates, i.e. u = i, are the three nearest round(u) each way.
Mesh marker(const Intrinsics& k, glm::vec3 p) {
  const float dx = 1.5f * p.z / k.fx, dy = 1.5f * p.z / k.fy;
  Mesh mesh;
  for (glm::vec3 corner : {p + glm::vec3(-dx, -dy, 0), p + glm::vec3(dx, -dy, 0),
                           p + glm::vec3(dx, dy, 0), p + glm::vec3(-dx, dy, 0)}) {
    mesh.positions.push_back(to_world(corner));
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

glm::vec4 marker_color(std::size_t i) {
  return {(i + 1) & 1 ? 1.0f : 0.0f, (i + 1) & 2 ? 1.0f : 0.0f, (i + 1) & 4 ? 1.0f : 0.25f, 1.0f};
}

void expect_points_at_their_pixels(const Camera& camera, const Intrinsics& k) {
  const std::size_t count = kCameraPoints.size();
  std::vector<Mesh> markers;
  for (glm::vec3 p : kCameraPoints) markers.push_back(marker(k, p));
  Renderer renderer;
  Framebuffer image(k.width, k.height, ColorFormat::rgba32f);
  renderer.begin_frame(camera);
  std::vector<Material> materials(count);
  for (std::size_t i = 0; i < count; ++i) {
    materials[i].shading = ShadingModel::unlit;
    materials[i].cull = CullMode::none;
    materials[i].base_color = marker_color(i);
    renderer.draw(markers[i], materials[i]);
  }
  renderer.finish(image);

  const glm::mat4 view_projection = camera.view_projection();
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec2 uv = project_by_hand(k, kCameraPoints[i]);
    // Rounding must be clear-cut for the test to mean anything.
    ASSERT_GT(std::abs(uv.x - std::floor(uv.x) - 0.5), 0.05) << uv.x;
    ASSERT_GT(std::abs(uv.y - std::floor(uv.y) - 0.5), 0.05) << uv.y;
    const long expected_x = std::lround(uv.x), expected_y = std::lround(uv.y);

    // The window coordinates the camera's matrices give: (u + 0.5, v + 0.5).
    const glm::vec4 clip = view_projection * glm::vec4(to_world(kCameraPoints[i]), 1.0f);
    const double window_x = (clip.x / clip.w + 1.0) * 0.5 * k.width;
    const double window_y = (1.0 - clip.y / clip.w) * 0.5 * k.height;
    EXPECT_NEAR(window_x, uv.x + 0.5, 1e-3) << "point " << i;
    EXPECT_NEAR(window_y, uv.y + 0.5, 1e-3) << "point " << i;

    // The marker's pixels: 9 of them, centred on (round(u), round(v)).
    long sum_x = 0, sum_y = 0, pixels = 0;
    for (int y = 0; y < k.height; ++y) {
      for (int x = 0; x < k.width; ++x) {
        if (glm::all(
                glm::lessThan(glm::abs(image.pixel(x, y) - marker_color(i)), glm::vec4(1e-3f)))) {
          sum_x += x, sum_y += y, ++pixels;
        }
      }
    }
    ASSERT_EQ(pixels, 9) << "point " << i << " at (" << uv.x << ", " << uv.y << ")";
    EXPECT_EQ(sum_x, 9 * expected_x) << "point " << i << ": u = " << uv.x;
    EXPECT_EQ(sum_y, 9 * expected_y) << "point " << i << ": v = " << uv.y;
    // And drawn at its depth in front of the camera.
    EXPECT_NEAR(camera.view_distance(image.depth_at(expected_x, expected_y)), kCameraPoints[i].z,
                kCameraPoints[i].z * 1e-4f)
        << "point " << i;
  }
}

TEST(CameraIntrinsics, OpenCvPoseDrawsPointsAtThePixelsKGives) {
  expect_points_at_their_pixels(
      Camera::from_intrinsics(kIntrinsics, opencv_pose(), CameraConvention::opencv, 0.5f, 50.0f),
      kIntrinsics);
}

TEST(CameraIntrinsics, OpenGlPoseDrawsPointsAtThePixelsKGives) {
  expect_points_at_their_pixels(
      Camera::from_intrinsics(kIntrinsics, opengl_pose(), CameraConvention::opengl, 0.5f, 50.0f),
      kIntrinsics);
}

// With the identity as the pose the camera is at the origin: an OpenCV camera looks down +Z
// with y down, an OpenGL one down -Z with y up; (cx, cy) is where the axis lands.
TEST(CameraIntrinsics, IdentityPoseLooksDownEachConventionsAxis) {
  const Intrinsics k{100.0f, 120.0f, 30.25f, 20.75f, 64, 48};
  struct Case {
    CameraConvention convention;
    glm::vec3 world;  // (0.5, 0.25, 2) in OpenCV camera axes
  };
  for (const Case& c : {Case{CameraConvention::opencv, {0.5f, 0.25f, 2.0f}},
                        Case{CameraConvention::opengl, {0.5f, -0.25f, -2.0f}}}) {
    const Camera camera = Camera::from_intrinsics(k, glm::mat4(1.0f), c.convention, 0.1f, 10.0f);
    const glm::vec4 clip = camera.view_projection() * glm::vec4(c.world, 1.0f);
    EXPECT_NEAR((clip.x / clip.w + 1.0f) * 0.5f * k.width, 100.0f * 0.25f + 30.25f + 0.5f, 1e-3f);
    EXPECT_NEAR((1.0f - clip.y / clip.w) * 0.5f * k.height, 120.0f * 0.125f + 20.75f + 0.5f, 1e-3f);
    EXPECT_NEAR(clip.w, 2.0f, 1e-5f);  // in front, 2 away
  }
}

// The error for a bad value, or "" if from_intrinsics accepts it.
std::string error_of(const Intrinsics& k, const glm::mat4& pose = glm::mat4(1.0f),
                     float near_plane = 0.1f, float far_plane = 10.0f) {
  try {
    Camera::from_intrinsics(k, pose, CameraConvention::opencv, near_plane, far_plane);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(CameraIntrinsics, BadValuesAreNamed) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Intrinsics good{100.0f, 100.0f, 31.5f, 23.5f, 64, 48};
  EXPECT_EQ(error_of(good), "");
  struct Case {
    Intrinsics k;
    const char* says;
  };
  for (const Case& c : {
           Case{{0.0f, 100.0f, 31.5f, 23.5f, 64, 48}, "fx must be a positive, finite focal"},
           Case{{-5.0f, 100.0f, 31.5f, 23.5f, 64, 48}, "fx must be a positive"},
           Case{{nan, 100.0f, 31.5f, 23.5f, 64, 48}, "fx must be a positive"},
           Case{{100.0f, 0.0f, 31.5f, 23.5f, 64, 48}, "fy must be a positive"},
           Case{{100.0f, inf, 31.5f, 23.5f, 64, 48}, "fy must be a positive"},
           Case{{100.0f, 100.0f, nan, 23.5f, 64, 48}, "principal point (cx, cy) must be finite"},
           Case{{100.0f, 100.0f, 31.5f, inf, 64, 48}, "principal point (cx, cy) must be finite"},
           Case{{100.0f, 100.0f, 31.5f, 23.5f, 0, 48}, "width and height must be at least 1"},
           Case{{100.0f, 100.0f, 31.5f, 23.5f, 64, -2}, "width and height must be at least 1"},
           Case{{1e-9f, 1e-9f, 31.5f, 23.5f, 64, 48}, "too short"},
       }) {
    const std::string error = error_of(c.k);
    EXPECT_NE(error.find("camera intrinsics: "), std::string::npos) << error;
    EXPECT_NE(error.find(c.says), std::string::npos) << error << " (wanted: " << c.says << ")";
  }
  EXPECT_NE(error_of(good, glm::mat4(1.0f), 0.0f).find("near plane must be positive"),
            std::string::npos);
  EXPECT_NE(error_of(good, glm::mat4(1.0f), 1.0f, 1.0f).find("must be beyond the near plane"),
            std::string::npos);
  EXPECT_NE(error_of(good, glm::mat4(1.0f), 1.0f, inf).find("must be beyond the near plane"),
            std::string::npos);
}

TEST(CameraIntrinsics, PosesThatAreNotRigidAreRefused) {
  const Intrinsics k{100.0f, 100.0f, 31.5f, 23.5f, 64, 48};
  const glm::mat4 rotated = glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
  EXPECT_EQ(error_of(k, glm::translate(rotated, {1.0f, 2.0f, 3.0f})), "");
  glm::mat4 nan_pose = rotated;
  nan_pose[3][1] = std::numeric_limits<float>::quiet_NaN();
  glm::mat4 projective = rotated;
  projective[2][3] = 0.5f;
  struct Case {
    glm::mat4 pose;
    const char* says;
  };
  for (const Case& c : {
           Case{glm::scale(rotated, glm::vec3(1.02f)), "not orthonormal"},
           Case{glm::scale(rotated, {1.0f, 1.0f, 3.0f}), "not orthonormal"},
           Case{glm::mat4(glm::mat3(1.0f, 0.3f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f)),
                "not orthonormal"},  // sheared
           Case{glm::scale(rotated, {1.0f, -1.0f, 1.0f}), "reflection"},
           Case{nan_pose, "not finite"},
           Case{projective, "last row"},
       }) {
    const std::string error = error_of(k, c.pose);
    EXPECT_NE(error.find("camera pose (camera_to_world) "), std::string::npos) << error;
    EXPECT_NE(error.find(c.says), std::string::npos) << error << " (wanted: " << c.says << ")";
  }
}

}  // namespace
}  // namespace facet::test
