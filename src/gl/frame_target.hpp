// The offscreen image the GL twin draws into: a framebuffer object with a linear float color
// buffer and a float depth buffer, and the readback into a facet::Framebuffer (rows flipped,
// exposure applied, sRGB-encoded as facet's resolve does).
#pragma once

#include "facet/framebuffer.hpp"
#include "gl/gl_api.hpp"

namespace facet::gl {

class FrameTarget {
 public:
  FrameTarget() = default;
  ~FrameTarget();
  FrameTarget(const FrameTarget&) = delete;
  FrameTarget& operator=(const FrameTarget&) = delete;

  // Binds a width x height target for drawing (made or remade when the size changes).
  void bind(int width, int height);
  // Reads the drawn image into target (same size), its color scaled by 2^exposure.
  void read(Framebuffer& target, float exposure) const;

 private:
  GLuint framebuffer_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace facet::gl
