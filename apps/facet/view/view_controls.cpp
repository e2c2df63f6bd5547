// The viewer's camera input (see view_controls.hpp).
#include "view_controls.hpp"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace facet::cli {
namespace {

constexpr float kWalkMetresPerSecond = 1.4f;  // a person's usual walking pace
constexpr float kWalkSecondsAcross = 20.0f;   // unknown units: the scene's diagonal in this time
constexpr float kRunFactor = 4.0f;            // Shift
constexpr float kTurnDegreesPerSecond = 90;   // arrow keys
constexpr float kMouseDegreesPerPixel = 0.15f;
constexpr float kZoomPerWheelStep = 0.9f;  // orbit: distance factor per wheel notch
constexpr float kZoomPerSecond = 1.5f;     // orbit, W/S: e-folds of distance per second
constexpr float kPanPerPixel = 0.002f;     // orbit: pan, in distances per pixel dragged

}  // namespace

float walking_speed(const Scene& scene) {
  if (scene.metres_per_unit > 0.0f) return kWalkMetresPerSecond / scene.metres_per_unit;
  Bounds bounds = scene.bounds();
  float extent = bounds.empty() ? 10.0f : glm::length(bounds.max - bounds.min);
  return extent / kWalkSecondsAcross;
}

ViewControls::ViewControls(const Camera& start, float speed, CameraMode mode)
    : start_(start),
      target_(start.target),
      distance_(glm::length(start.target - start.eye)),
      speed_(speed),
      mode_(mode) {
  // FirstPersonCamera::forward() is (-sin yaw cos pitch, sin pitch, -cos yaw cos pitch).
  glm::vec3 f = start.forward();
  first_person_.position = start.eye;
  first_person_.yaw_degrees = glm::degrees(std::atan2(-f.x, -f.z));
  first_person_.pitch_degrees = glm::degrees(std::asin(glm::clamp(f.y, -1.0f, 1.0f)));
}

void ViewControls::zoom(float factor) {
  // Between the near plane (closer, the target would be clipped; and 0 could never grow
  // again) and the far plane (farther, the scene is gone and the eye's coordinates would
  // swallow the unit step to the target).
  distance_ = std::clamp(distance_ * factor, start_.near_plane, start_.far_plane);
}

void ViewControls::place_orbit_eye() {
  first_person_.position = target_ - first_person_.forward() * distance_;
}

void ViewControls::turn(float yaw_degrees, float pitch_degrees) {
  first_person_.yaw_degrees += yaw_degrees;
  first_person_.pitch_degrees =
      glm::clamp(first_person_.pitch_degrees + pitch_degrees, -89.0f, 89.0f);
  if (mode_ == CameraMode::orbit) place_orbit_eye();
  moved_ = true;
}

ViewAction ViewControls::handle(const SDL_Event& event) {
  switch (event.type) {
    case SDL_QUIT:
      return ViewAction::quit;
    case SDL_KEYDOWN: {
      if (event.key.repeat) return ViewAction::none;
      SDL_Keycode key = event.key.keysym.sym;
      if (key == SDLK_F12) {
        return (event.key.keysym.mod & KMOD_SHIFT) ? ViewAction::window_screenshot
                                                   : ViewAction::screenshot;
      }
      if (key == SDLK_m) return ViewAction::toggle_mute;
      if (key == SDLK_TAB) {
        // Both modes share the eye and the view angles, so switching does not jump.
        if (mode_ == CameraMode::orbit) {
          mode_ = CameraMode::first_person;
        } else {
          mode_ = CameraMode::orbit;
          target_ = first_person_.position + first_person_.forward() * distance_;
          if (mouse_captured_) SDL_SetRelativeMouseMode(SDL_FALSE);
          mouse_captured_ = false;
        }
        return ViewAction::camera_mode;
      }
      if (key == SDLK_ESCAPE) {
        // The first Esc releases a captured mouse; Esc with a free mouse quits.
        if (!mouse_captured_) return ViewAction::quit;
        mouse_captured_ = false;
        SDL_SetRelativeMouseMode(SDL_FALSE);
      }
      return ViewAction::none;
    }
    case SDL_MOUSEBUTTONDOWN:
      if (mode_ == CameraMode::first_person && !mouse_captured_ &&
          SDL_SetRelativeMouseMode(SDL_TRUE) == 0) {
        mouse_captured_ = true;
      }
      return ViewAction::none;
    case SDL_MOUSEMOTION: {
      float dx = static_cast<float>(event.motion.xrel), dy = static_cast<float>(event.motion.yrel);
      if (dx == 0 && dy == 0) return ViewAction::none;
      if (mode_ == CameraMode::first_person) {
        if (mouse_captured_) turn(-dx * kMouseDegreesPerPixel, -dy * kMouseDegreesPerPixel);
      } else if (event.motion.state & SDL_BUTTON_LMASK) {
        turn(-dx * kMouseDegreesPerPixel, -dy * kMouseDegreesPerPixel);
      } else if (event.motion.state & SDL_BUTTON_MMASK) {
        // Pan: the target slides in the view plane, as far as the scene under the cursor.
        glm::vec3 up = glm::cross(first_person_.right(), first_person_.forward());
        target_ += (-first_person_.right() * dx + up * dy) * (distance_ * kPanPerPixel);
        place_orbit_eye();
        moved_ = true;
      }
      return ViewAction::none;
    }
    case SDL_MOUSEWHEEL:
      if (mode_ == CameraMode::orbit && event.wheel.y != 0) {
        zoom(std::pow(kZoomPerWheelStep, static_cast<float>(event.wheel.y)));
        place_orbit_eye();
        moved_ = true;
      }
      return ViewAction::none;
    default:
      return ViewAction::none;
  }
}

