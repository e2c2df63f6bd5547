// Stage: raster, the SIMD part. raster.hpp walks a triangle's 8x8 pixel blocks inside a tile
// and asks cover_block (block_raster.cpp, compiled for every SIMD target Highway supports and
// picked at run time) which pixels of one block the triangle covers and pass the depth test,
// with their depth and perspective-correct varyings; raster.hpp then shades those pixels.
#pragma once

#include <cstdint>

#include "core/simd_target.hpp"
#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Pixels per block side. Blocks are aligned to the tile origin, so tiles of 8, 16, ... 128
// pixels hold whole blocks (the last row/column of a frame may hold partial ones).
inline constexpr int kBlockSize = 8;
inline constexpr int kBlockPixels = kBlockSize * kBlockSize;

// One triangle over one block. Edge i at block pixel (x, y) is e[i] + a[i]*x + b[i]*y.
//
// Why 32 bits are enough: the full edge function E = A*X + B*Y + C (setup.hpp) is evaluated
// at pixel centres, which are 256 fixed-point units apart, so E(x, y) = E(0, 0) + 256*(a*x +
// b*y) with a, b the SetupTriangle's coefficients, and E >= 0 exactly when
// floor(E(0, 0) / 256) + a*x + b*y >= 0. That is what e holds. raster.hpp only passes an edge
// that crosses the block rectangle [x_begin, x_end) x [y_begin, y_end) (>= 0 at some of its
// corners, < 0 at others), so |e| <= 7 * (|a| + |b|); the kernel steps e over all 8 columns
// and rows, to at most 14 * (|a| + |b|) < 2^28 for coefficients within 2^23 (fixed_point.hpp).
// An edge that is inside at all four corners is passed as e = a = b = 0 (always inside).
struct BlockInput {
  std::int32_t e[3];
  std::int32_t a[3];
  std::int32_t b[3];
  // The block pixels the triangle may touch: columns [x_begin, x_end), rows [y_begin, y_end).
  int x_begin, x_end, y_begin, y_end;
  // Every pixel of the whole 8x8 block is inside all three edges (classify_edges; under MSAA,
  // every sample: classify_samples): no edge tests.
  bool covers_block = false;
  float px0, py0;  // centre of block pixel (0, 0), in frame pixels
  const SetupTriangle* triangle;
  const Plane* varying_planes;  // triangle->varying_planes resolved
  int varyings;
  // false: every covered pixel passes. Runtime: constant per draw, taken the same way in every
  // block (compile-time in the raster loop that calls this; BENCHMARKS.md, "Per-draw constants").
  bool depth_test;
  const float* depth;  // the tile's depth at block pixel (0, 0)
  int depth_stride;    // floats per depth row
  // false: the mask and depths only (BlockFragments::w and v left as they were), for blocks
  // whose pixels are packed and interpolated afterwards (interpolate_pixels).
  bool interpolate = true;
};

// What cover_block finds, structure of arrays indexed by y * 8 + x. Lanes whose mask bit is
// clear hold unspecified values; w and v are only filled when BlockInput::interpolate.
struct BlockFragments {
  std::uint64_t mask;  // bit y * 8 + x: covered and passes the depth test
  alignas(64) float z[kBlockPixels];
  alignas(64) float w[kBlockPixels];  // clip w = 1 / (1/w plane)
  alignas(64) float v[kMaxVaryings][kBlockPixels];
};

// Floats the tile's depth buffer holds past its last pixel: the pixel search reads whole
// vectors of a box row, which at the tile's last row may reach past its end.
inline constexpr int kDepthSlack = 16;

// Entries the pixel search may write past the last pixel it finds (RasterKernels).
inline constexpr int kBoxSearchSlack = 16;

