// Procedural meshes: the shapes the built-in worlds are made of (merged with mesh_tools.hpp).
// Written here once per scene; read by the vertex stage like any loaded mesh.
//
// Conventions shared by every shape (checked by tests/procedural_test.cpp):
//  * right-handed, +Y up; front faces are counter-clockwise seen from outside (as in OpenGL);
//  * texcoords follow OpenGL: (0, 0) is the bottom-left of the texture, so seen from the front
//    u runs to the right and v runs up;
//  * tangents point along +u, and w = +1 means the bitangent cross(normal, tangent) points
//    along +v. Every shape here maps textures unmirrored, so w is +1 until a mirror flips it.
#include "facet/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

#include "facet/error.hpp"

namespace facet {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

constexpr float kTau = 6.28318530717958647692f;
constexpr float kPi = kTau / 2.0f;
// Up to a dodecagon the facets are meant to be seen; beyond that a prism stands for a cylinder.
constexpr int kMaxFlatPrismSides = 12;
// Texcoords of triangle() and of the pyramid's sides: an upright triangle in texture space.
constexpr vec2 kTriangleUv[] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.5f, 1.0f}};
constexpr vec2 kQuadUv[] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};

// --- argument checks: the public functions validate, the helpers below assume ------------

template <class T>
std::string text(T value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void require_positive(const char* shape, const char* what, float value) {
  // Written so that NaN fails too.
  if (!(value > 0.0f && std::isfinite(value))) {
    throw Error(std::string(shape) + ": " + what + " is " + text(value) +
                " but must be positive and finite");
  }
}

void require_at_least(const char* shape, const char* what, int value, int minimum) {
  if (value < minimum) {
    throw Error(std::string(shape) + ": " + what + " is " + text(value) + " but must be at least " +
                text(minimum));
  }
}

// --- building blocks -----------------------------------------------------------------------

std::uint32_t vertex_count(const Mesh& mesh) {
  return static_cast<std::uint32_t>(mesh.positions.size());
}

void add_vertex(Mesh& mesh, vec3 position, vec3 normal, vec2 uv, vec4 tangent) {
  mesh.positions.push_back(position);
  mesh.normals.push_back(normal);
  mesh.texcoords.push_back(uv);
  mesh.tangents.push_back(tangent);
}

void add_triangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// a, b, c, d counter-clockwise seen from the front.
void add_quad(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  add_triangle(mesh, a, b, c);
  add_triangle(mesh, a, c, d);
}

// A point on the circle of the given radius around +Y at height y. Angle 0 is +Z and the angle
// grows towards +X, i.e. counter-clockwise seen from above, so u grows to the right seen from
// outside.
vec3 around(float angle, float radius, float y) {
  return {radius * std::sin(angle), y, radius * std::cos(angle)};
}

// The direction of growing angle in around(): the +u tangent of every surface of revolution.
vec4 around_tangent(float angle) { return {std::cos(angle), 0.0f, -std::sin(angle), 1.0f}; }

// A flat grid of (nu + 1) x (nv + 1) vertices spanning origin + [0, 1] u_axis + [0, 1] v_axis,
// facing cross(u_axis, v_axis); texcoords run 0..1 along the axes.
void add_grid(Mesh& mesh, vec3 origin, vec3 u_axis, vec3 v_axis, int nu, int nv) {
  const vec3 normal = glm::normalize(glm::cross(u_axis, v_axis));
  const vec4 tangent(glm::normalize(u_axis), 1.0f);
  const std::uint32_t first = vertex_count(mesh);
  const std::uint32_t row = static_cast<std::uint32_t>(nu) + 1;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      const vec2 uv(static_cast<float>(i) / nu, static_cast<float>(j) / nv);
      add_vertex(mesh, origin + uv.x * u_axis + uv.y * v_axis, normal, uv, tangent);
    }
  }
  for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(nv); ++j) {
    for (std::uint32_t i = 0; i < row - 1; ++i) {
      const std::uint32_t corner = first + j * row + i;
      add_quad(mesh, corner, corner + 1, corner + row + 1, corner + row);
    }
  }
}

