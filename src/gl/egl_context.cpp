// Headless EGL context (see egl_context.hpp).
//
// On Mesa without a GPU (servers, CI) there is no X or Wayland display to ask for a context:
// EGL_MESA_platform_surfaceless gives a display that needs none, and a context made current
// with no surface at all (EGL_KHR_surfaceless_context) draws only into framebuffer objects,
// which is all the renderer uses. Elsewhere (a GPU driver without that platform) the default
// display is tried.
#include "gl/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <string>

#include "facet/error.hpp"

namespace facet::gl {
namespace {

std::string egl_error() {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return code;
}

// One line: what failed, EGL's error code, and what to install where that helps.
[[noreturn]] void fail(const std::string& what, const std::string& hint = "") {
  throw Error("OpenGL backend: " + what + " (EGL error " + egl_error() + ")" + hint);
}

const char* const kMesaHint = "; Mesa's are in libegl-mesa0 and libgl1-mesa-dri";

EGLDisplay open_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::string extensions = client ? client : "";
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display &&
      extensions.find("EGL_MESA_platform_surfaceless") != std::string::npos) {
    EGLDisplay display =
        get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY) return display;
  }
  return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

}  // namespace

EglContext::EglContext() {
  EGLDisplay display = open_display();
  if (display == EGL_NO_DISPLAY) fail("no EGL display", kMesaHint);
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) fail("eglInitialize failed");
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) fail("this EGL has no desktop OpenGL");
  // No surface: the config only has to render OpenGL.
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                      EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs == 0) {
    config = nullptr;  // EGL_KHR_no_config_context: a context needs no config
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) fail("cannot make an OpenGL 3.3 core context", kMesaHint);
  context_ = context;
  make_current();
}

// The display is left initialized: EGL hands every caller the same display, and terminating
// it would pull it from under another renderer's context still in use.
EglContext::~EglContext() {
  if (context_ == nullptr) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
}

void EglContext::make_current() const {
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    fail("cannot make the context current without a surface");
  }
}

}  // namespace facet::gl
