// The viewer's third backend mode (B): where facet's image and its OpenGL twin's disagree,
// each channel's difference amplified so that one level of 255 shows.
#pragma once

#include "facet/framebuffer.hpp"

namespace facet::cli {

// How much a difference is magnified: 8 levels of difference show as 64 (a quarter of the
// range), a whole edge pixel of another color as full brightness.
inline constexpr int kDifferenceGain = 8;

// shown = |shown - other| x gain per color channel (8-bit sRGB codes), opaque. The two are
// rgba8_srgb framebuffers of the same size.
void show_difference(Framebuffer& shown, const Framebuffer& other, int gain = kDifferenceGain);

}  // namespace facet::cli