// A flat-shaded convex polygon (its own vertices, one face normal) given counter-clockwise from
// the front, triangulated as a fan from the first point.
template <std::size_t N>
void add_flat(Mesh& mesh, const char* shape, const vec3 (&points)[N], const vec2 (&uvs)[N]) {
  // Summing over the fan gives the area-weighted normal (Newell's), which for a quad is the
  // cross product of its diagonals and so is well defined even if the quad is not planar.
  // The tangent is dP/du of each fan triangle (Lengyel's formula), summed the same way.
  vec3 normal(0.0f), tangent(0.0f), bitangent(0.0f);
  for (std::size_t i = 1; i + 1 < N; ++i) {
    const vec3 e1 = points[i] - points[0], e2 = points[i + 1] - points[0];
    const vec2 d1 = uvs[i] - uvs[0], d2 = uvs[i + 1] - uvs[0];
    const float uv_area = d1.x * d2.y - d2.x * d1.y;  // never 0 for the texcoords used here
    normal += glm::cross(e1, e2);
    tangent += (e1 * d2.y - e2 * d1.y) / uv_area;
    bitangent += (e2 * d1.x - e1 * d2.x) / uv_area;
  }
  if (!(glm::length(normal) > 0.0f)) {
    throw Error(std::string(shape) + ": the points are collinear or not finite");
  }
  normal = glm::normalize(normal);
  tangent = glm::normalize(tangent - normal * glm::dot(normal, tangent));  // Gram-Schmidt
  const float handedness = glm::dot(glm::cross(normal, tangent), bitangent) < 0.0f ? -1.0f : 1.0f;

  const std::uint32_t first = vertex_count(mesh);
  for (std::size_t i = 0; i < N; ++i) {
    add_vertex(mesh, points[i], normal, uvs[i], vec4(tangent, handedness));
  }
  for (std::uint32_t i = 1; i + 1 < N; ++i) add_triangle(mesh, first, first + i, first + i + 1);
}

// A disk at height y facing +Y (up) or -Y, as a fan around its centre. Texcoords are projected
// along Y: u along +X, v along -Z on top and +Z underneath, so neither side is mirrored (the
// same layout as plane() and the box's top and bottom).
void add_disk(Mesh& mesh, float y, float radius, int segments, bool up) {
  const vec3 normal(0.0f, up ? 1.0f : -1.0f, 0.0f);
  const float v_sign = up ? -1.0f : 1.0f;
  const std::uint32_t centre = vertex_count(mesh);
  add_vertex(mesh, {0.0f, y, 0.0f}, normal, {0.5f, 0.5f}, {1.0f, 0.0f, 0.0f, 1.0f});
  for (int k = 0; k < segments; ++k) {
    const float angle = kTau * (static_cast<float>(k) / segments);  // as the sides have it
    const vec2 uv(0.5f + 0.5f * std::sin(angle), 0.5f + 0.5f * v_sign * std::cos(angle));
    add_vertex(mesh, around(angle, radius, y), normal, uv, {1.0f, 0.0f, 0.0f, 1.0f});
  }
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(segments); ++k) {
    const std::uint32_t a = centre + 1 + k;
    const std::uint32_t b = centre + 1 + (k + 1) % static_cast<std::uint32_t>(segments);
    // The ring runs counter-clockwise seen from above, so the underside takes it backwards.
    up ? add_triangle(mesh, centre, a, b) : add_triangle(mesh, centre, b, a);
  }
}

