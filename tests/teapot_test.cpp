// Tests for the Utah teapot mesh: what teapot.hpp promises (Y up on y = 0, classic size,
// counter-clockwise fronts, unit frames, welded smooth seams, the argument range).
#include "facet/teapot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "facet/mesh.hpp"

namespace facet {
namespace {

using glm::dvec3;
using glm::vec2;
using glm::vec3;

constexpr float kUnitTolerance = 1e-4f;

vec3 corner(const Mesh& mesh, std::size_t triangle, int k) {
  return mesh.positions[mesh.indices[3 * triangle + k]];
}

vec3 area_vector(const Mesh& mesh, std::size_t triangle) {
  const vec3 a = corner(mesh, triangle, 0);
  return glm::cross(corner(mesh, triangle, 1) - a, corner(mesh, triangle, 2) - a);
}

bool finite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Sum over the triangles of the tetrahedra they span with the origin: the enclosed volume if
// the fronts face out. The teapot is not closed (the lid gap, the open spout), so this is
// approximate, but the openings are small.
double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.primitive_count(); ++t) {
    const dvec3 a(corner(mesh, t, 0)), b(corner(mesh, t, 1)), c(corner(mesh, t, 2));
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return volume;
}

TEST(Teapot, IsAValidIndexedTriangleMeshWithEveryAttribute) {
  for (int n : {1, 2, 8, 12}) {
    SCOPED_TRACE(n);
    const Mesh mesh = teapot(n);
    EXPECT_NO_THROW(mesh.validate());
    EXPECT_EQ(mesh.topology, Topology::triangles);
    EXPECT_FALSE(mesh.indices.empty());
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_EQ(mesh.texcoords.size(), mesh.positions.size());
    EXPECT_EQ(mesh.tangents.size(), mesh.positions.size());
    EXPECT_TRUE(mesh.colors.empty());
  }
}

// 32 patches of n x n quads would be 64 n^2 triangles. The 8 patches whose first row of control
// points is one point (the 4 around the knob top, the 4 around the bottom centre) are fans there:
// the first row of quads gives n triangles instead of 2 n, the other n having zero area.
TEST(Teapot, TriangleCountIsTwoPerQuadLessTheZeroAreaOnesAtThePoles) {
  for (int n : {1, 2, 3, 8, 12, 64}) {
    SCOPED_TRACE(n);
    EXPECT_EQ(teapot(n).primitive_count(), static_cast<std::size_t>(64 * n * n - 8 * n));
  }
}

TEST(Teapot, FramesAreFiniteUnitAndOrthogonalWithPositiveHandedness) {
  for (int n : {1, 3, 8, 12}) {
    SCOPED_TRACE(n);
    const Mesh mesh = teapot(n);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      SCOPED_TRACE(v);
      const vec3 normal = mesh.normals[v], tangent(mesh.tangents[v]);
      ASSERT_TRUE(finite(mesh.positions[v]));
      ASSERT_TRUE(finite(normal));
      ASSERT_TRUE(finite(tangent));
      EXPECT_NEAR(glm::length(normal), 1.0f, kUnitTolerance);
      EXPECT_NEAR(glm::length(tangent), 1.0f, kUnitTolerance);
      EXPECT_NEAR(glm::dot(normal, tangent), 0.0f, kUnitTolerance);
      EXPECT_EQ(mesh.tangents[v].w, 1.0f);
      // One unit square per patch: 4 quarter turns around, 4 levels from bottom centre to rim.
      const vec2 uv = mesh.texcoords[v];
      EXPECT_TRUE(uv.x >= 0.0f && uv.x <= 4.0f && uv.y >= 0.0f && uv.y <= 4.0f) << uv.x << uv.y;
    }
  }
}

// Each triangle's geometric normal must agree with its three vertex normals. Zero-area triangles
// are exempt; the degenerate pole triangles are not emitted at all (see the count above). Below
// 6 subdivisions single triangles cut across the tight curl of the spout's lip and this fails,
// as it would for any surface sampled that coarsely.
TEST(Teapot, FrontFacesAreCounterClockwiseSeenFromOutside) {
  for (int n : {6, 8, 12, 16, 32}) {
    SCOPED_TRACE(n);
    const Mesh mesh = teapot(n);
    int zero_area = 0;
    for (std::size_t t = 0; t < mesh.primitive_count(); ++t) {
      const vec3 g = area_vector(mesh, t);
      if (glm::length(g) < 1e-12f) {
        ++zero_area;
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        const vec3 normal = mesh.normals[mesh.indices[3 * t + k]];
        ASSERT_GT(glm::dot(glm::normalize(g), normal), 0.0f)
            << "triangle " << t << " corner " << k << " at " << corner(mesh, t, k).x << ", "
            << corner(mesh, t, k).y << ", " << corner(mesh, t, k).z;
      }
    }
    EXPECT_EQ(zero_area, 0);
  }
}