// A box search under MSAA (raster/msaa.hpp): the pixels of the box of `width` x `height` pixels
// at frame pixel (x0, y0), at most kBlockPixels, whose samples triangle t covers and pass the
// depth test. Edge values are counted in sixteenths of a pixel, the grid the sample positions lie
// on: floor(E / 16) at the box's first pixel centre is e_first (clamped to +-2^30 for 32 bits), a
// pixel step adds 16 * a, sample s adds step[i][s] (a * offset x + b * offset y). Exact in 32 bits
// when |a| + |b| < 2^18 for every edge (SampleSteps::fits_32_bits; the others take the search
// in doubles, unclamped): the steps across a box of 64 pixels stay within 2^28, so a clamped
// e_first keeps every sign.
struct SampleBoxSearch {
  const SetupTriangle* triangle;
  int x0, y0, width, height;
  int samples;
  std::int64_t e_first[3];
  const std::int64_t (*step)[16];  // each sample's edge steps (SampleSteps::step)
  const float* sample_z;           // the depth step of each sample (TileContext::sample_z)
  bool depth_test;
  // find_box_samples only (with depth_test): each sample found takes its depth in the tile
  // at once, as a draw that writes depth without an alpha test would (small_triangles.hpp).
  bool write_depth;
  float* depth;  // plane 0's depth at the box's first pixel; kDepthSlack readable after
  int depth_stride;
  std::ptrdiff_t plane;  // floats between sample planes
};

// Waiting pixels' colors written to the samples found for them (small_triangles.hpp's
// write_waiting; opaque surfaces, so alpha is written as 1): pixel n, at frame pixel (x[n],
// y[n]), takes colors[n] at the samples of masks[n]; a pixel that was not split gives its other
// samples its old color, and is split afterwards unless every sample took the new one
// (TileContext::split).
struct SampleColorWrite {
  float* color;         // the tile's colors (sample 0), RGBA floats (TileContext::color)
  float* others;        // samples 1 ... samples - 1 (TileContext::sample_colors)
  std::uint8_t* split;  // TileContext::split
  int stride;           // pixels per tile row
  int x0, y0;           // the tile's first frame pixel
  int samples;
};

// A run of waiting pixels (small_triangles.hpp): `count` consecutive entries of one triangle's.
struct InterpolationRun {
  const SetupTriangle* triangle;
  int count;
};

