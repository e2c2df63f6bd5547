// The viewer's input: turns SDL key, mouse and window events into a first-person camera and
// the loop's actions (quit, screenshot). The library never sees input; only this file does.
#pragma once

#include "facet/camera.hpp"

union SDL_Event;

namespace facet::cli {

enum class ViewAction { none, quit, screenshot };

// TODO(issue 5): orbit mode for models (drag/wheel/middle-drag, Tab to switch), the function
// keys F1-F11 (help, render modes, fov, resolution, shading, threads, overlay, fullscreen) and
// the Dear ImGui overlay drawn by facet.
class ViewControls {
 public:
  // Starts at the start camera's pose; speed is in world units per second (walking).
  ViewControls(const Camera& start, float speed);

  // Reacts to one event: Esc, F12, window close, clicks (capture the mouse), mouse look.
  ViewAction handle(const SDL_Event& event);

  // Moves and turns by the keys held now, scaled by the frame's delta time in seconds.
  void update(double dt);

  // The camera to render this frame with. Until the first move it is exactly the start camera
  // (so a scripted frame matches `facet render`), then the first-person camera's.
  Camera camera() const;

 private:
  Camera start_;
  FirstPersonCamera first_person_;
  float speed_;
  bool moved_ = false;
  bool mouse_captured_ = false;
};

}  // namespace facet::cli
