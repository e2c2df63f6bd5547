// Stage: raster under multisampling, the per-triangle part every MSAA path shares: what a
// triangle's samples add to its edge functions and depth at a pixel centre (SampleSteps), and
// the SIMD search for the covered samples of a box built from them (sample_box_search). Used by
// msaa.hpp for a triangle drawn alone and by small_triangles.hpp for those whose pixels wait.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/pixel_writer.hpp"
#include "pipeline/setup/sample_positions.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {

// The depth each sample of triangle t adds at its pixel centre, into z[0 .. samples) (rounded
// once, the same on every path); returns their least and greatest.
struct DepthSteps {
  float min, max;
};
inline DepthSteps sample_depth_steps(const SetupTriangle& t, int samples, float* z) {
  const SampleOffset* pattern = sample_pattern(samples);
  for (int s = 0; s < samples; ++s) {
    // Sixteenths are exact in float; no contraction (the build's -ffp-contract=off).
    z[s] = t.z.dx * (static_cast<float>(pattern[s].x) / 16.0f) +
           t.z.dy * (static_cast<float>(pattern[s].y) / 16.0f);
  }
  return {*std::min_element(z, z + samples), *std::max_element(z, z + samples)};
}

// What a triangle's samples add to its values at the pixel centre: each edge function's step
// (exact, fixed point) and the depth's (rounded once, the same on every path, so a sample's
// depth is fl(depth at the centre + step) wherever it is computed). Rounding is monotonic, so
// fl(a + min step) and fl(b + max step) bound the samples' depths of centres within [a, b].
struct SampleSteps {
  // Each sample's step of each edge in sixteenths of a pixel, the box search's unit: the
  // fixed-point step over kSampleUnit, exactly (sample offsets are whole sixteenths).
  std::int64_t step[3][kMaxSamples];
  std::int64_t edge_min[3], edge_max[3];  // the fixed-point steps' extremes
  DepthSteps depth;                       // the depth steps' extremes
  // The SIMD box search computes in 32 bits (SampleBoxSearch): only for these coefficients.
  bool fits_32_bits = true;

  // Fills z[0 .. samples) with the depth steps (the tile's sample_z while t is drawn).
  SampleSteps(const SetupTriangle& t, int samples, float* z) {
    // The usual counts unrolled: a triangle's steps are taken for every tile it is drawn in.
    switch (samples) {
      case 2:
        fill<2>(t, z);
        break;
      case 4:
        fill<4>(t, z);
        break;
      case 8:
        fill<8>(t, z);
        break;
      default:
        fill<kMaxSamples>(t, z, samples);
    }
  }

 private:
  template <int kSamples>
  void fill(const SetupTriangle& t, float* z, int samples = kSamples) {
    const SampleOffset* pattern = sample_pattern(samples);
    for (int i = 0; i < 3; ++i) {
      const std::int64_t a = t.a[i], b = t.b[i];
      fits_32_bits = fits_32_bits && std::abs(a) + std::abs(b) < (std::int64_t{1} << 18);
      edge_min[i] = edge_max[i] = (a * pattern[0].x + b * pattern[0].y) * kSampleUnit;
      for (int s = 0; s < kSamples && s < samples; ++s) {
        step[i][s] = a * pattern[s].x + b * pattern[s].y;
        edge_min[i] = std::min(edge_min[i], step[i][s] * kSampleUnit);
        edge_max[i] = std::max(edge_max[i], step[i][s] * kSampleUnit);
      }
    }
    depth = sample_depth_steps(t, samples, z);
  }
};

// The search of the pixels of [left, right] x [top, bottom] (frame pixels, at most kBlockPixels)
// for the samples triangle t covers that pass the depth test against the tile, its depth steps
// being sample_z (SampleSteps): for find_box_samples when steps.fits_32_bits, else for
// find_box_samples_wide.
template <bool kDepthTest>
SampleBoxSearch sample_box_search(const TileContext& tile, const SetupTriangle& t,
                                  const SampleSteps& steps, const float* sample_z, int left,
                                  int top, int right, int bottom) {
  SampleBoxSearch search;
  search.triangle = &t;
  search.x0 = left, search.y0 = top;
  search.width = right - left + 1, search.height = bottom - top + 1;
  search.samples = tile.samples;
  constexpr std::int64_t kClamp = std::int64_t{1} << 30;
  for (int i = 0; i < 3; ++i) {
    // floor(E / 16): the first centre lies on the sixteenths' grid, like every sample.
    const std::int64_t e_first = edge_at_centre(t, i, left, top) >> 4;
    search.e_first[i] = steps.fits_32_bits ? std::clamp(e_first, -kClamp, kClamp) : e_first;
  }
  search.step = steps.step;
  search.sample_z = sample_z;
  search.depth_test = kDepthTest;
  search.write_depth = false;
  search.depth =
      tile.depth + static_cast<std::ptrdiff_t>(top - tile.y0) * tile.stride + (left - tile.x0);
  search.depth_stride = tile.stride;
  search.plane = tile.sample_plane;
  return search;
}

}  // namespace facet::pipeline
