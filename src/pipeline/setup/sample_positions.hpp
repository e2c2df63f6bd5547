// Multisample positions: where in a pixel the samples of 2, 4, 8 and 16x MSAA lie. Setup and
// binning read the samples' reach (kSampleReach), setup's small-triangle probe and the MSAA
// raster (raster/msaa.hpp) the positions themselves; tests check coverage against them.
#pragma once

#include <cstdint>

#include "pipeline/setup/fixed_point.hpp"

namespace facet::pipeline {

// The D3D11 standard sample patterns (D3D11_STANDARD_MULTISAMPLE_PATTERN, the same positions
// OpenGL implementations use), as offsets from the pixel centre in 1/16 pixel, y down. With 8
// sub-pixel bits they are exact: offset * 16 fixed-point units.
struct SampleOffset {
  std::int8_t x, y;
};
inline constexpr int kMaxSamples = 16;
inline constexpr SampleOffset kSamples1[1] = {{0, 0}};
inline constexpr SampleOffset kSamples2[2] = {{4, 4}, {-4, -4}};
inline constexpr SampleOffset kSamples4[4] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
inline constexpr SampleOffset kSamples8[8] = {{1, -3}, {-1, 3},  {5, 1}, {-3, -5},
                                              {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
inline constexpr SampleOffset kSamples16[16] = {
    {1, 1},  {-1, -3}, {-3, 2},  {4, -1}, {-5, -2}, {2, 5},  {5, 3}, {3, -5},
    {-2, 6}, {0, -7},  {-4, -6}, {-6, 4}, {-8, 0},  {7, -4}, {6, 7}, {-7, -8}};

// The pattern of `samples` per pixel (1, 2, 4, 8 or 16: Renderer checks).
inline const SampleOffset* sample_pattern(int samples) {
  switch (samples) {
    case 2:
      return kSamples2;
    case 4:
      return kSamples4;
    case 8:
      return kSamples8;
    case 16:
      return kSamples16;
    default:
      return kSamples1;
  }
}

// Fixed-point units per 1/16 pixel of a sample offset.
inline constexpr std::int32_t kSampleUnit = kSubpixelScale / 16;

// Every sample of every pattern lies within half a pixel of its pixel's centre (offsets -8 to
// 7 sixteenths): a pixel whose centre is up to kSampleReach fixed-point units outside a shape
// may have a sample inside it. Setup widens triangles' pixel boxes by it and binning its tile
// tests, when the frame has more than one sample.
inline constexpr std::int32_t kSampleReach = kHalfPixel;

// How far from a pixel's centre the samples of a frame of `samples` a pixel lie: kSampleReach,
// or 0 at one sample. Culling, setup, binning and the occlusion tests widen boxes by it alike.
inline std::int32_t sample_reach(int samples) { return samples > 1 ? kSampleReach : 0; }

}  // namespace facet::pipeline
