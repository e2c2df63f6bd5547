// Offscreen target and readback (see frame_target.hpp).
#include "gl/frame_target.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <vector>

#include "facet/color.hpp"
#include "facet/error.hpp"

namespace facet::gl {
namespace {

std::uint8_t unorm8(float v) {  // clamped, NaN to 0, rounded: core/color.hpp's encode_unorm8
  return static_cast<std::uint8_t>((v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f) * 255.0f + 0.5f);
}

}  // namespace

FrameTarget::~FrameTarget() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteRenderbuffers(1, &color_);
  glDeleteRenderbuffers(1, &depth_);
}

void FrameTarget::bind(int width, int height) {
  if (width != width_ || height != height_) {
    if (framebuffer_ == 0) {
      glGenFramebuffers(1, &framebuffer_);
      glGenRenderbuffers(1, &color_);
      glGenRenderbuffers(1, &depth_);
    }
    // Float color: the image stays linear and unclamped until the encode at readback, as in
    // facet's tiles.
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw Error("OpenGL backend: cannot make a " + std::to_string(width) + "x" +
                  std::to_string(height) + " float framebuffer");
    }
    width_ = width, height_ = height;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
}

void FrameTarget::read(Framebuffer& target, float exposure) const {
  const int w = width_, h = height_;
  std::vector<float> rgba(static_cast<std::size_t>(w) * h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  const float scale = std::exp2(exposure);
  // GL's first row is the bottom one; facet's the top one.
  for (int y = 0; y < h; ++y) {
    const float* from = rgba.data() + static_cast<std::size_t>(h - 1 - y) * w * 4;
    const std::size_t row = static_cast<std::size_t>(y) * w * 4;
    if (target.format() == ColorFormat::rgba8_srgb) {
      std::uint8_t* out = target.rgba8().data() + row;
      for (int x = 0; x < w; ++x, from += 4, out += 4) {
        const glm::vec3 linear =
            glm::clamp(glm::vec3(from[0], from[1], from[2]) * scale, 0.0f, 1.0f);
        const glm::vec3 encoded = linear_to_srgb(linear);
        for (int c = 0; c < 3; ++c) out[c] = unorm8(encoded[c]);
        out[3] = unorm8(from[3]);
      }
    } else {
      float* out = target.rgba32f().data() + row;
      for (int x = 0; x < w; ++x, from += 4, out += 4) {
        out[0] = from[0] * scale, out[1] = from[1] * scale, out[2] = from[2] * scale;
        out[3] = from[3];
      }
    }
  }
  if (!target.has_depth()) return;
  std::vector<float> depth(static_cast<std::size_t>(w) * h);
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  for (int y = 0; y < h; ++y) {
    std::copy_n(depth.data() + static_cast<std::size_t>(h - 1 - y) * w, w,
                target.depth().data() + static_cast<std::size_t>(y) * w);
  }
}

}  // namespace facet::gl
