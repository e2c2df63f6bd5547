// Offscreen target and readback (see frame_target.hpp).
#include "gl/frame_target.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "facet/color.hpp"
#include "facet/error.hpp"

namespace facet::gl {
FrameTarget::~FrameTarget() {
  const GLuint framebuffers[] = {framebuffer_, ms_framebuffer_};
  const GLuint renderbuffers[] = {color_, depth_, ms_color_, ms_depth_};
  glDeleteFramebuffers(2, framebuffers);
  glDeleteRenderbuffers(4, renderbuffers);
}

void FrameTarget::make(int width, int height, int samples, Color color_kind) {
  if (framebuffer_ == 0) {
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(1, &color_);
    glGenRenderbuffers(1, &depth_);
    glGenFramebuffers(1, &ms_framebuffer_);
    glGenRenderbuffers(1, &ms_color_);
    glGenRenderbuffers(1, &ms_depth_);
  }
  // Float color: the image stays linear and unclamped until the encode at readback, as in
  // facet's tiles. Or 8-bit sRGB, as glmark2 draws (GL_FRAMEBUFFER_SRGB on: encoded as written).
  const GLenum format = color_kind == Color::srgb8 ? GL_SRGB8_ALPHA8 : GL_RGBA32F;
  auto attach = [&](GLuint framebuffer, GLuint color, GLuint depth, int n) {
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, n, format, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, n, GL_DEPTH_COMPONENT32F, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw Error("OpenGL backend: cannot make a " + std::to_string(width) + "x" +
                  std::to_string(height) + (color_kind == Color::srgb8 ? " 8-bit sRGB" : " float") +
                  " framebuffer with " + std::to_string(n) + " samples a pixel");
    }
  };
  attach(framebuffer_, color_, depth_, 0);
  if (samples > 1) attach(ms_framebuffer_, ms_color_, ms_depth_, samples);
  width_ = width, height_ = height, samples_ = samples, color_kind_ = color_kind;
}

void FrameTarget::bind(int width, int height, int samples, Color color) {
  if (width != width_ || height != height_ || samples != asked_samples_ || color != color_kind_) {
    GLint max_samples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    const int usable = std::max(1, std::min(samples, static_cast<int>(max_samples)));
    if (usable < samples && !warned_) {
      std::fprintf(stderr, "OpenGL backend: %d samples a pixel asked, this OpenGL has at most %d\n",
                   samples, usable);
      warned_ = true;
    }
    make(width, height, usable, color);
    asked_samples_ = samples;
  }
  if (color == Color::srgb8) {
    glEnable(GL_FRAMEBUFFER_SRGB);
  } else {
    glDisable(GL_FRAMEBUFFER_SRGB);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? ms_framebuffer_ : framebuffer_);
  glViewport(0, 0, width, height);
}

void FrameTarget::read(Framebuffer& target, const Output& output) {
  const int w = width_, h = height_;
  const bool mapped = output.tone_mapping != ToneMapping::none;
  // Tone mapping leaves the clear color alone: it tells the pixels nothing was drawn on by depth.
  const bool need_depth = target.has_depth() || (mapped && !output.maps_background);
  resolve_samples(need_depth);
  std::vector<glm::vec4> rgba(static_cast<std::size_t>(w) * h);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  std::vector<float> depth;
  if (need_depth) {
    depth.resize(static_cast<std::size_t>(w) * h);
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  }
  float scale = std::exp2(output.exposure);
  if (mapped) {  // the exposure goes into the mapped colors
    std::vector<glm::vec4> drawn = rgba;
    tone_map(output.tone_mapping, drawn, output.exposure);
    for (std::size_t i = 0; i < rgba.size(); ++i) {
      const bool cleared = !output.maps_background && depth[i] == 1.0f;
      rgba[i] = cleared ? glm::vec4(glm::vec3(rgba[i]) * scale, rgba[i].a) : drawn[i];
    }
    scale = 1.0f;
  }
  // GL's first row is the bottom one; facet's the top one.
  for (int y = 0; y < h; ++y) {
    const glm::vec4* source = &rgba[static_cast<std::size_t>(h - 1 - y) * w];
    const std::size_t row = static_cast<std::size_t>(y) * w * 4;
    if (target.format() == ColorFormat::rgba8_srgb) {
      // facet's own encode: the twin's colors become the bytes facet's would.
      encode_srgb8({source, static_cast<std::size_t>(w)},
                   {target.rgba8().data() + row, static_cast<std::size_t>(w) * 4}, scale);
    } else {
      const float* from = &source->x;
      float* out = target.rgba32f().data() + row;
      for (int x = 0; x < w; ++x, from += 4, out += 4) {
        out[0] = from[0] * scale, out[1] = from[1] * scale, out[2] = from[2] * scale;
        out[3] = from[3];
      }
    }
  }
  if (!target.has_depth()) return;
  for (int y = 0; y < h; ++y) {
    std::copy_n(depth.data() + static_cast<std::size_t>(h - 1 - y) * w, w,
                target.depth().data() + static_cast<std::size_t>(y) * w);
  }
}

void FrameTarget::resolve_samples(bool depth) {
  if (samples_ == 1) return;
  const int w = width_, h = height_;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  if (depth) glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

void FrameTarget::finish() {
  resolve_samples(false);
  glFinish();
}

void FrameTarget::read_codes(Framebuffer& target) {
  const int w = width_, h = height_;
  std::vector<std::uint8_t> codes(static_cast<std::size_t>(w) * h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, codes.data());
  const std::size_t row_bytes = static_cast<std::size_t>(w) * 4;
  for (int y = 0; y < h; ++y) {  // GL's first row is the bottom one
    std::copy_n(codes.data() + static_cast<std::size_t>(h - 1 - y) * row_bytes, row_bytes,
                target.rgba8().data() + static_cast<std::size_t>(y) * row_bytes);
  }
}

}  // namespace facet::gl
