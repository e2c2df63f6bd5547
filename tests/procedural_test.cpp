// Tests for the procedural shapes and Mesh bookkeeping: the conventions procedural.hpp promises
// (outward unit normals, counter-clockwise fronts, texcoords in [0, 1], tangent frames).
#include "facet/procedural.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "facet/error.hpp"
#include "facet/mesh.hpp"

namespace facet {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

constexpr float kPi = 3.14159265358979323846f;

struct Triangle {
  std::uint32_t a, b, c;
};

// The triangles a mesh draws, with strip parity already applied (odd ones swapped, as GL does),
// so every triangle is listed counter-clockwise if it is front facing.
std::vector<Triangle> triangles_of(const Mesh& mesh) {
  auto at = [&](std::size_t i) {
    return mesh.indices.empty() ? static_cast<std::uint32_t>(i) : mesh.indices[i];
  };
  std::vector<Triangle> out;
  if (mesh.topology == Topology::triangles) {
    for (std::size_t i = 0; i + 2 < mesh.element_count(); i += 3) {
      out.push_back({at(i), at(i + 1), at(i + 2)});
    }
  } else if (mesh.topology == Topology::triangle_strip) {
    for (std::size_t i = 0; i + 2 < mesh.element_count(); ++i) {
      if (i % 2 == 0) {
        out.push_back({at(i), at(i + 1), at(i + 2)});
      } else {
        out.push_back({at(i + 1), at(i), at(i + 2)});
      }
    }
  }
  return out;
}

vec3 geometric_normal(const Mesh& mesh, const Triangle& t) {
  const vec3 a = mesh.positions[t.a], b = mesh.positions[t.b], c = mesh.positions[t.c];
  return glm::cross(b - a, c - a);
}

// Divergence theorem: the signed volumes of the tetrahedra (origin, triangle) add up to the
// enclosed volume when the surface is closed and its triangles face outwards.
double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (const Triangle& t : triangles_of(mesh)) {
    const glm::dvec3 a(mesh.positions[t.a]), b(mesh.positions[t.b]), c(mesh.positions[t.c]);
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return volume;
}

vec3 bounds_centre(const Mesh& mesh) {
  vec3 lo(INFINITY), hi(-INFINITY);
  for (const vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return 0.5f * (lo + hi);
}

// What every shape promises, closed or not.
void expect_well_formed(const Mesh& mesh) {
  ASSERT_NO_THROW(mesh.validate());
  EXPECT_EQ(mesh.topology, Topology::triangles);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  ASSERT_EQ(mesh.texcoords.size(), mesh.positions.size());
  ASSERT_EQ(mesh.tangents.size(), mesh.positions.size());
  EXPECT_GT(mesh.primitive_count(), 0u);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const vec3 n = mesh.normals[i];
    const vec4 t = mesh.tangents[i];
    const vec2 uv = mesh.texcoords[i];
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f) << "vertex " << i;
    EXPECT_NEAR(glm::length(vec3(t)), 1.0f, 1e-5f) << "vertex " << i;
    EXPECT_NEAR(glm::dot(n, vec3(t)), 0.0f, 1e-5f) << "vertex " << i;
    EXPECT_EQ(std::abs(t.w), 1.0f) << "vertex " << i;
    EXPECT_TRUE(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)
        << "vertex " << i << " uv " << uv.x << ", " << uv.y;
  }
}

// The stored tangent frame must agree with the texture layout: the tangent along dP/du and
// cross(normal, tangent) * w along dP/dv of every triangle.
void expect_tangents_follow_texcoords(const Mesh& mesh) {
  for (const Triangle& t : triangles_of(mesh)) {
    const vec3 e1 = mesh.positions[t.b] - mesh.positions[t.a];
    const vec3 e2 = mesh.positions[t.c] - mesh.positions[t.a];
    const vec2 d1 = mesh.texcoords[t.b] - mesh.texcoords[t.a];
    const vec2 d2 = mesh.texcoords[t.c] - mesh.texcoords[t.a];
    const float uv_area = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(uv_area) < 1e-12f) continue;
    const vec3 du = (e1 * d2.y - e2 * d1.y) / uv_area;
    const vec3 dv = (e2 * d1.x - e1 * d2.x) / uv_area;
    for (std::uint32_t v : {t.a, t.b, t.c}) {
      const vec4 tangent = mesh.tangents[v];
      const vec3 bitangent = tangent.w * glm::cross(mesh.normals[v], vec3(tangent));
      EXPECT_GT(glm::dot(vec3(tangent), du), 0.0f) << "vertex " << v;
      EXPECT_GT(glm::dot(bitangent, dv), 0.0f) << "vertex " << v;
    }
  }
}

