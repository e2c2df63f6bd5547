// The viewer's input (see view_controls.hpp).
#include "view_controls.hpp"

#include <SDL.h>

#include <cmath>
#include <glm/glm.hpp>

namespace facet::cli {
namespace {

constexpr float kRunFactor = 4.0f;           // Shift
constexpr float kTurnDegreesPerSecond = 90;  // arrow keys
constexpr float kMouseDegreesPerPixel = 0.15f;

}  // namespace

ViewControls::ViewControls(const Camera& start, float speed) : start_(start), speed_(speed) {
  // FirstPersonCamera::forward() is (-sin yaw cos pitch, sin pitch, -cos yaw cos pitch).
  glm::vec3 f = start.forward();
  first_person_.position = start.eye;
  first_person_.yaw_degrees = glm::degrees(std::atan2(-f.x, -f.z));
  first_person_.pitch_degrees = glm::degrees(std::asin(glm::clamp(f.y, -1.0f, 1.0f)));
}

ViewAction ViewControls::handle(const SDL_Event& event) {
  switch (event.type) {
    case SDL_QUIT:
      return ViewAction::quit;
    case SDL_KEYDOWN:
      if (event.key.repeat) return ViewAction::none;
      if (event.key.keysym.sym == SDLK_F12) return ViewAction::screenshot;
      if (event.key.keysym.sym == SDLK_ESCAPE) {
        // The first Esc releases a captured mouse; Esc with a free mouse quits.
        if (!mouse_captured_) return ViewAction::quit;
        mouse_captured_ = false;
        SDL_SetRelativeMouseMode(SDL_FALSE);
      }
      return ViewAction::none;
    case SDL_MOUSEBUTTONDOWN:
      if (!mouse_captured_ && SDL_SetRelativeMouseMode(SDL_TRUE) == 0) mouse_captured_ = true;
      return ViewAction::none;
    case SDL_MOUSEMOTION:
      if (mouse_captured_ && (event.motion.xrel || event.motion.yrel)) {
        first_person_.yaw_degrees -= event.motion.xrel * kMouseDegreesPerPixel;
        first_person_.pitch_degrees -= event.motion.yrel * kMouseDegreesPerPixel;
        first_person_.pitch_degrees = glm::clamp(first_person_.pitch_degrees, -89.0f, 89.0f);
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
  float forward = axis(SDL_SCANCODE_S, SDL_SCANCODE_W);
  float strafe = axis(SDL_SCANCODE_A, SDL_SCANCODE_D);
  bool up = key[SDL_SCANCODE_E] || key[SDL_SCANCODE_SPACE];
  bool down = key[SDL_SCANCODE_Q] || key[SDL_SCANCODE_LCTRL] || key[SDL_SCANCODE_RCTRL];
  float rise = static_cast<float>(up) - static_cast<float>(down);
  float turn = axis(SDL_SCANCODE_RIGHT, SDL_SCANCODE_LEFT);  // positive yaw turns left
  float tilt = axis(SDL_SCANCODE_DOWN, SDL_SCANCODE_UP);
  if (forward == 0 && strafe == 0 && rise == 0 && turn == 0 && tilt == 0) return;

  float seconds = static_cast<float>(dt);
  bool run = key[SDL_SCANCODE_LSHIFT] || key[SDL_SCANCODE_RSHIFT];
  float step = speed_ * (run ? kRunFactor : 1.0f) * seconds;
  // Walking follows the view's heading but stays level, as in most first-person games.
  glm::vec3 heading = first_person_.forward();
  heading.y = 0.0f;
  if (glm::length(heading) > 1e-6f) heading = glm::normalize(heading);
  first_person_.position += heading * (forward * step) + first_person_.right() * (strafe * step) +
                            glm::vec3(0.0f, rise * step, 0.0f);
  first_person_.yaw_degrees += turn * kTurnDegreesPerSecond * seconds;
  first_person_.pitch_degrees = glm::clamp(
      first_person_.pitch_degrees + tilt * kTurnDegreesPerSecond * seconds, -89.0f, 89.0f);
  moved_ = true;
}

Camera ViewControls::camera() const {
  if (!moved_) return start_;
  return first_person_.camera(start_.fov_y_degrees, start_.aspect, start_.near_plane,
                              start_.far_plane);
}

}  // namespace facet::cli
