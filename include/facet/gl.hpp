// GlRenderer: the OpenGL twin of facet's renderer, drawing the same Scene with OpenGL 3.3 core
// on a headless EGL context, for comparing the software pipeline with the hardware one.
// Optional: the facet::gl target (FACET_BUILD_GL); nothing else in facet links OpenGL.
#pragma once

#include <memory>
#include <string>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"

namespace facet {

class GlRenderer {
 public:
  // Makes an OpenGL 3.3 core context through EGL, without a window or a display server
  // (EGL_MESA_platform_surfaceless where it exists, else the default display). Throws
  // facet::Error with one line saying what is missing when there is no usable OpenGL.
  // Uses clear_color, exposure and msaa of the settings (msaa above the context's
  // GL_MAX_SAMPLES is clamped, with one warning on stderr); threads, tile size and debug views are
  // the software renderer's own and are ignored.
  explicit GlRenderer(const RenderSettings& settings = {});
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  // GL_RENDERER and GL_VERSION of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" and
  // "4.5 (Core Profile) Mesa 22.3.6".
  const std::string& renderer_name() const;
  const std::string& version() const;

  // Draws every mesh instance of the scene seen from camera into target, as draw_scene and
  // Renderer::finish would: same transforms, levels of detail, materials, lights, fog, sky and
  // transparency order. The target's color format and depth image are filled like the software
  // renderer's; extra outputs are not drawn (throws facet::Error if the target asks for any, or
  // has no color image: Framebuffer::depth_only).
  // Meshes and textures are uploaded the first time they are drawn and found again by address
  // (so, as for Renderer, a mesh must not change in place), and freed 60 frames after the last
  // frame that drew them.
  void render(const Scene& scene, const Camera& camera, Framebuffer& target);

  // The frame render() draws, timed as glmark2 times a frame of llvmpipe's (facet bench
  // --gl-readback off): into an 8-bit sRGB color buffer of the target's size, which OpenGL
  // encodes into as it writes, the samples resolved, then glFinish. Neither exposure nor tone
  // mapping is applied, and nothing is read back unless `read`: then, after the timing, the
  // codes OpenGL wrote go into target's color (not its depth). target must be rgba8_srgb (else
  // throws facet::Error).
  void draw(const Scene& scene, const Camera& camera, Framebuffer& target, bool read = false);

  // Wall time of the last render(), readback included, or of the last draw(), in milliseconds.
  double last_frame_ms() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facet