// For a convex closed shape around its bounding-box centre: every triangle is non-degenerate,
// counter-clockwise seen from outside, and on the same side as its vertex normals.
void expect_faces_outward(const Mesh& mesh) {
  const vec3 centre = bounds_centre(mesh);
  for (const Triangle& t : triangles_of(mesh)) {
    const vec3 g = geometric_normal(mesh, t);
    const vec3 middle = (mesh.positions[t.a] + mesh.positions[t.b] + mesh.positions[t.c]) / 3.0f;
    ASSERT_GT(glm::length(g), 1e-9f) << "degenerate triangle " << t.a << " " << t.b << " " << t.c;
    EXPECT_GT(glm::dot(g, middle - centre), 0.0f) << "triangle " << t.a << " " << t.b << " " << t.c;
    for (std::uint32_t v : {t.a, t.b, t.c}) {
      EXPECT_GT(glm::dot(g, mesh.normals[v]), 0.0f) << "vertex " << v;
    }
  }
}

// Closed: every edge, compared by position, is walked once in each direction.
void expect_watertight(const Mesh& mesh) {
  using Key = std::tuple<long long, long long, long long>;
  auto key = [&](std::uint32_t i) {
    const vec3 p = mesh.positions[i] * 1e4f;
    return Key{std::llround(p.x), std::llround(p.y), std::llround(p.z)};
  };
  std::map<std::pair<Key, Key>, int> edges;
  for (const Triangle& t : triangles_of(mesh)) {
    const std::uint32_t v[] = {t.a, t.b, t.c};
    for (int i = 0; i < 3; ++i) {
      const Key from = key(v[i]), to = key(v[(i + 1) % 3]);
      ++edges[{from, to}];
      --edges[{to, from}];
    }
  }
  for (const auto& [edge, balance] : edges) EXPECT_EQ(balance, 0);
}

void expect_closed_solid(const Mesh& mesh, double volume, double tolerance) {
  expect_well_formed(mesh);
  expect_tangents_follow_texcoords(mesh);
  expect_faces_outward(mesh);
  expect_watertight(mesh);
  EXPECT_GT(signed_volume(mesh), 0.0);
  EXPECT_NEAR(signed_volume(mesh), volume, tolerance * volume);
}

// Area of the regular n-gon inscribed in a circle of radius r.
double polygon_area(int n, double r) { return 0.5 * n * r * r * std::sin(2.0 * kPi / n); }

// --- Mesh ----------------------------------------------------------------------------------

Mesh soup(std::size_t vertices) {
  Mesh mesh;
  mesh.positions.assign(vertices, vec3(0.0f));
  return mesh;
}

TEST(Mesh, PrimitiveCountFollowsTopology) {
  Mesh mesh = soup(7);
  EXPECT_EQ(mesh.primitive_count(), 2u);
  mesh.topology = Topology::triangle_strip;
  EXPECT_EQ(mesh.primitive_count(), 5u);
  mesh.topology = Topology::lines;
  EXPECT_EQ(mesh.primitive_count(), 3u);
  mesh.indices = {0, 1, 2, 3};  // indices, when present, are what is walked
  EXPECT_EQ(mesh.primitive_count(), 2u);
}

TEST(Mesh, ShortStripsDrawNothing) {
  Mesh mesh = soup(2);
  mesh.topology = Topology::triangle_strip;
  EXPECT_EQ(mesh.primitive_count(), 0u);
  EXPECT_NO_THROW(mesh.validate());
  EXPECT_EQ(soup(0).primitive_count(), 0u);
}

TEST(Mesh, ValidateAcceptsAConsistentMesh) {
  EXPECT_NO_THROW(cube().validate());
  Mesh strip = soup(5);
  strip.topology = Topology::triangle_strip;
  EXPECT_NO_THROW(strip.validate());
  Mesh skipped = soup(3);
  skipped.positions[1] = vec3(NAN, 0.0f, INFINITY);  // the pipeline skips it; not an error here
  EXPECT_NO_THROW(skipped.validate());
}

