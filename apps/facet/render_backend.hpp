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

// The OpenGL twin, behind a wall: the program compiles and links with or without it.
class GlBackend {
 public:
  // Throws facet::Error, one line: the build has no OpenGL backend, or EGL cannot make a
  // context here (what is missing).
  explicit GlBackend(const RenderSettings& settings);
  ~GlBackend();
  GlBackend(const GlBackend&) = delete;
  GlBackend& operator=(const GlBackend&) = delete;

  // "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6".
  std::string description() const;
  const std::string& renderer_name() const;  // "llvmpipe (LLVM 15.0.6, 256 bits)"
  void render(const Scene& scene, const Camera& camera, Framebuffer& target);
  // GlRenderer::draw: the frame timed as glmark2 times one, nothing read back.
  void draw(const Scene& scene, const Camera& camera, Framebuffer& target);
  double last_frame_ms() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facet::cli
