// The meshes made from the land's height function (see terrain.hpp): the ground as a grid, at
// levels of detail, whose triangles are sorted into grass, sand and rock, and the water as strips
// along the courses with the falling sheet between them.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <unordered_map>
#include <vector>

#include "facet/procedural.hpp"
#include "worlds/islands/noise.hpp"
#include "worlds/islands/terrain.hpp"

namespace facet::islands {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

constexpr float kGrassTile = 6.0f, kSandTile = 5.0f, kRockTile = 8.0f;  // metres per repeat
constexpr float kHiddenBelow = -0.02f;  // ground under the sea is hidden by its opaque water
constexpr float kCliff = 0.65f;         // faces steeper than about 49 degrees are rock
constexpr float kSheetLift = 2.0f;      // the falling sheet hangs this far above the cliff
constexpr float kRiverTile = 8.0f, kFallsTile = 6.0f;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The noise that moves the beach line and the rock line about.
float lines_noise(vec3 p) { return value_noise(p.x / 12.0f, p.z / 12.0f, 41); }

// Rock: faces steeper than kCliff, and the heights.
bool is_rock(vec3 centre, float face_up) {
  return face_up < kCliff || centre.y > 40.0f + 10.0f * lines_noise(centre);
}

// How far a point stands above the beach line: sand below it, grass above.
float above_beach(vec3 p) { return p.y - (1.9f + 0.9f * lines_noise(p)); }

// Gentle color variation so the repeating textures do not show their tiling: grass dries
// toward the heights, sand darkens where the waves wet it.
vec4 tint(Surface surface, vec3 p) {
  const float n = fbm(p.x / 40.0f, p.z / 40.0f, 3, 51);
  if (surface == Surface::grass) {
    const float dry = std::clamp(0.7f * n + 0.5f * smoothstep(18.0f, 40.0f, p.y), 0.0f, 1.0f);
    return vec4(glm::mix(vec3(0.82f, 1.0f, 0.78f), vec3(1.12f, 1.0f, 0.66f), dry), 1.0f);
  }
  if (surface == Surface::sand) {
    return vec4(vec3(glm::mix(0.72f, 1.0f, smoothstep(0.1f, 0.9f, p.y)) * (0.92f + 0.16f * n)),
                1.0f);
  }
  return vec4(vec3(0.82f + 0.3f * n), 1.0f);
}

void add_vertex(Mesh& mesh, vec3 p, vec3 n, vec2 uv, vec4 color) {
  mesh.positions.push_back(p);
  mesh.normals.push_back(n);
  mesh.texcoords.push_back(uv);
  mesh.colors.push_back(color);
}

// The grid's vertices, with smooth normals from the heights around each.
struct Grid {
  int nx = 0, nz = 0;
  std::vector<vec3> points, normals;
  int index(int i, int j) const { return j * (nx + 1) + i; }
};

// Rock gets its own vertices and face normals: faceted cliffs against smooth meadows, and
// texture coordinates projected along the face's main axis so cliffs are not streaked.
void add_rock(Mesh& rock, const vec3 (&p)[3]) {
  const vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
  const vec3 a = glm::abs(n);
  for (const vec3& q : p) {
    const vec2 uv = a.y >= a.x && a.y >= a.z ? vec2(q.x, -q.z)
                    : a.x >= a.z             ? vec2(q.z, q.y)
                                             : vec2(q.x, q.y);
    add_vertex(rock, q, n, uv / kRockTile, tint(Surface::rock, q));
  }
}

// Triangles strips of water: rows of (left, right) points; flips the winding if needed so the
// front faces `front`.
Mesh ribbon(const std::vector<vec3>& left, const std::vector<vec3>& right,
            const std::vector<vec3>& normals, const std::vector<vec2>& uv_left, float uv_width,
            vec3 front) {
  Mesh mesh;
  for (std::size_t r = 0; r < left.size(); ++r) {
    add_vertex(mesh, left[r], normals[r], uv_left[r], vec4(1.0f));
    add_vertex(mesh, right[r], normals[r], uv_left[r] + vec2(uv_width, 0.0f), vec4(1.0f));
  }
  const bool flip = glm::dot(glm::cross(right[0] - left[0], left[1] - left[0]), front) < 0.0f;
  for (std::uint32_t r = 0; r + 1 < left.size(); ++r) {
    const std::uint32_t l0 = 2 * r, r0 = l0 + 1, l1 = l0 + 2, r1 = l0 + 3;
    flip ? mesh.indices.insert(mesh.indices.end(), {l0, l1, r0, r0, l1, r1})
         : mesh.indices.insert(mesh.indices.end(), {l0, r0, l1, r0, r1, l1});
  }
  return mesh;
}

// The water surface along a course; v counts down the stream so that a growing texture offset
// moves the ripples downstream. `extend` adds a row that far upstream of the first sample.
Mesh course_surface(const std::vector<Terrain::Sample>& course, float extend) {
  std::vector<vec3> left, right, normals;
  std::vector<vec2> uvs;
  const float total = course.back().distance;
  float width = 0.0f;
  for (std::size_t i = 0; i < course.size(); ++i) {
    const Terrain::Sample& s = course[i];
    const vec2 dir = glm::normalize(course[std::min(i + 1, course.size() - 1)].xz -
                                    course[i == 0 ? 0 : i - 1].xz);
    const vec2 side(-dir.y, dir.x);
    const float w = water_half_width(s.half_width, s.bank_slope);
    width = std::max(width, w);
    const vec2 xz = i == 0 ? s.xz - dir * extend : s.xz;
    const float along = i == 0 ? total + extend : total - s.distance;
    left.push_back({xz.x + side.x * w, s.level, xz.y + side.y * w});
    right.push_back({xz.x - side.x * w, s.level, xz.y - side.y * w});
    normals.push_back({0.0f, 1.0f, 0.0f});
    uvs.push_back({0.0f, along / kRiverTile});
  }
  return ribbon(left, right, normals, uvs, 2.0f * width / kRiverTile, {0.0f, 1.0f, 0.0f});
}

// The grid lines a level keeps: every step-th of 0 ... n, and n.
std::vector<int> kept_lines(int n, int step) {
  std::vector<int> lines;
  for (int i = 0; i < n; i += step) lines.push_back(i);
  lines.push_back(n);
  return lines;
}

// The triangles of a grid at one level of detail, counter-clockwise seen from above (x east,
// z south): cells between the kept lines, two triangles each, but for a cell with a side on
// the grid's edge that spans several grid squares. That cell fans out from a point at its
// centre (added to the grid, its height from `ground`) to every grid point of such sides, so
// that the edge has the same points at every level and chunks side by side meet without
// cracks whatever their levels. At step 1 every cell is a grid square.
template <class Ground>
std::vector<std::array<int, 3>> level_triangles(Grid& g, int step, float cell, Ground ground) {
  const std::vector<int> xs = kept_lines(g.nx, step), zs = kept_lines(g.nz, step);
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t b = 0; b + 1 < zs.size(); ++b) {
    for (std::size_t a = 0; a + 1 < xs.size(); ++a) {
      const int x0 = xs[a], x1 = xs[a + 1], z0 = zs[b], z1 = zs[b + 1];
      const int v00 = g.index(x0, z0), v10 = g.index(x1, z0);
      const int v01 = g.index(x0, z1), v11 = g.index(x1, z1);
      const bool west = x0 == 0, east = x1 == g.nx, north = z0 == 0, south = z1 == g.nz;
      if (!((west || east) && z1 - z0 > 1) && !((north || south) && x1 - x0 > 1)) {
        triangles.push_back({v00, v01, v11});
        triangles.push_back({v00, v11, v10});
        continue;
      }
      // The cell's outline in the same turn: down its west side, east along its south side,
      // up its east side, west along its north side; every grid point of a side on the edge.
      std::vector<int> outline;
      for (int z = z0; z < z1; ++z) {
        if (west || z == z0) outline.push_back(g.index(x0, z));
      }
      for (int x = x0; x < x1; ++x) {
        if (south || x == x0) outline.push_back(g.index(x, z1));
      }
      for (int z = z1; z > z0; --z) {
        if (east || z == z1) outline.push_back(g.index(x1, z));
      }
      for (int x = x1; x > x0; --x) {
        if (north || x == x1) outline.push_back(g.index(x, z0));
      }
      const vec2 middle(0.5f * (g.points[v00].x + g.points[v11].x),
                        0.5f * (g.points[v00].z + g.points[v11].z));
      const vec2 dx(cell, 0.0f), dz(0.0f, cell);
      const int centre = static_cast<int>(g.points.size());
      g.points.push_back({middle.x, ground(middle), middle.y});
      g.normals.push_back(
          glm::normalize(vec3(ground(middle - dx) - ground(middle + dx), 2.0f * cell,
                              ground(middle - dz) - ground(middle + dz))));
      for (std::size_t k = 0; k < outline.size(); ++k) {
        triangles.push_back({centre, outline[k], outline[(k + 1) % outline.size()]});
      }
    }
  }
  return triangles;
}