void expect_error(const Mesh& mesh, const std::string& message) {
  try {
    mesh.validate();
    ADD_FAILURE() << "expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(e.what(), message);
  }
}

TEST(Mesh, ValidateNamesAnIndexOutOfRange) {
  Mesh mesh = cube();
  mesh.indices[12] = 40;
  expect_error(mesh, "mesh: index 12 is 40 but the mesh has 24 vertices");
  // The first one out of range is named, however large the later ones are; one past the last
  // vertex is already out.
  mesh.indices[30] = 4000000000u;
  mesh.indices[5] = 24;
  expect_error(mesh, "mesh: index 5 is 24 but the mesh has 24 vertices");
}

TEST(Mesh, ValidateNamesAnAttributeSizeMismatch) {
  Mesh mesh = soup(12);
  mesh.normals.resize(10);
  expect_error(mesh, "mesh: 10 normals for 12 positions");
  mesh.normals.clear();
  mesh.texcoords.resize(13);
  expect_error(mesh, "mesh: 13 texcoords for 12 positions");
  mesh.texcoords.clear();
  mesh.colors.resize(1);
  expect_error(mesh, "mesh: 1 colors for 12 positions");
  mesh.colors.clear();
  mesh.tangents.resize(11);
  expect_error(mesh, "mesh: 11 tangents for 12 positions");
}

TEST(Mesh, ValidateRejectsPartialPrimitives) {
  Mesh mesh = soup(8);
  mesh.indices = {0, 1, 2, 3, 4, 5, 6};
  expect_error(mesh, "mesh: 7 indices do not make whole triangles");
  mesh.indices.clear();
  expect_error(mesh, "mesh: 8 vertices do not make whole triangles");
  mesh.topology = Topology::lines;
  mesh.indices = {0, 1, 2, 3, 4};
  expect_error(mesh, "mesh: 5 indices do not make whole lines");
  mesh.topology = Topology::triangle_strip;
  EXPECT_NO_THROW(mesh.validate());
}

// --- flat shapes ---------------------------------------------------------------------------

TEST(Procedural, PlaneFacesUp) {
  const Mesh mesh = plane(4.0f, 2.0f, 3, 5);
  expect_well_formed(mesh);
  expect_tangents_follow_texcoords(mesh);
  EXPECT_EQ(mesh.positions.size(), 4u * 6u);
  EXPECT_EQ(mesh.primitive_count(), 2u * 3u * 5u);
  for (const vec3& n : mesh.normals) EXPECT_EQ(n, vec3(0.0f, 1.0f, 0.0f));
  for (const vec3& p : mesh.positions) {
    EXPECT_EQ(p.y, 0.0f);
    EXPECT_LE(std::abs(p.x), 2.0f);
    EXPECT_LE(std::abs(p.z), 1.0f);
  }
  for (const Triangle& t : triangles_of(mesh)) EXPECT_GT(geometric_normal(mesh, t).y, 0.0f);
}

TEST(Procedural, RectangleFacesPlusZ) {
  const Mesh mesh = rectangle(3.0f, 1.0f);
  expect_well_formed(mesh);
  expect_tangents_follow_texcoords(mesh);
  EXPECT_EQ(mesh.primitive_count(), 2u);
  for (const vec3& n : mesh.normals) EXPECT_EQ(n, vec3(0.0f, 0.0f, 1.0f));
  for (const Triangle& t : triangles_of(mesh)) EXPECT_GT(geometric_normal(mesh, t).z, 0.0f);
}

TEST(Procedural, QuadTakesItsNormalAndTexcoordsFromThePoints) {
  // Counter-clockwise seen from +X.
  const Mesh mesh = quad({0, 0, 1}, {0, 0, -1}, {0, 2, -1}, {0, 2, 1});
  expect_well_formed(mesh);
  expect_tangents_follow_texcoords(mesh);
  EXPECT_EQ(mesh.primitive_count(), 2u);
  for (const vec3& n : mesh.normals) EXPECT_NEAR(glm::distance(n, vec3(1, 0, 0)), 0.0f, 1e-6f);
  for (const Triangle& t : triangles_of(mesh)) EXPECT_GT(geometric_normal(mesh, t).x, 0.0f);
  const std::vector<vec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(mesh.texcoords, uvs);
}

