// Stage: raster + shade, the small-triangle path: triangles whose bounding box in the tile is
// a few pixels (up to kMaxWaitingTriangleBox for draws whose pixels wait) skip raster.hpp's
// 8x8 blocks. Their covered pixels are found a box row at a time, and those of consecutive
// small triangles of one draw wait to be shaded together (WaitingPixels).
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>

#include "pipeline/raster/block_raster.hpp"
#include "pipeline/raster/pixel_writer.hpp"
#include "pipeline/raster/sample_steps.hpp"

namespace facet::pipeline {

// Triangles whose bounding box in the tile is at most this many pixels skip the block
// machinery: for them, one pixel at a time is cheaper than classifying and dispatching blocks.
inline constexpr int kSmallTrianglePixels = 64;

// The covered pixels of the small triangle t's bounding box [x0, x1] x [y0, y1] (inclusive)
// that pass the depth test: their positions go to out.x, y from entry `first` on (their depths
// come with their interpolation); returns how many. Same arithmetic as cover_block, so the same
// pixels get the same values; SIMD across a box row (find_box_pixels).
template <class Shading>
int find_small_pixels(const TileContext& tile, const SetupTriangle& t, int x0, int y0, int x1,
                      int y1, PackedPixels& out, int first) {
  const float* depth =
      tile.depth + static_cast<std::ptrdiff_t>(y0 - tile.y0) * tile.stride + (x0 - tile.x0);
  return tile.kernels.find_box_pixels(t, x0, y0, x1 - x0 + 1, y1 - y0 + 1, depth, tile.stride,
                                      depth_tested<Shading>(), out.x + first, out.y + first);
}

// The loop over the bounding box [x0, x1] x [y0, y1] (inclusive), for small triangles: finds
// the covered pixels that pass the depth test a box row at a time, then interpolates their
// varyings with SIMD (interpolate_pixels) and shades them.
template <class Shading, AlphaMode kAlpha>
void raster_small_triangle(TileContext& tile, const SetupTriangle& t, int x0, int y0, int x1,
                           int y1, PixelWriter<Shading, kAlpha>& out) {
  static_assert(kSmallTrianglePixels <= PackedPixels::kCapacity);
  PackedPixels found;
  found.count = find_small_pixels<Shading>(tile, t, x0, y0, x1, y1, found, 0);
  if (found.count == 0) return;
  found.pad(0);  // interpolate_pixels reads whole vectors of positions
  tile.kernels.interpolate_pixels(t, out.fragment.planes, Shading::kVaryings, 0, found.count,
                                  found.x, found.y, found.z, found.w, found.v);
  out.shade(found);
}

// Pixels of consecutive small triangles of one draw, waiting to be shaded together. Shaded a
// triangle at a time, a few pixels each, every triangle would pay the SIMD sampling and shading
// calls' fixed costs and mostly empty lanes. Only opaque, depth-tested and -writing, batch-shaded
// draws wait (PixelWriter::kWaits); whatever else the tile draws first shades and writes what waits
// (flush_waiting). A waiting pixel passed the depth test against the tile as it was before the
// others waited; when written it is tested again, against what the pixels before it wrote: so a
// pixel writes exactly when drawing the triangles one by one would have written it, with the same
// color. Under MSAA a waiting pixel carries the samples its triangle covers that passed the
// depth test when it was found, and the search wrote their depths then (find_small_samples): so
// each triangle's search tests against the depths of the triangles before it, exactly as drawing
// them one by one, and the colors, written later in the same order, end where drawing one by one
// leaves them (a sample a later triangle won is written again after). No sample is tested twice,
// and writing a waiting pixel is writing its color (the pixel is shaded once at its centre
// whatever its samples, so its color is the one drawing triangles one by one gives).
struct WaitingPixels {
  // Positions start at zero: interpolate_pixels reads whole vectors of them, the entries after
  // the last one found too, which then hold zeros, earlier pixels' positions or what the
  // search stored past what it found (all inside the tile; ignored).
  WaitingPixels() {
    std::fill(std::begin(pixels.x), std::end(pixels.x), 0);
    std::fill(std::begin(pixels.y), std::end(pixels.y), 0);
  }
  PackedPixels pixels;
  // MSAA: each waiting pixel's samples (bits), alongside its position (and like the positions,
  // with room for a box found past a batch and for the search's whole-vector stores).
  std::uint16_t masks[std::size(PackedPixels{}.x)];
  // Each pixel's triangle's plane slopes for the texture's level of detail (TexelBatch).
  alignas(64) float slopes[shading::TexelBatch::kSlopes][PackedPixels::kCapacity];
  std::uint32_t draw = 0;
  void (*flush)(TileContext&) = nullptr;  // shades and writes them; null: none wait
  // Each waiting triangle and its number of pixels, in order: each run of pixels starts where
  // the one before ends. Their varyings are interpolated when they are shaded (write_waiting),
  // not as each triangle's pixels are found: read right after the search stored them, the
  // positions' loads would span several of its row stores and wait for them to retire.
  InterpolationRun runs[PackedPixels::kCapacity];
  int run_count = 0;
};

// Boxes of at most this many pixels join the waiting pixels in one piece: interpolate_pixels
// writes up to 7 entries past the last one found, and those must stay in the arrays.
inline constexpr int kMaxWaitingBox = PackedPixels::kCapacity - 8;
// A search starts after at most kMaxWaitingBox waiting pixels, finds at most a box's pixels
// and stores up to kBoxSearchSlack entries past them: all inside the positions' arrays.
static_assert(kMaxWaitingBox + kBlockPixels + kBoxSearchSlack <=
              static_cast<int>(std::size(PackedPixels{}.x)));

// Triangles whose box in the tile is at most this many pixels, and at most kMaxWaitingBox
// wide, wait too, a band of rows of at most kMaxWaitingBox pixels at a time. Up to this size,
// finding their pixels a box row at a time and shading them with other triangles' beats
// raster.hpp's 8x8 blocks, as batches fill with pixels found rather than with boxes
// (add_waiting_band); larger boxes gain nothing more.
inline constexpr int kMaxWaitingTriangleBox = 512;

// Whether a triangle whose box in the tile is width x height pixels may wait (add_waiting).
inline bool box_may_wait(int width, int height) {
  return width * height <= kMaxWaitingTriangleBox && width <= kMaxWaitingBox;
}

// MSAA: the pixels of the small triangle t's box [x0, x1] x [y0, y1] (inclusive, at most
// kBlockPixels) with covered samples that pass the depth test, t's depth steps being sample_z
// (steps.fits_32_bits): positions to out.x, y and sample bits to masks from entry `first` on;
// returns how many. The same search as msaa.hpp's for a triangle drawn alone, and it writes the
// depths of the samples it finds (WaitingPixels: the colors follow when the pixels are written).
template <class Shading>
int find_small_samples(const TileContext& tile, const SetupTriangle& t, const SampleSteps& steps,
                       const float* sample_z, int x0, int y0, int x1, int y1, PackedPixels& out,
                       std::uint16_t* masks, int first) {
  SampleBoxSearch search =
      sample_box_search<depth_tested<Shading>()>(tile, t, steps, sample_z, x0, y0, x1, y1);
  search.write_depth = true;
  return tile.kernels.find_box_samples(search, out.x + first, out.y + first, masks + first);
}

// Shades and writes whatever waits in the tile (WaitingPixels).
inline void flush_waiting(TileContext& tile) {
  if (tile.waiting->flush != nullptr) tile.waiting->flush(tile);
}

// WaitingPixels::flush for draws of this shading model and alpha mode.
template <class Shading, AlphaMode kAlpha>
void write_waiting(TileContext& tile) {
  WaitingPixels& waiting = *tile.waiting;
  PackedPixels& pixels = waiting.pixels;
  const Plane* planes = tile.frame->planes.data();
  tile.kernels.interpolate_runs(waiting.runs, waiting.run_count, planes, Shading::kVaryings,
                                pixels.x, pixels.y, pixels.z, pixels.w, pixels.v);
  for (int n = pixels.count; n % 8 != 0; ++n) {  // read by the SIMD sampler, then ignored
    for (auto& slope : waiting.slopes) slope[n] = 0.0f;
  }
  static_assert(!edge_overlay<Shading>(), "waiting pixels are stored without the wire overlay");
  PixelWriter<Shading, kAlpha> out(tile, waiting.draw);
  alignas(64) float colors[PackedPixels::kCapacity][4];
  alignas(64) std::uint32_t shown[PackedPixels::kCapacity];  // their codes, for a tile of codes
  out.shade_waiting(pixels, waiting.slopes, colors, tile.codes != nullptr ? shown : nullptr);
  if (tile.samples == 1) {
    // PixelWriter::store for these draws (opaque, depth-writing, no overlay), with the tile's
    // values and the count in locals: through the tile, each would be read again after every
    // store (a code's store may alias the count).
    static_assert(decltype(out)::kWaits && decltype(out)::kDepthWrite);
    float* const depth = tile.depth;
    glm::vec4* const color = tile.color;
    std::uint32_t* const codes = tile.codes;
    const std::ptrdiff_t stride = tile.stride;
    const int x0 = tile.x0, y0 = tile.y0, count = pixels.count;
    std::uint64_t written = 0;
    for (int n = 0; n < count; ++n) {
      const std::ptrdiff_t pixel = (pixels.y[n] - y0) * stride + (pixels.x[n] - x0);
      if (!(pixels.z[n] < depth[pixel])) continue;  // a pixel before it is nearer
      const float* c = colors[n];
      if (codes != nullptr) {
        codes[pixel] = shown[n];
      } else {
        blend_into<Shading, kAlpha>(color[pixel], glm::vec4(c[0], c[1], c[2], c[3]));
      }
      depth[pixel] = pixels.z[n];
      ++written;
    }
    out.shaded += written;
  } else {
    // Their samples' depths are in the tile already (find_small_samples): the colors follow,
    // in the same order.
    static_assert(SampleWriter<Shading, kAlpha, false>::kReplaces && !writes_data<Shading>(),
                  "waiting draws are opaque surfaces");
    const SampleColorWrite to{reinterpret_cast<float*>(tile.color),
                              reinterpret_cast<float*>(tile.sample_colors),
                              tile.split,
                              tile.stride,
                              tile.x0,
                              tile.y0,
                              tile.samples};
    tile.kernels.write_sample_colors(to, colors, pixels.x, pixels.y, waiting.masks, pixels.count);
    tile.pixels_shaded += pixels.count;
  }
  waiting.run_count = 0;
  tile.pixels_shaded += out.shaded;
  pixels.count = 0;
  waiting.flush = nullptr;
}

// Adds triangle t's pixels in the box [x0, x1] x [y0, y1] (inclusive, at most kMaxWaitingBox
// pixels) to the tile's waiting pixels. Under MSAA, steps and sample_z are t's (SampleSteps);
// at one sample they are null.
template <class Shading, AlphaMode kAlpha>
void add_waiting_band(TileContext& tile, const SetupTriangle& t, const SampleSteps* steps,
                      const float* sample_z, int x0, int y0, int x1, int y1) {
  WaitingPixels& waiting = *tile.waiting;
  PackedPixels& pixels = waiting.pixels;
  // A triangle covers about half its box: what waits is shaded first when even that would not
  // fit. Otherwise the pixels are found after what waits (the arrays have room for a whole
  // box past a batch), and when they do not fit after all, what waited is shaded and they move
  // to the front: batches fill with pixels found rather than with boxes.
  const int box = (x1 - x0 + 1) * (y1 - y0 + 1);
  if (waiting.flush != nullptr &&
      (waiting.draw != t.draw || pixels.count + box / 2 > kMaxWaitingBox)) {
    waiting.flush(tile);
  }
  int first = pixels.count;
  const int found = steps == nullptr
                        ? find_small_pixels<Shading>(tile, t, x0, y0, x1, y1, pixels, first)
                        : find_small_samples<Shading>(tile, t, *steps, sample_z, x0, y0, x1, y1,
                                                      pixels, waiting.masks, first);
  if (found == 0) return;
  if (first + found > kMaxWaitingBox) {
    std::int16_t x[kMaxWaitingBox], y[kMaxWaitingBox];
    std::uint16_t masks[kMaxWaitingBox];
    std::copy_n(pixels.x + first, found, x);
    std::copy_n(pixels.y + first, found, y);
    if (steps != nullptr) std::copy_n(waiting.masks + first, found, masks);
    waiting.flush(tile);  // pads past what waited: over these
    std::copy_n(x, found, pixels.x);
    std::copy_n(y, found, pixels.y);
    if (steps != nullptr) std::copy_n(masks, found, waiting.masks);
    first = 0;
  }
  pixels.count = first + found;
  InterpolationRun& run = waiting.runs[waiting.run_count++];
  run.triangle = &t;
  run.count = found;
  if constexpr (base_color_texcoord<Shading>() >= 0) {
    const Plane* uv = tile.frame->planes.data() + t.varying_planes + base_color_texcoord<Shading>();
    const float slopes[shading::TexelBatch::kSlopes] = {uv[0].dx, uv[1].dx,   uv[0].dy,
                                                        uv[1].dy, t.inv_w.dx, t.inv_w.dy};
    // Whole runs of eight (vector stores, no remainder loop): the entries past the last pixel
    // are before kMaxWaitingBox + 8, inside the arrays, and later pixels or the pad overwrite
    // them.
    static_assert(kMaxWaitingBox + 8 <= PackedPixels::kCapacity);
    for (int k = 0; k < shading::TexelBatch::kSlopes; ++k) {
      float* out = waiting.slopes[k] + first;
      for (int j = 0; j < found; j += 8) {
        for (int lane = 0; lane < 8; ++lane) out[j + lane] = slopes[k];
      }
    }
  }
  waiting.draw = t.draw;
  waiting.flush = &write_waiting<Shading, kAlpha>;
}

// Adds small triangle t's pixels in its bounding box [x0, x1] x [y0, y1] (inclusive;
// box_may_wait) to the tile's waiting pixels, a band of rows at a time. Under MSAA, steps and
// sample_z are t's (SampleSteps, fits_32_bits); at one sample they are null.
template <class Shading, AlphaMode kAlpha>
void add_waiting(TileContext& tile, const SetupTriangle& t, int x0, int y0, int x1, int y1,
                 const SampleSteps* steps = nullptr, const float* sample_z = nullptr) {
  const int rows = kMaxWaitingBox / (x1 - x0 + 1);
  for (int y = y0; y <= y1; y += rows) {
    add_waiting_band<Shading, kAlpha>(tile, t, steps, sample_z, x0, y, x1,
                                      std::min(y + rows - 1, y1));
  }
}

}  // namespace facet::pipeline
