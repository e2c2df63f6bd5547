// Classic rasterizer 3: a ray per pixel, intersected with the triangle's plane, then an inside
// test (docs/classic/ray_per_pixel.md).
//
// The idea: send a ray from the eye through each pixel centre, find where it meets the plane of
// the triangle, and ask whether that point is inside the triangle. Nothing is projected or
// clipped: a ray either meets the triangle between the near and far planes or it does not, and
// the hit point's barycentric weights are weights in space, so interpolation is
// perspective-correct by construction. The price is 3D arithmetic for every pixel and triangle.
#include <cmath>
#include <glm/glm.hpp>

#include "classic/classic.hpp"

namespace facet::classic {
namespace {

// The textbook test (fill rule off): the plane's normal N = (b - a) x (c - a); the ray meets
// the plane at t = N.(a - o) / N.d; the hit P is inside when, for each edge, the triangle it
// makes with P turns the same way as N. Those three areas, over N.N, are P's weights. A centre
// on an edge shared by two triangles is decided twice, from two different planes and hits, so
// rounding may give it to both triangles or to neither.
bool textbook_hit(const glm::dvec3 p[3], glm::dvec3 o, glm::dvec3 d, double weight[3]) {
  const glm::dvec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double along = glm::dot(normal, d);
  if (along == 0.0) return false;  // the ray runs along the plane
  const glm::dvec3 hit = o + glm::dot(normal, p[0] - o) / along * d;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3& from = p[(i + 1) % 3];
    const glm::dvec3& to = p[(i + 2) % 3];
    weight[i] = glm::dot(normal, glm::cross(to - from, hit - from));
    if (weight[i] < 0.0) return false;
  }
  return true;
}

// Which of two triangles sharing an edge owns a ray that passes exactly through it: the one
// the ray enters when its direction is nudged by (e, e^2, e^3) for a vanishing e. That is the
// sign of the nudge against the normal of the plane through the origin and the edge, read
// lexicographically. The neighbour sees the same plane with its normal exactly negated (the
// edge runs the other way), so exactly one of the two owns the ray; at a corner shared by a fan
// the nudged ray still enters exactly one triangle.
bool owns(const glm::dvec3& n) {
  return n.x > 0 || (n.x == 0 && (n.y > 0 || (n.y == 0 && n.z > 0)));
}

// The watertight test (fill rule on; after Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): for each edge p -> q, s = d . ((p - o) x (q - o)) says on which side
// of the plane through the ray's origin and the edge the ray passes. The ray meets the
// triangle when all three sides agree, and the three s are then the hit's weights up to a
// common factor. The triangle next door computes the same s for the shared edge, exactly
// negated (a cross product with its arguments swapped rounds to the exact negation): the two
// can never both take a pixel, nor both miss it.
bool watertight_hit(const glm::dvec3 p[3], glm::dvec3 o, glm::dvec3 d, double weight[3]) {
  glm::dvec3 n[3];
  for (int i = 0; i < 3; ++i) {
    n[i] = glm::cross(p[(i + 1) % 3] - o, p[(i + 2) % 3] - o);
    weight[i] = glm::dot(d, n[i]);
  }
  const double sum = weight[0] + weight[1] + weight[2];  // d . N: which way the triangle faces
  if (sum == 0.0) return false;
  const double facing = sum > 0.0 ? 1.0 : -1.0;
  for (int i = 0; i < 3; ++i) {
    if (weight[i] * facing < 0.0 || (weight[i] == 0.0 && !owns(facing * n[i]))) return false;
  }
  return true;
}

}  // namespace

void fill_ray_per_pixel(const ViewVertex v[3], const Rays& rays, const PixelBox& box,
                        bool fill_rule, Image& image) {
  const glm::dvec3 p[3] = {v[0].position, v[1].position, v[2].position};
  for (int y = box.y0; y <= box.y1; ++y) {
    for (int x = box.x0; x <= box.x1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      double weight[3];
      const bool hit = fill_rule ? watertight_hit(p, rays.origin[i], rays.direction[i], weight)
                                 : textbook_hit(p, rays.origin[i], rays.direction[i], weight);
      if (!hit) continue;
      const double sum = weight[0] + weight[1] + weight[2];
      const glm::dvec3 point = (weight[0] * p[0] + weight[1] * p[1] + weight[2] * p[2]) / sum;
      // Window depth of the hit; outside [0, 1] it lies before the near plane (or behind the
      // eye, where w <= 0) or beyond the far plane: that is all the clipping there is.
      const glm::dvec4 clip = rays.projection * glm::dvec4(point, 1.0);
      const double depth = clip.z / clip.w * 0.5 + 0.5;
      if (!(clip.w > 0.0) || !(depth >= 0.0 && depth <= 1.0)) continue;
      glm::dvec3 normal(0.0);
      for (int k = 0; k < 3; ++k) normal += weight[k] / sum * glm::dvec3(v[k].normal);
      write_fragment(image, x, y, static_cast<float>(depth), glm::vec3(normal));
    }
  }
}

}  // namespace facet::classic