void ViewControls::update(double dt) {
  const Uint8* key = SDL_GetKeyboardState(nullptr);
  auto axis = [&](SDL_Scancode negative, SDL_Scancode positive) {
    return static_cast<float>(key[positive]) - static_cast<float>(key[negative]);
  };
  HeldKeys keys;
  keys.forward = axis(SDL_SCANCODE_S, SDL_SCANCODE_W);
  keys.strafe = axis(SDL_SCANCODE_A, SDL_SCANCODE_D);
  bool up = key[SDL_SCANCODE_E] || key[SDL_SCANCODE_SPACE];
  bool down = key[SDL_SCANCODE_Q] || key[SDL_SCANCODE_LCTRL] || key[SDL_SCANCODE_RCTRL];
  keys.rise = static_cast<float>(up) - static_cast<float>(down);
  keys.turn = axis(SDL_SCANCODE_RIGHT, SDL_SCANCODE_LEFT);  // positive yaw turns left
  keys.tilt = axis(SDL_SCANCODE_DOWN, SDL_SCANCODE_UP);
  keys.run = key[SDL_SCANCODE_LSHIFT] || key[SDL_SCANCODE_RSHIFT];
  move(keys, dt);
}

void ViewControls::move(const HeldKeys& keys, double dt) {
  const float forward = keys.forward, strafe = keys.strafe, rise = keys.rise;
  const float turn_axis = keys.turn, tilt = keys.tilt;
  if (forward == 0 && strafe == 0 && rise == 0 && turn_axis == 0 && tilt == 0) return;

  float seconds = static_cast<float>(dt);
  float factor = keys.run ? kRunFactor : 1.0f;
  if (mode_ == CameraMode::orbit) {
    // A/D and the arrows orbit, W/S zoom, Q/E move the target down/up.
    zoom(std::exp(-forward * kZoomPerSecond * factor * seconds));
    target_.y += rise * speed_ * factor * seconds;
    float degrees = kTurnDegreesPerSecond * factor * seconds;
    turn((turn_axis - strafe) * degrees, tilt * degrees);
    return;
  }
  float step = speed_ * factor * seconds;
  // Walking follows the view's heading but stays level, as in most first-person games.
  glm::vec3 heading = first_person_.forward();
  heading.y = 0.0f;
  if (glm::length(heading) > 1e-6f) heading = glm::normalize(heading);
  first_person_.position += heading * (forward * step) + first_person_.right() * (strafe * step) +
                            glm::vec3(0.0f, rise * step, 0.0f);
  turn(turn_axis * kTurnDegreesPerSecond * seconds, tilt * kTurnDegreesPerSecond * seconds);
}

Camera ViewControls::camera(float fov_y_degrees, float aspect) const {
  if (!moved_) {
    // The window's aspect replaces the start camera's: it comes from a file or the framing,
    // never from intrinsics (whose aspect belongs to their calibration: camera.hpp).
    Camera c = start_;
    c.fov_y_degrees = fov_y_degrees;
    c.aspect = aspect;
    return c;
  }
  return first_person_.camera(fov_y_degrees, aspect, start_.near_plane, start_.far_plane);
}

}  // namespace facet::cli
