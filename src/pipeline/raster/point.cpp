// Stage: point raster. Reads points from the tile's bin (set up in setup.cpp) and writes the
// tile's color and depth, like line.cpp does for segments.
//
// Fill rule for points: a point of side s pixels centred at (cx, cy) (snapped to fixed point)
// covers the pixels whose centre lies in the half-open square [cx - s/2, cx + s/2) x
// [cy - s/2, cy + s/2). A whole s covers exactly s x s pixels wherever the centre lies, and
// points s pixels apart tile the plane without gaps or doubled pixels. Setup evaluates the
// rule in integers (setup.hpp's point_span) and stores the covered pixels as a box, so a
// pixel's coverage cannot depend on which tile draws it. The square is cut at the frame's edges;
// a point whose centre is outside the frustum is dropped whole (primitive.cpp).
//
// Depth: the centre's, at every pixel, tested (nearer than what is there) and written like an
// opaque triangle's. Points are unlit: their color was fixed at setup.
#include <algorithm>
#include <bit>

#include "pipeline/raster/raster.hpp"

namespace facet::pipeline {
namespace {

// Under MSAA a point covers every sample of its pixels (its square is not anti-aliased), each
// sample passing the depth test on its own.
void plot_samples(TileContext& tile, std::ptrdiff_t i, const SetupPoint& p) {
  unsigned mask = 0;
  for (int s = 0; s < tile.samples; ++s) {
    if (p.z < tile.depth[s * tile.sample_plane + i]) mask |= 1u << s;
  }
  if (mask == 0) return;
  if (mask == (1u << tile.samples) - 1) {
    tile.split[i] = 0;  // every sample this color
    tile.color[i] = p.color;
  } else {
    split_pixel(tile, i);
    for (unsigned m = mask; m != 0; m &= m - 1)
      sample_color(tile, i, std::countr_zero(m)) = p.color;
  }
  for (unsigned m = mask; m != 0; m &= m - 1)
    tile.depth[std::countr_zero(m) * tile.sample_plane + i] = p.z;
  ++tile.pixels_shaded;
}

}  // namespace

void raster_point(TileContext& tile, const SetupPoint& p) {
  const int x0 = std::max(p.min_x, tile.x0), x1 = std::min(p.max_x, tile.x1 - 1);
  const int y0 = std::max(p.min_y, tile.y0), y1 = std::min(p.max_y, tile.y1 - 1);
  for (int y = y0; y <= y1; ++y) {
    const std::size_t row = static_cast<std::size_t>(y - tile.y0) * tile.stride;
    for (int x = x0; x <= x1; ++x) {
      const std::size_t i = row + static_cast<std::size_t>(x - tile.x0);
      if (tile.samples > 1) {
        plot_samples(tile, static_cast<std::ptrdiff_t>(i), p);
        continue;
      }
      if (!(p.z < tile.depth[i])) continue;
      tile.color[i] = p.color;
      tile.depth[i] = p.z;
      ++tile.pixels_shaded;
    }
  }
}

}  // namespace facet::pipeline
