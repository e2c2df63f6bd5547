// Stage: line raster. Reads segments from the tile's bin (set up in setup.cpp) and writes
// the tile's color and depth, like raster.hpp does for triangles.
//
// Fill rule for lines: walk the major axis. A segment covers, in each pixel column (x-major)
// or row (y-major) whose centre lies in the half-open span [start, end), the one pixel that
// contains the segment's point at that centre. The end is excluded, so a polyline's shared
// vertex is drawn once and segments never double a pixel. Everything is integer (fixed
// point), so a pixel's coverage does not depend on which tile evaluates it.
//
// Under MSAA a segment is a rectangle one pixel wide along the minor axis, as OpenGL
// rasterizes multisampled lines: it covers each sample whose major coordinate lies in [start,
// end) and whose minor coordinate lies within half a pixel of the segment there (the lower
// bound in, the upper out). The samples average into an anti-aliased line.
#include <algorithm>
#include <bit>
#include <cstdlib>

#include "pipeline/raster/raster.hpp"
#include "pipeline/setup/sample_positions.hpp"

namespace facet::pipeline {
namespace {

// Lines pass the depth test against the surface they outline: their depth is interpolated
// differently from the triangle's plane, so equality needs a little slack.
constexpr float kLineDepthBias = 2e-5f;

struct Walk {
  std::int64_t start, end;  // major-axis coordinates (fixed point)
  std::int64_t minor_start, minor_delta;
};

// Visits every major-axis pixel p in [lo, hi] whose centre lies in [start, end) (in the walk
// direction) and the minor-axis pixel holding the segment there.
template <class Visit>
void walk(const Walk& w, int lo, int hi, Visit&& visit) {
  std::int64_t delta = w.end - w.start;
  for (int p = lo; p <= hi; ++p) {
    std::int64_t c = pixel_centre(p);
    bool inside = delta > 0 ? (c >= w.start && c < w.end) : (c <= w.start && c > w.end);
    if (!inside) continue;
    // minor = minor_start + (c - start) * minor_delta / delta, floored; delta made positive.
    std::int64_t num = (c - w.start) * w.minor_delta, den = delta;
    if (den < 0) num = -num, den = -den;
    std::int64_t minor = w.minor_start + floor_div(num, den);
    float t = static_cast<float>(c - w.start) / static_cast<float>(delta);
    visit(p, static_cast<int>(floor_div(minor, kSubpixelScale)), t);
  }
}

// The samples of pixel (major p, minor q) that the segment's rectangle covers (see the top).
unsigned covered_samples(const Walk& w, int samples, bool x_major, int p, int q) {
  const SampleOffset* pattern = sample_pattern(samples);
  const std::int64_t delta = w.end - w.start;
  const std::int64_t den = delta < 0 ? -delta : delta;
  unsigned mask = 0;
  for (int s = 0; s < samples; ++s) {
    const std::int64_t major =
        pixel_centre(p) + (x_major ? pattern[s].x : pattern[s].y) * kSampleUnit;
    const std::int64_t minor =
        pixel_centre(q) + (x_major ? pattern[s].y : pattern[s].x) * kSampleUnit;
    const bool inside =
        delta > 0 ? (major >= w.start && major < w.end) : (major <= w.start && major > w.end);
    if (!inside) continue;
    std::int64_t num = (major - w.start) * w.minor_delta;
    if (delta < 0) num = -num;
    const std::int64_t line = w.minor_start + floor_div(num, den);
    if (minor >= line - kHalfPixel && minor < line + kHalfPixel) mask |= 1u << s;
  }
  return mask;
}

// Under MSAA each covered sample passes the depth test on its own, so a line along a
// multisampled silhouette is hidden exactly where the surface hides it.
void plot_samples(TileContext& tile, std::ptrdiff_t i, float z, const glm::vec4& color,
                  unsigned covered) {
  unsigned mask = 0;
  for (unsigned m = covered; m != 0; m &= m - 1) {
    const int s = std::countr_zero(m);
    if (z <= tile.depth[s * tile.sample_plane + i] + kLineDepthBias) mask |= 1u << s;
  }
  if (mask == 0) return;
  if (mask == (1u << tile.samples) - 1) {
    tile.split[i] = 0;  // every sample this color
    tile.color[i] = color;
  } else {
    split_pixel(tile, i);
    for (unsigned m = mask; m != 0; m &= m - 1) sample_color(tile, i, std::countr_zero(m)) = color;
  }
  for (unsigned m = mask; m != 0; m &= m - 1) {
    float& depth = tile.depth[std::countr_zero(m) * tile.sample_plane + i];
    depth = std::min(z, depth);
  }
  ++tile.pixels_shaded;
}

}  // namespace

// The multisampled segment: in each major-axis pixel of the tile, the pixel holding the
// segment at its centre and the one on either side, each with the samples it covers.
void raster_line_samples(TileContext& tile, const SetupLine& l, const Walk& w, bool x_major) {
  const int lo = x_major ? std::max(l.min_x, tile.x0) : std::max(l.min_y, tile.y0);
  const int hi = x_major ? std::min(l.max_x, tile.x1 - 1) : std::min(l.max_y, tile.y1 - 1);
  const std::int64_t delta = w.end - w.start;
  for (int p = lo; p <= hi; ++p) {
    const std::int64_t c = pixel_centre(p);
    std::int64_t num = (c - w.start) * w.minor_delta, den = delta;
    if (den < 0) num = -num, den = -den;
    const int centre =
        static_cast<int>(floor_div(w.minor_start + floor_div(num, den), kSubpixelScale));
    const float t =
        std::clamp(static_cast<float>(c - w.start) / static_cast<float>(delta), 0.0f, 1.0f);
    const float z = l.z0 + (l.z1 - l.z0) * t;
    for (int q = centre - 1; q <= centre + 1; ++q) {
      const int x = x_major ? p : q, y = x_major ? q : p;
      if (x < tile.x0 || x >= tile.x1 || y < tile.y0 || y >= tile.y1) continue;
      const unsigned covered = covered_samples(w, tile.samples, x_major, p, q);
      if (covered == 0) continue;
      const std::ptrdiff_t i =
          static_cast<std::ptrdiff_t>(y - tile.y0) * tile.stride + (x - tile.x0);
      plot_samples(tile, i, z, l.color, covered);
    }
  }
}

void raster_line(TileContext& tile, const SetupLine& l) {
  std::int64_t dx = std::int64_t{l.x1} - l.x0, dy = std::int64_t{l.y1} - l.y0;
  bool x_major = std::llabs(dx) >= std::llabs(dy);
  if (tile.samples > 1) {
    raster_line_samples(tile, l, x_major ? Walk{l.x0, l.x1, l.y0, dy} : Walk{l.y0, l.y1, l.x0, dx},
                        x_major);
    return;
  }
  auto plot = [&](int x, int y, float t) {
    if (x < tile.x0 || x >= tile.x1 || y < tile.y0 || y >= tile.y1) return;
    float z = l.z0 + (l.z1 - l.z0) * t;
    std::size_t i = static_cast<std::size_t>(y - tile.y0) * tile.stride + (x - tile.x0);
    if (!(z <= tile.depth[i] + kLineDepthBias)) return;
    tile.color[i] = l.color;
    tile.depth[i] = std::min(z, tile.depth[i]);
    ++tile.pixels_shaded;
  };
  if (x_major) {
    walk({l.x0, l.x1, l.y0, dy}, std::max(l.min_x, tile.x0), std::min(l.max_x, tile.x1 - 1),
         [&](int x, int y, float t) { plot(x, y, t); });
  } else {
    walk({l.y0, l.y1, l.x0, dx}, std::max(l.min_y, tile.y0), std::min(l.max_y, tile.y1 - 1),
         [&](int y, int x, float t) { plot(x, y, t); });
  }
}

}  // namespace facet::pipeline
