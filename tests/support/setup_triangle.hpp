// A triangle set up as raster receives it, from three screen vertices, for the tests of the
// raster's SIMD searches (small_box_test, sample_box_test).
#pragma once

#include <random>

#include "pipeline/setup/setup.hpp"

namespace facet::test {

// The frame the triangles are set up in.
inline constexpr int kSetupWidth = 1920, kSetupHeight = 1080;

// The triangle through three screen vertices (fixed point) as setup gives it to raster, or
// false when setup drops it.
bool set_up_triangle(const pipeline::ScreenVertex s[3], pipeline::SetupTriangle& out);

// A triangle of vertices within size / 2 pixels of a random point (cx, cy) at least 100 pixels
// inside the frame, at random depths, set up (set_up_triangle); false when setup drops it.
bool random_triangle(std::mt19937& rng, float size, float& cx, float& cy,
                     pipeline::SetupTriangle& out);

}  // namespace facet::test