// Sorts triangles of the grid's points into grass, sand and rock (leaving out those under the
// sea, kHiddenBelow). A triangle the beach line crosses is cut along it, so the sand ends on a
// line through the triangles rather than in steps along their edges. The line crosses an edge
// at one point, made once from the edge's lower-numbered end and shared by both triangles of
// the edge (a rock triangle is cut too, all rock): no triangle has a vertex in the middle of
// its neighbour's edge, where the ground could show gaps.
Model ground_model(const Grid& g, const std::vector<std::array<int, 3>>& triangles) {
  std::vector<vec3> points = g.points, normals = g.normals;  // then the crossings
  std::vector<float> above(points.size());  // of the grid's points (crossings are on the line)
  for (std::size_t v = 0; v < points.size(); ++v) above[v] = above_beach(points[v]);
  std::unordered_map<std::uint64_t, int> crossings;  // lower end << 32 | upper end -> point
  auto crossing = [&](int a, int b) {
    const int lo = std::min(a, b), hi = std::max(a, b);
    const auto [at, added] = crossings.try_emplace(
        std::uint64_t{static_cast<std::uint32_t>(lo)} << 32 | static_cast<std::uint32_t>(hi),
        static_cast<int>(points.size()));
    if (added) {
      const float t = above[lo] / (above[lo] - above[hi]);
      points.push_back(glm::mix(points[lo], points[hi], t));
      normals.push_back(glm::normalize(glm::mix(normals[lo], normals[hi], t)));
    }
    return at->second;
  };

  Mesh grass, sand, rock;
  std::vector<std::uint32_t> grass_index, sand_index;
  auto shared = [&](Surface surface, int v) {
    Mesh& mesh = surface == Surface::grass ? grass : sand;
    std::vector<std::uint32_t>& index = surface == Surface::grass ? grass_index : sand_index;
    if (index.size() <= static_cast<std::size_t>(v)) index.resize(points.size(), kNone);
    std::uint32_t& slot = index[v];
    if (slot == kNone) {
      slot = static_cast<std::uint32_t>(mesh.positions.size());
      const vec3 p = points[v];
      const float tile = surface == Surface::grass ? kGrassTile : kSandTile;
      add_vertex(mesh, p, normals[v], vec2(p.x, -p.z) / tile, tint(surface, p));
    }
    return slot;
  };
  auto add = [&](Surface surface, int a, int b, int c) {
    if (surface == Surface::rock) return add_rock(rock, {points[a], points[b], points[c]});
    Mesh& mesh = surface == Surface::grass ? grass : sand;
    for (int v : {a, b, c}) mesh.indices.push_back(shared(surface, v));
  };
  for (const auto& [a, b, c] : triangles) {
    const vec3 p[3] = {points[a], points[b], points[c]};
    if (std::max({p[0].y, p[1].y, p[2].y}) < kHiddenBelow) continue;
    const vec3 centre = (p[0] + p[1] + p[2]) / 3.0f;
    const bool rocky = is_rock(centre, glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0])).y);
    const int v[3] = {a, b, c};
    const bool grassy[3] = {above[a] >= 0.0f, above[b] >= 0.0f, above[c] >= 0.0f};
    auto surface = [&](bool on_grass) {
      return rocky ? Surface::rock : on_grass ? Surface::grass : Surface::sand;
    };
    if (grassy[0] == grassy[1] && grassy[1] == grassy[2]) {
      add(surface(grassy[0]), a, b, c);
      continue;
    }
    // The vertex alone on its side of the line, then the other two in the triangle's turn:
    // the corner it cuts off, and the rest as two triangles.
    const int i = grassy[1] == grassy[2] ? 0 : grassy[0] == grassy[2] ? 1 : 2;
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const int ij = crossing(v[i], v[j]), ik = crossing(v[i], v[k]);
    add(surface(grassy[i]), v[i], ij, ik);
    add(surface(!grassy[i]), ij, v[j], v[k]);
    add(surface(!grassy[i]), ij, v[k], ik);
  }
  Model model;
  model.add_keeping_uv(Surface::grass, std::move(grass));
  model.add_keeping_uv(Surface::sand, std::move(sand));
  model.add_keeping_uv(Surface::rock, std::move(rock));
  return model;
}

}  // namespace

