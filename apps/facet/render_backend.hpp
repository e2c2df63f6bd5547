// Which renderer draws the frames of `facet render` and `facet view`: facet's own, or the
// OpenGL twin (facet::gl, docs/gl_twin.md), which exists only in a build with FACET_BUILD_GL.
#pragma once

#include <memory>
#include <string>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"

namespace facet::cli {

enum class Backend { facet, gl };

// "facet" or "gl"; throws facet::Error naming the flag otherwise.
Backend parse_backend(const std::string& flag, const std::string& text);
const char* backend_name(Backend backend);

// The OpenGL twin (facet::gl, docs/gl_twin.md) as the program uses it: made by the OpenGL
// module (gl/gl_twin_backend.cpp, modules.hpp), so that only the commands that draw with it load
// OpenGL.
class GlBackend {
 public:
  virtual ~GlBackend() = default;

  // "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6".
  virtual std::string description() const = 0;
  virtual const std::string& renderer_name() const = 0;  // "llvmpipe (LLVM 15.0.6, 256 bits)"
  virtual void render(const Scene& scene, const Camera& camera, Framebuffer& target) = 0;
  // GlRenderer::draw: the frame timed as glmark2 times one, nothing read back.
  virtual void draw(const Scene& scene, const Camera& camera, Framebuffer& target) = 0;
  virtual double last_frame_ms() const = 0;
};

// The OpenGL module's backend (modules.cpp). Throws facet::Error, one line: the build has no
// OpenGL backend, its module is not installed, or EGL cannot make a context here (what is
// missing).
std::unique_ptr<GlBackend> make_gl_backend(const RenderSettings& settings);

}  // namespace facet::cli