// The smooth side of a cylinder (top_radius == radius) or of a cone (top_radius == 0) from
// y = 0 to y = height; u runs around, v from the bottom (0) to the top (1).
void add_smooth_side(Mesh& mesh, float radius, float top_radius, float height, int segments) {
  const bool apex = top_radius == 0.0f;
  const std::uint32_t first = vertex_count(mesh);
  const std::uint32_t row = static_cast<std::uint32_t>(segments) + 1;  // the seam is doubled
  for (int level = 0; level <= 1; ++level) {
    for (int k = 0; k <= segments; ++k) {
      // An apex gets one copy per segment, in the segment's middle, so that each triangle meeting
      // there is shaded with its own direction; the last copy is unused.
      const float step = level == 1 && apex ? std::min(k + 0.5f, float(segments)) : float(k);
      const float u = step / segments;
      // The seam's second copy at angle 0, the first's bits: the surface closes (uv_sphere).
      const float angle = k == segments && !(level == 1 && apex) ? 0.0f : kTau * u;
      // Perpendicular to both the circle and the slant line (-radius, height) in the
      // (radial, y) plane.
      const vec3 normal = glm::normalize(around(angle, height, radius - top_radius));
      const vec3 position = around(angle, level == 1 ? top_radius : radius, level * height);
      add_vertex(mesh, position, normal, {u, float(level)}, around_tangent(angle));
    }
  }
  for (std::uint32_t k = 0; k < row - 1; ++k) {
    const std::uint32_t bottom = first + k, top = bottom + row;
    apex ? add_triangle(mesh, bottom, bottom + 1, top)
         : add_quad(mesh, bottom, bottom + 1, top + 1, top);
  }
}

}  // namespace

// --- flat shapes ---------------------------------------------------------------------------

Mesh plane(float width, float depth, int segments_x, int segments_z) {
  require_positive("plane", "width", width);
  require_positive("plane", "depth", depth);
  require_at_least("plane", "segments_x", segments_x, 1);
  require_at_least("plane", "segments_z", segments_z, 1);
  Mesh mesh;
  // v runs towards -Z: a texture on the floor reads upright to a viewer looking along -Z.
  add_grid(mesh, {-0.5f * width, 0.0f, 0.5f * depth}, {width, 0.0f, 0.0f}, {0.0f, 0.0f, -depth},
           segments_x, segments_z);
  return mesh;
}

Mesh rectangle(float width, float height) {
  require_positive("rectangle", "width", width);
  require_positive("rectangle", "height", height);
  Mesh mesh;
  add_grid(mesh, {-0.5f * width, -0.5f * height, 0.0f}, {width, 0.0f, 0.0f}, {0.0f, height, 0.0f},
           1, 1);
  return mesh;
}

Mesh quad(vec3 p0, vec3 p1, vec3 p2, vec3 p3) {
  Mesh mesh;
  add_flat(mesh, "quad", {p0, p1, p2, p3}, kQuadUv);
  return mesh;
}

Mesh triangle(vec3 a, vec3 b, vec3 c) {
  Mesh mesh;
  add_flat(mesh, "triangle", {a, b, c}, kTriangleUv);
  return mesh;
}

// --- solids --------------------------------------------------------------------------------

Mesh box(vec3 size) {
  require_positive("box", "size.x", size.x);
  require_positive("box", "size.y", size.y);
  require_positive("box", "size.z", size.z);
  // Each face by its outward normal and the way "up" points in its texture seen from outside;
  // the top and bottom are laid out as plane() and the caps of prism() are.
  struct Face {
    vec3 normal, up;
  };
  constexpr Face kFaces[] = {
      {{1, 0, 0}, {0, 1, 0}},  {{-1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}},
      {{0, 0, -1}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, -1}}, {{0, -1, 0}, {0, 0, 1}},
  };
  Mesh mesh;
  for (const Face& face : kFaces) {
    const vec3 right = glm::cross(face.up, face.normal);
    const vec3 u_axis = right * glm::dot(glm::abs(right), size);
    const vec3 v_axis = face.up * glm::dot(glm::abs(face.up), size);
    const vec3 centre = 0.5f * face.normal * glm::dot(glm::abs(face.normal), size);
    add_grid(mesh, centre - 0.5f * (u_axis + v_axis), u_axis, v_axis, 1, 1);
  }
  return mesh;
}

Mesh cube(float size) {
  require_positive("cube", "size", size);
  return box(vec3(size));
}

Mesh pyramid(float base_width, float base_depth, float height) {
  require_positive("pyramid", "base_width", base_width);
  require_positive("pyramid", "base_depth", base_depth);
  require_positive("pyramid", "height", height);
  const float hw = 0.5f * base_width, hd = 0.5f * base_depth;
  Mesh mesh;
  add_grid(mesh, {-hw, 0.0f, -hd}, {base_width, 0.0f, 0.0f}, {0.0f, 0.0f, base_depth}, 1, 1);
  // Base corners counter-clockwise seen from above, so each side (corner, next, apex) is
  // counter-clockwise seen from outside.
  const vec3 corners[] = {{-hw, 0, hd}, {hw, 0, hd}, {hw, 0, -hd}, {-hw, 0, -hd}};
  const vec3 apex(0.0f, height, 0.0f);
  for (int i = 0; i < 4; ++i) {
    add_flat(mesh, "pyramid", {corners[i], corners[(i + 1) % 4], apex}, kTriangleUv);
  }
  return mesh;
}