TEST(Procedural, TriangleFacesTheWayItsPointsTurn) {
  const Mesh mesh = triangle({0, 0, 0}, {1, 0, 0}, {0, 0, -1});  // counter-clockwise from above
  expect_well_formed(mesh);
  expect_tangents_follow_texcoords(mesh);
  EXPECT_EQ(mesh.primitive_count(), 1u);
  for (const vec3& n : mesh.normals) EXPECT_NEAR(glm::distance(n, vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_THROW(triangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), Error);
  EXPECT_THROW(quad(vec3(0), vec3(0), vec3(0), vec3(0)), Error);
}

// --- solids --------------------------------------------------------------------------------

TEST(Procedural, BoxIsAClosedSolid) {
  const Mesh mesh = box({1.0f, 2.0f, 3.0f});
  EXPECT_EQ(mesh.positions.size(), 24u);
  EXPECT_EQ(mesh.primitive_count(), 12u);
  expect_closed_solid(mesh, 6.0, 1e-6);
  const Mesh unit = cube(2.0f);
  EXPECT_EQ(unit.positions.size(), 24u);
  expect_closed_solid(unit, 8.0, 1e-6);
}

TEST(Procedural, PyramidIsAClosedSolid) {
  const Mesh mesh = pyramid(2.0f, 3.0f, 1.5f);
  EXPECT_EQ(mesh.positions.size(), 4u + 4u * 3u);
  expect_closed_solid(mesh, 2.0 * 3.0 * 1.5 / 3.0, 1e-5);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(mesh.normals[i], vec3(0, -1, 0));
}

TEST(Procedural, SphereIsAClosedSolid) {
  const Mesh mesh = uv_sphere(1.0f, 64, 32);
  expect_closed_solid(mesh, 4.0 / 3.0 * kPi, 0.02);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_NEAR(glm::distance(mesh.positions[i], mesh.normals[i]), 0.0f, 1e-5f);
  }
  // One triangle per segment at each pole, two per segment elsewhere.
  EXPECT_EQ(mesh.primitive_count(), 64u * 2u * (32u - 1u));
  expect_closed_solid(uv_sphere(0.5f, 3, 2), polygon_area(3, 0.5) / 3.0, 1e-5);
}

TEST(Procedural, PrismsAreClosedSolids) {
  for (int sides : {3, 8, 12, 13, 32}) {
    SCOPED_TRACE("sides " + std::to_string(sides));
    expect_closed_solid(prism(sides, 1.5f, 2.0f), polygon_area(sides, 1.5) * 2.0, 1e-5);
  }
  const double octagon = 2.0 * std::sqrt(2.0) * 1.5 * 1.5 * 2.0;
  EXPECT_NEAR(signed_volume(prism(8, 1.5f, 2.0f)), octagon, 1e-5 * octagon);
}

TEST(Procedural, PrismSidesAreFlatUpToTwelve) {
  // Flat: the side vertices of one face share its normal, which has no Y component.
  const Mesh flat = prism(8, 1.0f, 1.0f);
  for (int face = 0; face < 8; ++face) {
    for (int corner = 1; corner < 4; ++corner) {
      EXPECT_EQ(flat.normals[face * 4 + corner], flat.normals[face * 4]);
    }
  }
  // Smooth: each side vertex's normal points straight away from the axis.
  const Mesh smooth = prism(32, 1.0f, 1.0f);
  for (std::size_t i = 0; i < 2 * 33; ++i) {
    const vec3 radial = smooth.positions[i] * vec3(1, 0, 1);
    EXPECT_NEAR(glm::distance(smooth.normals[i], radial), 0.0f, 1e-5f);
  }
}

TEST(Procedural, ConeIsAClosedSolid) {
  for (int segments : {3, 32}) {
    SCOPED_TRACE("segments " + std::to_string(segments));
    expect_closed_solid(cone(0.5f, 2.0f, segments), polygon_area(segments, 0.5) * 2.0 / 3.0, 1e-5);
  }
}

