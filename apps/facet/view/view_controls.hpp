// The viewer's camera input: turns SDL key, mouse and window events into a first-person or an
// orbit camera and the loop's actions (quit, screenshots, mute). The library never sees input;
// only this file (and the function keys in view_settings.cpp) does.
#pragma once

#include "facet/camera.hpp"
#include "facet/scene.hpp"

union SDL_Event;

namespace facet::cli {

enum class ViewAction { none, quit, screenshot, window_screenshot, toggle_mute, camera_mode };

enum class CameraMode { first_person, orbit };

// First-person walking speed in world units per second: a person's walk (1.4 m/s) where the
// scene says what a unit is (Scene::metres_per_unit: the built-in worlds), else a pace that
// crosses the scene's bounding box diagonally in 20 s (a model of unknown units). Shift runs
// at 4 times this.
float walking_speed(const Scene& scene);

// The movement keys held during a frame, each axis -1, 0 or 1.
struct HeldKeys {
  float forward = 0.0f;  // W / S
  float strafe = 0.0f;   // D / A
  float rise = 0.0f;     // E or Space / Q or Ctrl
  float turn = 0.0f;     // Left / Right (positive turns left)
  float tilt = 0.0f;     // Up / Down
  bool run = false;      // Shift
};

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
  // Moves and turns by these keys for dt seconds (what update does with the keyboard's state).
  void move(const HeldKeys& keys, double dt);

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