TEST(Teapot, SignedVolumeIsPositiveAndConverges) {
  for (int n : {1, 2, 4}) {
    SCOPED_TRACE(n);
    EXPECT_GT(signed_volume(teapot(n)), 0.0);
  }
  // About 25.9 cubic units when finely tessellated; coarse meshes cut the bulges a little.
  for (int n : {8, 12, 32}) {
    SCOPED_TRACE(n);
    EXPECT_NEAR(signed_volume(teapot(n)), 25.9, 0.3);
  }
}

// Classic units, Y up: height 3.15 (bottom 0, knob top 3.15), body radius 2 (z in [-2, 2]),
// handle back at x = -3, spout tip near x = 3.434 — a box of about 6.43 x 3.15 x 4.0.
TEST(Teapot, BoundsAreTheClassicTeapotStandingOnYZeroWithTheSpoutAlongPlusX) {
  const Mesh mesh = teapot(12);
  vec3 low(1e30f), high(-1e30f);
  std::size_t spout_tip = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    low = glm::min(low, mesh.positions[v]);
    high = glm::max(high, mesh.positions[v]);
    if (mesh.positions[v].x > mesh.positions[spout_tip].x) spout_tip = v;
  }
  EXPECT_NEAR(low.y, 0.0f, 1e-6f);
  EXPECT_NEAR(high.y, 3.15f, 1e-5f);
  EXPECT_NEAR(low.x, -3.0f, 1e-5f);
  EXPECT_NEAR(high.x, 3.434f, 0.005f);
  EXPECT_NEAR(low.z, -2.0f, 1e-5f);
  EXPECT_NEAR(high.z, 2.0f, 1e-5f);
  // The spout tip is up by the rim, not down by the base.
  EXPECT_GT(mesh.positions[spout_tip].y, 2.4f);
}

TEST(Teapot, KnobTopFacesUpAndBottomCentreFacesDown) {
  for (int n : {1, 8, 64}) {
    SCOPED_TRACE(n);
    const Mesh mesh = teapot(n);
    int top = 0, bottom = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const vec3 p = mesh.positions[v];
      if (std::abs(p.x) > 1e-6f || std::abs(p.z) > 1e-6f) continue;
      if (std::abs(p.y - 3.15f) < 1e-5f) {
        ++top;
        EXPECT_NEAR(glm::distance(mesh.normals[v], vec3(0, 1, 0)), 0.0f, kUnitTolerance);
      } else if (std::abs(p.y) < 1e-6f) {
        ++bottom;
        EXPECT_NEAR(glm::distance(mesh.normals[v], vec3(0, -1, 0)), 0.0f, kUnitTolerance);
      }
    }
    // One fan tip per triangle around each pole: 4 patches x n.
    EXPECT_EQ(top, 4 * n);
    EXPECT_EQ(bottom, 4 * n);
  }
}