TEST(Procedural, ConeSideNormalsArePerpendicularToTheSlant) {
  const Mesh mesh = cone(1.0f, 2.0f, 16);
  for (std::size_t i = 0; i <= 16; ++i) {  // the base ring of the side
    const vec3 slant = vec3(0, 2, 0) - mesh.positions[i];
    EXPECT_NEAR(glm::dot(mesh.normals[i], slant), 0.0f, 1e-5f);
    EXPECT_GT(mesh.normals[i].y, 0.0f);
  }
}

TEST(Procedural, BadArgumentsThrow) {
  const std::vector<std::function<void()>> calls = {
      [] { plane(0.0f, 1.0f); },         [] { plane(1.0f, -1.0f); },
      [] { plane(1.0f, 1.0f, 0, 1); },   [] { plane(1.0f, 1.0f, 1, -3); },
      [] { rectangle(NAN, 1.0f); },      [] { rectangle(1.0f, INFINITY); },
      [] { box({1.0f, 0.0f, 1.0f}); },   [] { cube(-1.0f); },
      [] { pyramid(1.0f, 1.0f, 0.0f); }, [] { uv_sphere(0.0f); },
      [] { uv_sphere(1.0f, 2, 8); },     [] { uv_sphere(1.0f, 8, 1); },
      [] { prism(2, 1.0f, 1.0f); },      [] { prism(6, -1.0f, 1.0f); },
      [] { prism(6, 1.0f, 0.0f); },      [] { cone(0.0f, 1.0f); },
      [] { cone(1.0f, -2.0f); },         [] { cone(1.0f, 1.0f, 2); },
  };
  for (std::size_t i = 0; i < calls.size(); ++i) EXPECT_THROW(calls[i](), Error) << "call " << i;
  try {
    uv_sphere(1.0f, 8, 1);
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "uv_sphere: rings is 1 but must be at least 2");
  }
}

// --- transformed ---------------------------------------------------------------------------

TEST(Procedural, TransformedMovesPositionsNormalsAndTangents) {
  const glm::mat4 m = glm::scale(
      glm::rotate(glm::translate(glm::mat4(1.0f), {1, 2, 3}), 0.7f, glm::normalize(vec3(1, 1, 0))),
      {1.0f, 3.0f, 0.5f});
  const Mesh mesh = transformed(box({1, 1, 1}), m);
  expect_closed_solid(mesh, 1.5, 1e-5);
  // Flat faces: the vertex normals must still be the face normals.
  for (const Triangle& t : triangles_of(mesh)) {
    const vec3 g = glm::normalize(geometric_normal(mesh, t));
    EXPECT_NEAR(glm::dot(g, mesh.normals[t.a]), 1.0f, 1e-5f);
  }
  EXPECT_NEAR(glm::distance(bounds_centre(transformed(cube(), m)), vec3(1, 2, 3)), 0.0f, 1e-5f);
}

TEST(Procedural, MirroredShapesStayFrontFacingOutward) {
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f});
  const glm::mat4 squash = glm::scale(glm::mat4(1.0f), {2.0f, -0.5f, 1.0f});
  for (const glm::mat4& m : {mirror, squash}) {
    const double scale = std::abs(glm::determinant(glm::mat3(m)));
    expect_closed_solid(transformed(box({1, 2, 3}), m), 6.0 * scale, 1e-5);
    expect_closed_solid(transformed(pyramid(1, 1, 1), m), scale / 3.0, 1e-5);
    expect_closed_solid(transformed(uv_sphere(1.0f, 64, 32), m), 4.0 / 3.0 * kPi * scale, 0.02);
    expect_closed_solid(transformed(cone(1.0f, 1.0f, 8), m), polygon_area(8, 1) / 3 * scale, 1e-5);
  }
  const Mesh flipped = transformed(box({1, 1, 1}), mirror);
  for (const vec4& t : flipped.tangents) EXPECT_EQ(t.w, -1.0f);
}

Mesh strip_facing_z() {
  Mesh strip;
  strip.topology = Topology::triangle_strip;
  strip.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}};
  return strip;
}

void expect_all_face_plus_z(const Mesh& mesh) {
  int drawn = 0;
  for (const Triangle& t : triangles_of(mesh)) {
    const vec3 g = geometric_normal(mesh, t);
    if (glm::length(g) == 0.0f) continue;  // degenerate joins
    EXPECT_GT(g.z, 0.0f) << "triangle " << t.a << " " << t.b << " " << t.c;
    ++drawn;
  }
  EXPECT_GT(drawn, 0);
}