Mesh uv_sphere(float radius, int segments, int rings) {
  require_positive("uv_sphere", "radius", radius);
  require_at_least("uv_sphere", "segments", segments, 3);
  require_at_least("uv_sphere", "rings", rings, 2);
  Mesh mesh;
  // Rings are walked from the north pole down; v is 1 at the north pole and 0 at the south.
  const std::uint32_t row = static_cast<std::uint32_t>(segments) + 1;  // the seam is doubled
  for (int ring = 0; ring <= rings; ++ring) {
    const float polar = kPi * static_cast<float>(ring) / rings;
    const bool pole = ring == 0 || ring == rings;
    for (int k = 0; k <= segments; ++k) {
      // As at a cone's apex: one pole copy per segment, in its middle (the last one is unused).
      const float step = pole ? std::min(k + 0.5f, float(segments)) : float(k);
      const float u = step / segments;
      // The seam's second copy at angle 0 and the poles on the axis exactly (sin(kTau) and
      // sin(kPi) are not 0 in floats): the surface closes bit for bit, which the shadow maps'
      // passes rely on (pipeline/shadow/closed_surface.hpp).
      const float angle = k == segments && !pole ? 0.0f : kTau * u;
      const vec3 normal = pole ? vec3(0.0f, ring == 0 ? 1.0f : -1.0f, 0.0f)
                               : around(angle, std::sin(polar), std::cos(polar));
      add_vertex(mesh, radius * normal, normal, {u, 1.0f - float(ring) / rings},
                 around_tangent(angle));
    }
  }
  for (std::uint32_t ring = 0; ring < static_cast<std::uint32_t>(rings); ++ring) {
    for (std::uint32_t k = 0; k + 1 < row; ++k) {
      const std::uint32_t top = ring * row + k, bottom = top + row;
      // One triangle per segment at each pole, using that segment's own pole copy.
      if (ring == 0) {
        add_triangle(mesh, top, bottom, bottom + 1);
      } else if (ring + 1 == static_cast<std::uint32_t>(rings)) {
        add_triangle(mesh, bottom, top + 1, top);
      } else {
        add_quad(mesh, bottom, bottom + 1, top + 1, top);
      }
    }
  }
  return mesh;
}

Mesh prism(int sides, float radius, float height) {
  require_at_least("prism", "sides", sides, 3);
  require_positive("prism", "radius", radius);
  require_positive("prism", "height", height);
  Mesh mesh;
  if (sides <= kMaxFlatPrismSides) {
    for (int k = 0; k < sides; ++k) {
      const float u0 = static_cast<float>(k) / sides, u1 = static_cast<float>(k + 1) / sides;
      const float a0 = kTau * u0, a1 = k + 1 == sides ? 0.0f : kTau * u1;  // the seam closes
      add_flat(mesh, "prism",
               {around(a0, radius, 0.0f), around(a1, radius, 0.0f), around(a1, radius, height),
                around(a0, radius, height)},
               {vec2(u0, 0.0f), vec2(u1, 0.0f), vec2(u1, 1.0f), vec2(u0, 1.0f)});
    }
  } else {
    add_smooth_side(mesh, radius, radius, height, sides);
  }
  add_disk(mesh, 0.0f, radius, sides, false);
  add_disk(mesh, height, radius, sides, true);
  return mesh;
}

Mesh cone(float radius, float height, int segments) {
  require_positive("cone", "radius", radius);
  require_positive("cone", "height", height);
  require_at_least("cone", "segments", segments, 3);
  Mesh mesh;
  add_smooth_side(mesh, radius, 0.0f, height, segments);
  add_disk(mesh, 0.0f, radius, segments, false);
  return mesh;
}

}  // namespace facet