// Vertices at one point (within 1e-6) are either one smooth group — the same position bits and
// the same normal, kept apart only because the texture coordinates jump there — or different
// surfaces meeting (the handle and spout ends against the body), far apart in angle.
TEST(Teapot, SeamsAreWeldedAndShadeSmoothly) {
  for (int n : {2, 8, 12}) {
    SCOPED_TRACE(n);
    const Mesh mesh = teapot(n);
    std::vector<std::uint32_t> order(mesh.positions.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return mesh.positions[a].x < mesh.positions[b].x;
    });
    int split = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        const std::uint32_t a = order[i], b = order[j];
        if (mesh.positions[b].x - mesh.positions[a].x > 1e-6f) break;
        if (glm::distance(mesh.positions[a], mesh.positions[b]) > 1e-6f) continue;
        const float cosine = glm::dot(mesh.normals[a], mesh.normals[b]);
        if (cosine < std::cos(0.5f)) continue;  // ~29 degrees: a crease, not a seam
        ++split;
        EXPECT_EQ(mesh.positions[a], mesh.positions[b]) << a << " " << b;
        EXPECT_EQ(mesh.normals[a], mesh.normals[b]) << a << " " << b;
        // Texture space only jumps where it must: at the fan tips around the poles, and where u
        // wraps around (4 quarter turns of the body, 2 half turns of the spout and handle), on
        // the z = 0 plane; anywhere else the coordinates run on across the seams.
        const vec3 p = mesh.positions[a];
        const vec2 jump = glm::abs(mesh.texcoords[a] - mesh.texcoords[b]);
        const bool pole = std::abs(p.x) < 1e-6f && std::abs(p.z) < 1e-6f;
        const bool wrap = std::abs(p.z) < 1e-6f && jump.y == 0.0f &&
                          (jump.x == 4.0f || (jump.x == 2.0f && std::abs(p.x) > 1.4f));
        EXPECT_TRUE(pole || wrap) << "texture seam at " << p.x << ", " << p.y << ", " << p.z;
      }
    }
    EXPECT_GT(split, 0);  // the u = 0 / u = 4 seam at +X, and the fan tips
  }
}

// Joined by position, every edge is shared by exactly two triangles that run it in opposite
// directions (no cracks, consistent winding), except the 16 n edges of the six open rims: the
// lid's edge and the inner edge of the pot's rim (4 patches each), the spout's tip and base and
// the handle's two ends (2 patches each).
TEST(Teapot, SurfaceIsClosedExceptTheClassicOpenings) {
  for (int n : {2, 8, 12}) {
    SCOPED_TRACE(n);
    const Mesh mesh = teapot(n);
    std::map<std::tuple<float, float, float>, int> point_ids;
    std::vector<int> point(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const vec3 p = mesh.positions[v];
      point[v] = point_ids.emplace(std::make_tuple(p.x, p.y, p.z), point_ids.size()).first->second;
    }
    std::map<std::pair<int, int>, int> directed;
    for (std::size_t t = 0; t < mesh.primitive_count(); ++t) {
      for (int k = 0; k < 3; ++k) {
        ++directed[{point[mesh.indices[3 * t + k]], point[mesh.indices[3 * t + (k + 1) % 3]]}];
      }
    }
    int open = 0;
    for (const auto& [edge, count] : directed) {
      const auto reverse = directed.find({edge.second, edge.first});
      const int back = reverse == directed.end() ? 0 : reverse->second;
      ASSERT_EQ(count, 1) << "edge run twice the same way: " << edge.first << " " << edge.second;
      if (back == 0) ++open;
    }
    EXPECT_EQ(open, 16 * n);
  }
}

// Texture space turns like the surface (no mirrored patch) and the tangents follow +u: per
// triangle, the uv-space area is positive and dP/du (Lengyel) agrees with the vertex tangents.
TEST(Teapot, TexcoordsAreUnmirroredAndTangentsFollowU) {
  for (int n : {6, 12}) {
    SCOPED_TRACE(n);
    const Mesh mesh = teapot(n);
    for (std::size_t t = 0; t < mesh.primitive_count(); ++t) {
      const std::uint32_t* i = &mesh.indices[3 * t];
      const vec3 e1 = mesh.positions[i[1]] - mesh.positions[i[0]];
      const vec3 e2 = mesh.positions[i[2]] - mesh.positions[i[0]];
      const vec2 d1 = mesh.texcoords[i[1]] - mesh.texcoords[i[0]];
      const vec2 d2 = mesh.texcoords[i[2]] - mesh.texcoords[i[0]];
      const float uv_area = d1.x * d2.y - d2.x * d1.y;
      ASSERT_GT(uv_area, 0.0f) << "triangle " << t;
      const vec3 d_du = (e1 * d2.y - e2 * d1.y) / uv_area;
      for (int k = 0; k < 3; ++k) {
        EXPECT_GT(glm::dot(d_du, vec3(mesh.tangents[i[k]])), 0.0f) << "triangle " << t;
      }
    }
  }
}

TEST(Teapot, SubdivisionsOutsideOneToSixtyFourThrow) {
  EXPECT_THROW(teapot(0), Error);
  EXPECT_THROW(teapot(65), Error);
  EXPECT_THROW(teapot(-1), Error);
  EXPECT_NO_THROW(teapot(1));
  EXPECT_NO_THROW(teapot(64));
}

}  // namespace
}  // namespace facet
