// Color spaces: facet works in linear light inside (materials, lights, clear colors are linear
// RGB); colors people pick or read off the screen are sRGB. These convert (IEC 61966-2-1), and
// tone mapping brings linear colors of any brightness into what a display shows.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>

namespace facet {

// An sRGB color with components in [0, 1] as linear RGB, and back.
glm::vec3 srgb_to_linear(glm::vec3 srgb);
glm::vec3 linear_to_srgb(glm::vec3 linear);

// Linear RGBA colors to the bytes of an rgba8_srgb framebuffer, as the renderer's resolve writes
// them: red, green and blue times `scale` (2^exposure) sRGB-encoded, within one code of
// round(linear_to_srgb(v) * 255) (v clamped to [0, 1], NaN as 0; docs/pipeline.md, "Resolve"),
// and alpha clamped and rounded to 8 bits. rgba takes four bytes a color and must hold them all.
void encode_srgb8(std::span<const glm::vec4> linear, std::span<std::uint8_t> rgba,
                  float scale = 1.0f);

// How linear colors of any brightness become colors a display can show, after the exposure
// and before the sRGB encode (docs/pipeline.md, "Tone mapping"). What is drawn is mapped, the
// environment background too; the clear color is not, nor what is drawn over it without
// writing depth (blended surfaces), nor a frame whose every draw writes display values (the
// normals, depth and texture-coordinate views). Each sample of a multisampled pixel is mapped
// before the samples are averaged. Float targets take the mapped linear values.
enum class ToneMapping {
  none,         // clip at 1 (each channel on its own)
  pbr_neutral,  // Khronos PBR Neutral: colors up to 0.76 keep hue and value (the darkest lose
                // at most 0.04), brighter ones roll off toward white
  aces,         // ACES filmic (Hill's fit, with three.js' 1/0.6 exposure): more contrast,
                // highlights desaturate
};

// Scales red, green and blue of linear colors by 2^exposure and maps them through curve, in
// place, as the renderer's resolve maps what is drawn (alpha unchanged): for images rendered
// into float targets with ToneMapping::none, to be mapped later.
void tone_map(ToneMapping curve, std::span<glm::vec4> colors, float exposure = 0.0f);

// The linear color that curve shows as display (linear, each channel in [0, 1]): the renderer
// fogs toward the fog color's inverse, so fully fogged surfaces meet a clear color of the fog's
// value. A color the curve cannot show gives the nearest it can: channels just under 1; for
// PBR Neutral, bright saturated colors as the brightest of their hue below its knee; for ACES,
// channels its matrices would need below 0 at 0. ToneMapping::none gives display itself.
glm::vec3 inverse_tone_map(ToneMapping curve, glm::vec3 display);

// What fog fades toward so that a fully fogged surface, scaled by exposure_scale (2^exposure)
// and mapped by curve, shows as fog_color does as a clear color (which is not mapped): the
// inverse of fog_color x exposure_scale (clipped to 1), over exposure_scale. ToneMapping::none
// gives fog_color.
glm::vec3 fog_color_under(ToneMapping curve, glm::vec3 fog_color, float exposure_scale);

}  // namespace facet
