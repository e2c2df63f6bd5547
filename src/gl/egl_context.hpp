// A headless OpenGL 3.3 core context through EGL: no window, no display server. The GL
// renderer (gl_renderer.cpp) makes one and draws into its own framebuffer objects.
#pragma once

#include <string>

namespace facet::gl {

class EglContext {
 public:
  // Throws facet::Error, one line naming what is missing (no EGL display, no OpenGL API, no
  // 3.3 core context).
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // Makes the context current on the calling thread (each GL call below needs that).
  void make_current() const;

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace facet::gl