std::vector<Model> Terrain::land(glm::vec2 min, glm::vec2 max, float cell,
                                 std::span<const int> steps) const {
  Grid g;
  g.nx = static_cast<int>(std::ceil((max.x - min.x) / cell));
  g.nz = static_cast<int>(std::ceil((max.y - min.y) / cell));
  // One extra ring of heights so every vertex has neighbours for its normal.
  const int stride = g.nx + 3;
  std::vector<float> h(static_cast<std::size_t>(stride) * (g.nz + 3));
  for (int j = -1; j <= g.nz + 1; ++j) {
    for (int i = -1; i <= g.nx + 1; ++i)
      h[(j + 1) * stride + i + 1] = height(min + vec2(i, j) * cell);
  }
  auto H = [&](int i, int j) { return h[(j + 1) * stride + i + 1]; };
  for (int j = 0; j <= g.nz; ++j) {
    for (int i = 0; i <= g.nx; ++i) {
      g.points.push_back({min.x + i * cell, H(i, j), min.y + j * cell});
      g.normals.push_back(
          glm::normalize(vec3(H(i - 1, j) - H(i + 1, j), 2.0f * cell, H(i, j - 1) - H(i, j + 1))));
    }
  }
  std::vector<Model> levels;
  for (int step : steps) {
    Grid level = g;  // its fans' centres are its own
    const auto ground = [this](vec2 p) { return height(p); };
    levels.push_back(ground_model(level, level_triangles(level, step, cell, ground)));
  }
  return levels;
}

