// Camera: where the eye is and how it projects. Right-handed, looks down -Z in view space,
// OpenGL-style projection (clip z in [-w, w]). Also a first-person (yaw/pitch) camera form.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace facet {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 60.0f;  // vertical field of view
  float aspect = 16.0f / 9.0f;  // width / height
  float near_plane = 0.1f;
  float far_plane = 100.0f;

  static Camera look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up = {0, 1, 0},
                        float fov_y_degrees = 60.0f, float aspect = 16.0f / 9.0f,
                        float near_plane = 0.1f, float far_plane = 100.0f);

  glm::mat4 view() const;
  glm::mat4 projection() const;
  glm::mat4 view_projection() const { return projection() * view(); }
  glm::vec3 forward() const;  // unit vector from eye toward target
  glm::vec3 right() const;    // unit vector, forward x up

  // Distance along the view direction, in scene units, of what lies at this window depth
  // (Framebuffer::depth, in [0, 1]): near * far / (far - depth * (far - near)). The depth 1
  // of pixels where nothing was drawn gives far_plane.
  float view_distance(float window_depth) const;

  // Throws facet::Error if the camera cannot project (fov outside (0, 180), near <= 0,
  // far <= near, eye == target, up parallel to the view direction, non-finite values).
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
