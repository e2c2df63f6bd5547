// The viewer's camera input: turns SDL key, mouse and window events into a first-person or an
// orbit camera and the loop's actions (quit, screenshots, mute). The library never sees input;
// only this file (and the function keys in view_settings.cpp) does.
#pragma once

#include "facet/camera.hpp"

union SDL_Event;

namespace facet::cli {

enum class ViewAction { none, quit, screenshot, window_screenshot, toggle_mute, camera_mode };

enum class CameraMode { first_person, orbit };

class ViewControls {
 public:
  // Starts at the start camera's pose; speed is in world units per second (walking). Orbit
  // mode turns around the start camera's target.
  ViewControls(const Camera& start, float speed, CameraMode mode);

  // Reacts to one event: Esc, F12, M, Tab, window close, clicks (capture the mouse in first
  // person), mouse look, orbit drags and the wheel.
  ViewAction handle(const SDL_Event& event);

  // Moves and turns by the keys held now, scaled by the frame's delta time in seconds.
  void update(double dt);

  // The camera to render this frame with. Until the first move it is exactly the start camera
  // with this field of view and aspect (so a scripted frame matches `facet render`).
  Camera camera(float fov_y_degrees, float aspect) const;

  CameraMode mode() const { return mode_; }

 private:
  void place_orbit_eye();   // orbit: the eye from the target, the distance and the view angles
  void zoom(float factor);  // orbit distance times factor, kept between near and far
  void turn(float yaw_degrees, float pitch_degrees);

  Camera start_;
  FirstPersonCamera first_person_;  // the eye and view angles, in both modes
  glm::vec3 target_;                // orbit: what the camera turns around
  float distance_;                  // orbit: from the eye to the target
  float speed_;
  CameraMode mode_;
  bool moved_ = false;
  bool mouse_captured_ = false;
};

}  // namespace facet::cli
