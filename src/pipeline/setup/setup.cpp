// Stage: setup (see setup.hpp).
#include "pipeline/setup/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "pipeline/setup/fixed_point.hpp"

namespace facet::pipeline {
Plane make_plane(const float x[3], const float y[3], const float value[3]) {
  return PlaneSolver(x, y).plane(value);
}

bool setup_line(PrimitiveSink& out, int width, int height, const ScreenVertex& s0,
                const ScreenVertex& s1, const glm::vec4& color) {
  if (s0.x == s1.x && s0.y == s1.y) return false;
  SetupLine l;
  l.x0 = s0.x, l.y0 = s0.y, l.x1 = s1.x, l.y1 = s1.y;
  l.z0 = s0.z, l.z1 = s1.z;
  // The pixels the segment passes through and one more on every side: under MSAA it is a
  // rectangle one pixel wide, whose samples reach into the neighbours (line.cpp).
  l.min_x = std::max(0, static_cast<int>(floor_div(std::min(l.x0, l.x1), kSubpixelScale)) - 1);
  l.min_y = std::max(0, static_cast<int>(floor_div(std::min(l.y0, l.y1), kSubpixelScale)) - 1);
  l.max_x =
      std::min(width - 1, static_cast<int>(floor_div(std::max(l.x0, l.x1), kSubpixelScale)) + 1);
  l.max_y =
      std::min(height - 1, static_cast<int>(floor_div(std::max(l.y0, l.y1), kSubpixelScale)) + 1);
  if (l.min_x > l.max_x || l.min_y > l.max_y) return false;
  l.color = color;
  out.add_line(l.min_x, l.min_y, l.max_x, l.max_y) = l;
  return true;
}

bool setup_point(PrimitiveSink& out, int width, int height, const ScreenVertex& s,
                 std::int32_t half, const glm::vec4& color) {
  const PixelSpan x = point_span(s.x, half), y = point_span(s.y, half);
  SetupPoint p;
  p.min_x = std::max(0, x.first), p.max_x = std::min(width - 1, x.last);
  p.min_y = std::max(0, y.first), p.max_y = std::min(height - 1, y.last);
  if (p.min_x > p.max_x || p.min_y > p.max_y) return false;
  p.z = s.z;
  p.color = color;
  out.add_point(p.min_x, p.min_y, p.max_x, p.max_y) = p;
  return true;
}

}  // namespace facet::pipeline
