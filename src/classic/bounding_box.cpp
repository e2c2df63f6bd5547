// Classic rasterizer 1: the bounding box and barycentric weights (docs/classic/bounding_box.md).
//
// The idea: an edge function E(x, y) is twice the signed area of the triangle an edge makes
// with the point (x, y): positive on the inside of the edge, zero on its line. A pixel centre is
// in the triangle when all three are positive, so test every pixel of the triangle's screen
// box. Divided by the whole triangle's area, the three values are also the point's barycentric
// weights on screen: they interpolate depth as it is, and everything else after dividing by w.
#include <algorithm>
#include <cmath>

#include "classic/classic.hpp"

namespace facet::classic {
namespace {

// The edge function of the edge from p to q at (x, y), positive on the inside of a triangle
// wound clockwise on the y-down screen. The corners are snapped to 1/256 pixel and small (well
// under 2^20 pixels), so every difference and product here is an exact double: no rounding
// decides coverage, as in facet's fixed-point setup.
double edge(const ScreenVertex& p, const ScreenVertex& q, double x, double y) {
  return (double{q.x} - p.x) * (y - p.y) - (double{q.y} - p.y) * (x - p.x);
}

// The top-left rule (D3D11 functional spec 3.4.2.1): a centre exactly on an edge belongs to
// the triangle only if the edge is a top edge (horizontal, pointing right in a clockwise
// triangle) or a left edge (pointing up). Of two triangles sharing the edge, exactly one sees
// it as top or left, so the centre is covered once.
bool is_top_left(const ScreenVertex& p, const ScreenVertex& q) {
  return q.y < p.y || (q.y == p.y && q.x > p.x);
}

// The first and last pixel whose centre (p + 0.5) lies in [lo, hi], within [0, size - 1].
int first_centre(float lo, int size) {
  return static_cast<int>(std::clamp(std::ceil(lo - 0.5f), 0.0f, static_cast<float>(size)));
}
int last_centre(float hi, int size) {
  return static_cast<int>(std::clamp(std::floor(hi - 0.5f), -1.0f, size - 1.0f));
}

}  // namespace

void fill_bounding_box(const ScreenVertex v[3], bool fill_rule, Image& image) {
  // Per triangle: the box, the area, and which edges own the centres on them.
  const int x0 = first_centre(std::min({v[0].x, v[1].x, v[2].x}), image.width);
  const int x1 = last_centre(std::max({v[0].x, v[1].x, v[2].x}), image.width);
  const int y0 = first_centre(std::min({v[0].y, v[1].y, v[2].y}), image.height);
  const int y1 = last_centre(std::max({v[0].y, v[1].y, v[2].y}), image.height);
  const double area = edge(v[0], v[1], v[2].x, v[2].y);
  bool owns[3];  // owns[i]: the edge opposite corner i, from v[i + 1] to v[i + 2]
  for (int i = 0; i < 3; ++i) owns[i] = !fill_rule || is_top_left(v[(i + 1) % 3], v[(i + 2) % 3]);

  // Per pixel: three edge functions; if all three say inside, the weights and a fragment.
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      double e[3];
      bool inside = true;
      for (int i = 0; i < 3; ++i) {
        e[i] = edge(v[(i + 1) % 3], v[(i + 2) % 3], x + 0.5, y + 0.5);
        // Without the rule a centre on an edge is in both triangles sharing it.
        inside = inside && (e[i] > 0.0 || (e[i] == 0.0 && owns[i]));
      }
      if (!inside) continue;
      // Window depth is affine on screen: the screen weights e[i] / area interpolate it.
      const double z = (e[0] * v[0].z + e[1] * v[1].z + e[2] * v[2].z) / area;
      // The normal is affine in space, not on screen: weigh each corner by e[i] / w[i] and
      // renormalise, and the screen weights become the weights in space (perspective-correct).
      double weight[3], sum = 0.0;
      for (int i = 0; i < 3; ++i) sum += weight[i] = e[i] * v[i].inv_w;
      glm::dvec3 normal(0.0);
      for (int i = 0; i < 3; ++i) normal += weight[i] / sum * glm::dvec3(v[i].normal);
      write_fragment(image, x, y, static_cast<float>(z), glm::vec3(normal));
    }
  }
}

}  // namespace facet::classic