// The falling sheet follows the cliff from the pool up to the stream, hanging a little in
// front of the rock; returns it and the distance from the foot where it meets the pool.
Mesh Terrain::falls_sheet(float& pool_edge) const {
  const Sample& foot = river_.front();
  const vec2 up = glm::normalize(falls_top_ - falls_foot_);
  const float reach = glm::length(falls_top_ - falls_foot_);
  const float top_level = stream_.back().level;
  const float w = water_half_width(stream_.back().half_width, stream_.back().bank_slope);
  std::vector<vec2> profile;  // (distance from the foot, height)
  constexpr float kStep = 0.5f;
  for (int k = 0; k * kStep < reach; ++k) {
    const float d = k * kStep, ground = height(falls_foot_ + up * d);
    // While the ground is under the pool, restart: the sheet begins at the pool's far edge,
    // dipping just under the surface there.
    if (ground < foot.level) profile.clear();
    profile.push_back(
        {d, ground < foot.level ? foot.level - 0.15f : std::min(top_level, ground + kSheetLift)});
  }
  profile.push_back({reach, top_level});
  pool_edge = profile.front().x;

  const vec2 side(-up.y, up.x);
  std::vector<vec3> left, right, normals;
  std::vector<vec2> uvs;
  float along = 0.0f;
  for (std::size_t r = 0; r < profile.size(); ++r) {
    const vec2 prev = profile[r == 0 ? 0 : r - 1],
               next = profile[std::min(r + 1, profile.size() - 1)];
    const vec2 xz = falls_foot_ + up * profile[r].x;
    if (r > 0) along += glm::length(profile[r] - prev);
    left.push_back({xz.x + side.x * w, profile[r].y, xz.y + side.y * w});
    right.push_back({xz.x - side.x * w, profile[r].y, xz.y - side.y * w});
    const vec2 t = next - prev;  // (horizontal, vertical) along the profile
    normals.push_back(glm::normalize(vec3(-up.x * t.y, t.x, -up.y * t.y)));
    uvs.push_back({0.0f, along / kFallsTile});
  }
  return ribbon(left, right, normals, uvs, 2.0f * w / kFallsTile, vec3(-up.x, 0.0f, -up.y));
}

Model Terrain::water() const {
  Model model;
  // Each course starts a little upstream of its first sample, inside the rounded end of its
  // channel, so the water's upstream edge is hidden in the bank.
  for (const std::vector<Sample>* course : {&river_, &stream_}) {
    const Sample& source = course->front();
    const float extend = water_half_width(source.half_width, source.bank_slope) + 0.3f;
    model.add_keeping_uv(Surface::river, course_surface(*course, extend));
  }
  float pool_edge = 0.0f;
  model.add_keeping_uv(Surface::falls, falls_sheet(pool_edge));

  // Foam where the sheet meets the pool.
  const vec2 up = glm::normalize(falls_top_ - falls_foot_), side(-up.y, up.x);
  const float w = water_half_width(stream_.back().half_width, stream_.back().bank_slope);
  const vec2 splash = falls_foot_ + up * (pool_edge + 0.5f);
  for (int k = -1; k <= 1; ++k) {
    const vec2 p = splash + side * (0.55f * w * k) - up * (0.6f * std::abs(k));
    model.add(Surface::foam, uv_sphere(1.0f, 12, 6),
              at({p.x, river_.front().level, p.y}, 25.0f * k) * scale({1.4f, 0.45f, 1.1f}));
  }
  return model;
}

Model Terrain::ocean(glm::vec2 centre, float size) {
  constexpr float kOceanTile = 14.0f;  // metres per repeat of the water texture
  Mesh sea = plane(size, size, 32, 32);
  for (vec2& uv : sea.texcoords) uv *= size / kOceanTile;
  Model model;
  model.add_keeping_uv(Surface::ocean, std::move(sea), at({centre.x, 0.0f, centre.y}));
  return model;
}

}  // namespace facet::islands