TEST(Procedural, MirroredStripsKeepTheirFront) {
  const Mesh strip = strip_facing_z();
  expect_all_face_plus_z(strip);
  const Mesh mirrored = transformed(strip, glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f}));
  EXPECT_NO_THROW(mirrored.validate());
  expect_all_face_plus_z(mirrored);
}

TEST(Procedural, TransformedRejectsSingularMatrices) {
  EXPECT_THROW(transformed(cube(), glm::mat4(0.0f)), Error);
  EXPECT_THROW(transformed(cube(), glm::scale(glm::mat4(1.0f), {1.0f, 0.0f, 1.0f})), Error);
}

// --- append --------------------------------------------------------------------------------

TEST(Procedural, AppendOffsetsIndices) {
  Mesh merged = cube();
  const Mesh sphere = uv_sphere(0.5f, 8, 4);
  append(merged, sphere);
  EXPECT_NO_THROW(merged.validate());
  ASSERT_EQ(merged.positions.size(), 24u + sphere.positions.size());
  ASSERT_EQ(merged.indices.size(), 36u + sphere.indices.size());
  for (std::size_t i = 0; i < sphere.indices.size(); ++i) {
    EXPECT_EQ(merged.indices[36 + i], sphere.indices[i] + 24u);
  }
  EXPECT_EQ(merged.primitive_count(), cube().primitive_count() + sphere.primitive_count());
}

TEST(Procedural, AppendToAnEmptyMeshCopies) {
  Mesh merged;
  append(merged, pyramid(1, 1, 1));
  const Mesh expected = pyramid(1, 1, 1);
  EXPECT_EQ(merged.positions, expected.positions);
  EXPECT_EQ(merged.indices, expected.indices);
  EXPECT_EQ(merged.tangents, expected.tangents);
  EXPECT_TRUE(merged.colors.empty());
}

TEST(Procedural, AppendIndexesAndFillsMissingAttributes) {
  Mesh soup_mesh;  // non-indexed, with colors but no texcoords or tangents
  soup_mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  soup_mesh.normals.assign(3, vec3(0, 0, 1));
  soup_mesh.colors.assign(3, vec4(1, 0, 0, 1));
  Mesh merged = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  append(merged, soup_mesh);
  EXPECT_NO_THROW(merged.validate());
  EXPECT_EQ(merged.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  ASSERT_EQ(merged.colors.size(), 6u);
  EXPECT_EQ(merged.colors[0], vec4(1.0f));
  EXPECT_EQ(merged.colors[5], vec4(1, 0, 0, 1));
  EXPECT_EQ(merged.texcoords[4], vec2(0.0f));
  EXPECT_EQ(merged.tangents[4], vec4(1, 0, 0, 1));

  Mesh plain = soup_mesh;  // both non-indexed: stays a plain list
  append(plain, soup_mesh);
  EXPECT_TRUE(plain.indices.empty());
  EXPECT_EQ(plain.positions.size(), 6u);
}

TEST(Procedural, AppendJoinsStripsWithoutFlippingThem) {
  for (std::size_t length : {4u, 5u}) {
    Mesh a = strip_facing_z();
    a.positions.resize(length);
    Mesh b = strip_facing_z();
    for (vec3& p : b.positions) p.x += 5.0f;
    append(a, b);
    EXPECT_NO_THROW(a.validate());
    expect_all_face_plus_z(a);
    EXPECT_EQ(a.positions.size(), length + 5u);
  }
}

TEST(Procedural, AppendRejectsMismatches) {
  Mesh lines;
  lines.topology = Topology::lines;
  lines.positions = {{0, 0, 0}, {1, 0, 0}};
  Mesh merged = cube();
  EXPECT_THROW(append(merged, lines), Error);
  Mesh bare;
  bare.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(append(merged, bare), Error);  // normals on one side only
  Mesh broken = cube();
  broken.indices[0] = 99;
  EXPECT_THROW(append(merged, broken), Error);
  EXPECT_EQ(merged.positions.size(), 24u);  // failed appends leave the mesh alone
}

}  // namespace
}  // namespace facet
