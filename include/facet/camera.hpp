// Camera: where the eye is and how it projects — perspective, orthographic, or from a calibrated
// camera's intrinsics (docs/cameras.md). Also a first-person (yaw/pitch) camera form.
#pragma once

#include <glm/ext/vector_int2.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace facet {

enum class Projection {
  perspective,   // a pinhole: fov_y_degrees wide, things shrink with distance
  orthographic,  // parallel rays: view_height scene units tall at every distance
};

// How a camera-to-world pose's axes are read (docs/cameras.md has a figure).
enum class CameraConvention {
  opencv,  // camera frame x right, y down, z forward (OpenCV, COLMAP, ROS optical frames)
  opengl,  // x right, y up, looking down -z (OpenGL, Blender, NeRF's transforms.json)
};

// A pinhole camera's calibration, in pixels. Pixel coordinates (u, v) run right and down from
// the top-left, with OpenCV's pixel-centre convention: pixel (i, j)'s centre is at (u, v) =
// (i, j). A point at (X, Y, Z) in the camera frame (OpenCV axes, Z > 0 in front) lands at
// u = fx X / Z + cx, v = fy Y / Z + cy, so it is drawn in pixel (round(u), round(v)) of a
// width x height framebuffer. K = [fx 0 cx; 0 fy cy; 0 0 1] whichever the pose's convention.
struct Intrinsics {
  float fx = 0.0f, fy = 0.0f;  // focal lengths, > 0
  float cx = 0.0f, cy = 0.0f;  // principal point (the centre of the image is (w - 1) / 2)
  int width = 0, height = 0;   // the image the calibration is for, >= 1 each

  // Throws facet::Error naming the first bad field (a focal length that is not positive and
  // finite, a non-finite principal point, a size below 1).
  void validate() const;
};

// The view: eye, target and up (right-handed, the view space looks down -Z with +Y up) and a
// projection to OpenGL clip space (clip z in [-w, w]); the renderer maps NDC to window
// coordinates with y down, pixel (x, y)'s centre at (x + 0.5, y + 0.5).
struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 60.0f;  // vertical field of view (perspective)
  // Width / height of the view. A camera from intrinsics has W fy / (H fx), right for a W x H
  // framebuffer only: code that sets aspect to another framebuffer's (the CLI, the viewer)
  // would stretch it; scale the intrinsics instead.
  float aspect = 16.0f / 9.0f;
  float near_plane = 0.1f;  // > 0 (perspective) or >= 0 (orthographic), along the view axis
  float far_plane = 100.0f;
  Projection projection_kind = Projection::perspective;
  float view_height = 2.0f;  // orthographic: the view's height in scene units
  // Where the optical axis meets the image, in NDC ((0, 0) is the centre, +y up): an off-centre
  // principal point. It moves the image, not the eye, as a shift lens does.
  glm::vec2 lens_shift{0.0f};
  // The image a camera from intrinsics is calibrated for (Intrinsics::width and height); (0, 0)
  // for the others, which fit an image of any size through their aspect.
  glm::ivec2 calibrated_size{0};

  static Camera look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up = {0, 1, 0},
                        float fov_y_degrees = 60.0f, float aspect = 16.0f / 9.0f,
                        float near_plane = 0.1f, float far_plane = 100.0f);
  // A parallel projection looking from eye toward target whose view is view_height scene units
  // tall (view_height * aspect wide) at every distance.
  static Camera orthographic(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float view_height,
                             float aspect, float near_plane, float far_plane);
  // The camera a calibration describes, for a k.width x k.height framebuffer: a camera-frame
  // point projects as Intrinsics says. camera_to_world is the pose, a rigid transform (rotation
  // and translation, no scale) whose axes `convention` names; the identity puts the camera at
  // the origin looking down +Z (OpenCV) or -Z (OpenGL). Throws facet::Error naming the bad
  // field: the intrinsics, a pose that is not rigid or not finite, near or far.
  static Camera from_intrinsics(const Intrinsics& k, const glm::mat4& camera_to_world,
                                CameraConvention convention, float near_plane, float far_plane);

  glm::mat4 view() const;
  glm::mat4 projection() const;
  glm::mat4 view_projection() const { return projection() * view(); }
  glm::vec3 forward() const;  // unit vector from eye toward target
  glm::vec3 right() const;    // unit vector, forward x up

  // Distance along the view direction, in scene units, of what lies at this window depth
  // (Framebuffer::depth, in [0, 1]). Perspective: near * far / (far - depth * (far - near));
  // orthographic: near + depth * (far - near). The depth 1 of pixels where nothing was drawn
  // gives far_plane.
  float view_distance(float window_depth) const;

  // The point shading measures view directions from: the eye, or for an orthographic camera,
  // whose rays are parallel (an eye at infinity), a point 1e4 view sizes back along the axis,
  // so that every direction to it is within 1e-4 radians of the axis.
  glm::vec3 shading_eye() const;

  // Throws facet::Error if the camera cannot project (fov outside (0, 180), view_height not
  // positive, near or far out of range, eye == target, up parallel to the view direction,
  // non-finite values), naming the field.
  void validate() const;
};

// A first-person camera: position plus yaw (degrees, 0 looks down -Z, positive turns left)
// and pitch (degrees, positive looks up, clamped to +-89).
struct FirstPersonCamera {
  glm::vec3 position{0.0f, 1.7f, 0.0f};
  float yaw_degrees = 0.0f;
  float pitch_degrees = 0.0f;

  glm::vec3 forward() const;  // unit view direction
  glm::vec3 right() const;    // unit, horizontal
  Camera camera(float fov_y_degrees, float aspect, float near_plane = 0.1f,
                float far_plane = 1000.0f) const;
};

}  // namespace facet
