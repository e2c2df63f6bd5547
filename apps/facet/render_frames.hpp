// Drawing the frames of a `facet render` job (frame_options.hpp): the scene and the camera
// posed at each frame's time, rendered into a framebuffer holding every output asked for; for
// a sequence, the loop that skips frames already written, writes each frame's files, reports
// progress and stops cleanly on Ctrl-C.
#pragma once

#include <string>

#include "animated_scene.hpp"
#include "arguments.hpp"
#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/renderer.hpp"
#include "frame_options.hpp"
#include "render_backend.hpp"

namespace facet::cli {

class FrameRenderer {
 public:
  // `camera` is the view when there is no camera path, and gives a path its lens otherwise.
  // With `gl`, the OpenGL twin draws the frames instead of `renderer`.
  FrameRenderer(Renderer& renderer, AnimatedScene& scene, const Camera& camera, const FrameJob& job,
                ImageSize size, GlBackend* gl = nullptr);

  // Renders the frame at `seconds` on the animation clock.
  const Framebuffer& render(double seconds);

 private:
  Renderer& renderer_;
  AnimatedScene& scene_;
  Camera camera_;
  const FrameJob& job_;
  Framebuffer framebuffer_;
  GlBackend* gl_;
};

// Renders and writes every frame of a sequence. Returns the exit code: 0, or 128 + the signal
// that stopped it after a whole frame. Throws facet::Error if a frame cannot be written (the
// frames before it stay, whole).
int render_sequence(const FrameJob& job, FrameRenderer& frames, ImageSize size);

}  // namespace facet::cli
