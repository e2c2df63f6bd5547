// The offscreen image the GL twin draws into: a framebuffer object with a linear float color
// buffer and a float depth buffer, and the readback into a facet::Framebuffer (rows flipped,
// exposure applied, encoded to 8-bit sRGB as facet's resolve encodes). With MSAA it draws into
// multisampled buffers, resolved by a blit into the single-sample ones before the readback: the
// color is linear float, so the average is in linear light, as facet's resolve. Or, for timing
// frames as glmark2 does (GlRenderer::draw), an 8-bit sRGB color buffer that OpenGL encodes into
// as it writes (and averages in linear light).
#pragma once

#include "facet/color.hpp"
#include "facet/framebuffer.hpp"
#include "gl/gl_api.hpp"

namespace facet::gl {

class FrameTarget {
 public:
  FrameTarget() = default;
  ~FrameTarget();
  FrameTarget(const FrameTarget&) = delete;
  FrameTarget& operator=(const FrameTarget&) = delete;

  enum class Color { linear_float, srgb8 };
  // Binds a width x height target with `samples` samples a pixel and that color buffer for
  // drawing (made or remade when any changes). samples above GL_MAX_SAMPLES are clamped, with
  // one warning on stderr.
  void bind(int width, int height, int samples, Color color = Color::linear_float);
  // The samples a pixel of the bound target (after the clamp).
  int samples() const { return samples_; }
  // How the drawn colors become the target's: facet's resolve (pipeline/output/output.hpp)
  // as the twin can do it, after GL's resolve of the samples rather than per sample.
  struct Output {
    float exposure = 0.0f;  // in stops
    ToneMapping tone_mapping = ToneMapping::none;
    bool maps_background = false;  // the sky is drawn: mapped too; else the clear color is not
  };
  // Resolves the samples if there are several, then reads the drawn image into target (same
  // size), its color scaled by 2^exposure and tone mapped. The depth image takes one sample's
  // depth (GL's blit of depth picks one; facet's takes sample 0).
  void read(Framebuffer& target, const Output& output);
  // An 8-bit sRGB target (Color::srgb8): resolves the samples if there are several and waits
  // for OpenGL to finish (glFinish), reading nothing back.
  void finish();
  // After finish(): the codes OpenGL wrote into an 8-bit sRGB target, into target (same size,
  // rgba8_srgb), rows flipped; not its depth.
  void read_codes(Framebuffer& target);

 private:
  void make(int width, int height, int samples, Color color);
  // Multisampled: each pixel's samples averaged into the single-sample buffers (a blit), and,
  // when `depth`, one sample's depth.
  void resolve_samples(bool depth);
  GLuint framebuffer_ = 0, color_ = 0, depth_ = 0;           // single-sample: read back
  GLuint ms_framebuffer_ = 0, ms_color_ = 0, ms_depth_ = 0;  // multisampled: drawn into
  int width_ = 0, height_ = 0, samples_ = 0, asked_samples_ = 0;
  Color color_kind_ = Color::linear_float;
  bool warned_ = false;
};

}  // namespace facet::gl