// The raster's SIMD kernels (block_raster.cpp, compiled for every target Highway supports) for
// the target chosen now, as plain function pointers: the raster loops call them a triangle or
// a block at a time, so dispatching each call (asking libhwy for the chosen target, then
// copying the arguments again in a wrapper) would add its overhead to every triangle and block.
// Each tile fetches them once (TileContext), so a target forced between frames (tests) is still
// honoured. Every kernel repeats the scalar path's arithmetic lane by lane (same operations in
// the same order, no fused multiply-add), so every target gives identical values.
struct RasterKernels {
  // Fills out for one block.
  void (*cover_block)(const BlockInput& in, BlockFragments& out);
  // The small-triangle path's part of cover_block (raster.hpp): the depth, clip w and the
  // perspective-correct varyings of `count` pixels of triangle t at frame pixels (x[n], y[n]),
  // n = first ... first + count - 1, into z[n], w[n] and v[k][n], the same values cover_block
  // gives. Computes whole vectors: entries up to first + the next multiple of 8 past count are
  // written too (from x, y there, which must be readable), so that must stay within
  // kBlockPixels.
  void (*interpolate_pixels)(const SetupTriangle& t, const Plane* varying_planes, int varyings,
                             int first, int count, const std::int16_t* x, const std::int16_t* y,
                             float* z, float* w, float (*v)[kBlockPixels]);
  // interpolate_pixels for runs of pixels of one triangle each, one after the other from entry 0
  // on, each triangle's varying planes at its varying_planes in `planes` (the frame's): one call
  // for a batch of small triangles' pixels instead of one a triangle.
  void (*interpolate_runs)(const InterpolationRun* runs, int run_count, const Plane* planes,
                           int varyings, const std::int16_t* x, const std::int16_t* y, float* z,
                           float* w, float (*v)[kBlockPixels]);
  // The small-triangle path's pixel search (small_triangles.hpp): the pixels of the box of
  // `width` x `height` pixels at frame pixel (x0, y0) whose centres triangle t covers and, if
  // depth_test, whose depth is less than the tile's there (`depth` points at the box's first
  // pixel, rows `depth_stride` floats apart, kDepthSlack readable floats after the last).
  // Their positions go to x[n], y[n] from n = 0; returns how many. Each row is stored as whole
  // vectors, so up to kBoxSearchSlack entries past the last found are written too, with values
  // of no use (the box's other pixels, or zeros): full stores, unlike masked ones, forward to
  // the interpolation's loads. The box holds at most kBlockPixels pixels. Same coverage as the
  // 64-bit edge functions, same depths as evaluate_row and evaluate_in_row. The depths it tests
  // are not stored: interpolate_pixels computes them again, as it does w, with the same
  // operations. (Compressing them too would take a second compress per row, the search's
  // largest cost.)
  int (*find_box_pixels)(const SetupTriangle& t, int x0, int y0, int width, int height,
                         const float* depth, int depth_stride, bool depth_test, std::int16_t* x,
                         std::int16_t* y);
  // find_box_pixels for a depth-only draw (depth_only.hpp), depth-tested: the pixels found take
  // their depths, in the same rows' order; returns how many. Nothing else is stored.
  int (*write_box_depths)(const SetupTriangle& t, int x0, int y0, int width, int height,
                          float* depth, int depth_stride);
  // The MSAA box search (SampleBoxSearch): the pixels with a covered sample that passes the
  // depth test (the samples of the 64-bit edge functions, and the sample depths z at the centre
  // as evaluate_row and evaluate_in_row give it plus sample_z[s]): positions to x[n], y[n],
  // sample bits to masks[n], from n = 0; returns how many. For triangles whose coefficients
  // allow 32 bits (SampleSteps::fits_32_bits); like find_box_pixels it stores whole vectors, up
  // to kBoxSearchSlack entries past the last found. With write_depth, the samples found take
  // their depths (masked stores: the tile's other depths keep theirs).
  int (*find_box_samples)(const SampleBoxSearch& search, std::int16_t* x, std::int16_t* y,
                          std::uint16_t* masks);
  // The same search for the other triangles, with the edge functions in doubles; it stores the
  // pixels found only, and never depths (write_depth is for triangles that fit 32 bits).
  int (*find_box_samples_wide)(const SampleBoxSearch& search, std::int16_t* x, std::int16_t* y,
                               std::uint16_t* masks);
  // Writes `count` waiting pixels' colors in order (SampleColorWrite), a pixel's samples with
  // selects rather than branches on its mask and on whether it was split: along a small
  // triangle's edges both are as good as random to the branch predictor.
  void (*write_sample_colors)(const SampleColorWrite& to, const float (*colors)[4],
                              const std::int16_t* x, const std::int16_t* y,
                              const std::uint16_t* masks, int count);
  // Whether every sample of a whole 8x8 block of a triangle covering them all (msaa.hpp) is in
  // front: each sample's depth, z at the pixel's centre (cover_block's, row by row) plus
  // sample_z[s], less than the tile's there (`depth` points at the block's first pixel of
  // sample plane 0, rows `stride` floats apart, planes `plane` apart; NaN fails).
  bool (*block_samples_in_front)(const float* z, const float* sample_z, int samples,
                                 const float* depth, std::ptrdiff_t stride, std::ptrdiff_t plane);
  // Those samples take those depths.
  void (*write_block_sample_depths)(const float* z, const float* sample_z, int samples,
                                    float* depth, std::ptrdiff_t stride, std::ptrdiff_t plane);
};
RasterKernels raster_kernels(SimdTarget target);

// Name of the SIMD target the kernels run on now (e.g. "AVX2"), for bench output and tests.
const char* simd_target_name();

}  // namespace facet::pipeline
