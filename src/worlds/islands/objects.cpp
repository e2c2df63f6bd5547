// Trees, the house, the bridge and clouds of the islands world (see objects.hpp).
#include "worlds/islands/objects.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/procedural.hpp"
#include "worlds/islands/noise.hpp"

namespace facet::islands {
namespace {

using glm::vec3;
using glm::vec4;

constexpr float kDegrees = 180.0f / 3.14159265f;
constexpr vec3 kUp{0.0f, 1.0f, 0.0f}, kDown{0.0f, -1.0f, 0.0f};

// A shade of `base` picked by the seed, `spread` wide: no two trees quite alike.
vec4 vary(std::uint32_t seed, vec3 base, float spread) {
  const float k = random01(static_cast<int>(seed), 7, 71);
  return vec4(base * (1.0f - 0.5f * spread + spread * k), 1.0f);
}

float jitter(std::uint32_t seed, int salt) {
  return random01(static_cast<int>(seed), salt, 72) * 2.0f - 1.0f;
}

// A triangle whose front faces `outward` whatever order its corners come in.
Mesh facing(vec3 a, vec3 b, vec3 c, vec3 outward) {
  return glm::dot(glm::cross(b - a, c - a), outward) >= 0.0f ? triangle(a, b, c)
                                                             : triangle(a, c, b);
}

// A window on a wall facing +Z through the origin: a white frame with the pane standing a
// little proud of it.
Model window(float width, float height) {
  Model m;
  m.add(Surface::paint, box({width + 0.25f, height + 0.25f, 0.1f}), glm::mat4(1.0f),
        srgb(0.93f, 0.92f, 0.88f));
  m.add(Surface::glass, box({width, height, 0.18f}));
  return m;
}

}  // namespace

// --- trees -----------------------------------------------------------------------------------

Model conifer(float height, std::uint32_t seed, Detail detail) {
  Model m;
  const bool far = detail == Detail::far;
  // Trunks are cones tapering out of sight inside the foliage (no hidden caps to draw), and
  // start below the ground so that trees on slopes never float.
  m.add_keeping_uv(Surface::bark,
                   without_faces_toward(cone(0.06f * height, 0.6f * height, 6), kDown),
                   at({0, -0.5f, 0}));
  const vec4 needles = vary(seed, {0.55f, 0.74f, 0.62f}, 0.3f);
  for (int tier = 0; tier < 3; ++tier) {
    const float base = height * (0.18f + 0.24f * tier);
    m.add_keeping_uv(
        Surface::foliage,
        cone(height * (0.30f - 0.07f * tier), height * (0.42f - 0.04f * tier), far ? 6 : 10),
        at({0, base, 0}, 20.0f * tier), needles);
  }
  return m;
}

Model broadleaf(float height, std::uint32_t seed, Detail detail) {
  Model m;
  const bool far = detail == Detail::far;
  m.add_keeping_uv(Surface::bark,
                   without_faces_toward(cone(0.06f * height, 0.85f * height, 7), kDown),
                   at({0, -0.5f, 0}));
  const vec4 leaves = vary(seed, {0.95f, 1.0f, 0.8f}, 0.35f);
  m.add_keeping_uv(Surface::foliage, uv_sphere(0.28f * height, far ? 8 : 16, far ? 5 : 10),
                   at({0, 0.64f * height, 0}) * scale({1.0f, 0.85f, 1.0f}), leaves);
  const float turn = random01(static_cast<int>(seed), 1, 73) * 6.2832f;
  for (int k = 0; k < 2; ++k) {
    const float a = turn + 3.1416f * k, r = 0.2f * height;
    m.add_keeping_uv(Surface::foliage, uv_sphere(r, far ? 6 : 10, far ? 4 : 7),
                     at({std::cos(a) * r, (0.52f + 0.18f * k) * height, std::sin(a) * r}),
                     leaves * vec4(vec3(0.92f + 0.12f * k), 1.0f));
  }
  return m;
}

Model palm(float height, std::uint32_t seed, Detail detail) {
  Model m;
  // The trunk: five segments, each leaning a little more than the one below.
  constexpr int kSegments = 5;
  const float segment = height / kSegments, lean = 4.0f + 4.0f * jitter(seed, 2);
  glm::mat4 frame = rot_y(360.0f * random01(static_cast<int>(seed), 3, 74)) * at({0, -0.4f, 0});
  for (int k = 0; k < kSegments; ++k) {
    const float radius = height * (0.04f - 0.003f * k);
    const Mesh piece = without_faces_toward(prism(6, radius, segment * 1.05f), kDown);
    m.add_keeping_uv(Surface::bark, without_faces_toward(piece, kUp), frame,
                     srgb(0.85f, 0.78f, 0.66f));
    frame = frame * at({0, segment, 0}) * rot_z(lean);
  }
  // Fronds: each a kite bent down at its middle, so its two halves catch the light differently.
  const float reach = 0.55f * height, half = 0.07f * height;
  const vec4 green = vary(seed, {0.85f, 1.0f, 0.7f}, 0.25f);
  for (int k = 0; k < 7; ++k) {
    const glm::mat4 f = frame * rot_y(360.0f / 7.0f * k + 20.0f * jitter(seed, 10 + k));
    const vec3 base(0.0f), mid_l(0.5f * reach, 0.08f * height, half),
        mid_r(0.5f * reach, 0.08f * height, -half), tip(reach, -0.2f * height, 0.0f);
    m.add_keeping_uv(Surface::palm, facing(base, mid_l, mid_r, {0, 1, 0}), f, green);
    m.add_keeping_uv(Surface::palm, facing(mid_l, tip, mid_r, {0, 1, 0}), f, green);
  }
  for (int k = 0; detail == Detail::full && k < 3; ++k) {  // coconuts
    const float a = 2.1f * k;
    m.add_keeping_uv(
        Surface::bark, uv_sphere(0.035f * height, 8, 5),
        frame * at({0.05f * height * std::cos(a), -0.03f * height, 0.05f * height * std::sin(a)}),
        srgb(0.45f, 0.33f, 0.2f));
  }
  return m;
}

Model bush(float size, std::uint32_t seed, Detail detail) {
  Model m;
  const bool far = detail == Detail::far;
  const vec4 leaves = vary(seed, {0.85f, 1.0f, 0.75f}, 0.4f);
  for (int k = 0; k < 3; ++k) {
    const float r = size * (0.5f + 0.15f * jitter(seed, 60 + k));
    const vec3 p(0.45f * size * jitter(seed, 63 + k), 0.25f * size,
                 0.45f * size * jitter(seed, 66 + k));
    m.add_keeping_uv(Surface::foliage, uv_sphere(r, far ? 5 : 8, far ? 3 : 5),
                     at(p) * scale({1.0f, 0.7f, 1.0f}), leaves);
  }
  return m;
}

Model boulder(float size, std::uint32_t seed, Detail detail) {
  Model m;
  // A coarse sphere squashed and stretched by the seed: few facets read as a rough stone.
  const vec3 stretch(1.0f + 0.3f * jitter(seed, 70), 0.6f + 0.2f * jitter(seed, 71),
                     1.0f + 0.3f * jitter(seed, 72));
  m.add(Surface::rock,
        uv_sphere(0.5f * size, detail == Detail::far ? 5 : 7, detail == Detail::far ? 3 : 5),
        at({0, 0.1f * size, 0}) * scale(stretch));
  return m;
}

// --- buildings ---------------------------------------------------------------------------------

Model house(float width, float depth, float wall_height) {
  constexpr float kPitch = 35.0f, kOverhang = 0.45f, kFloor = 0.3f, kSlab = 0.18f;
  const float top = kFloor + wall_height;
  const float tan_pitch = std::tan(kPitch / kDegrees), rise = 0.5f * depth * tan_pitch;
  Model m;
  // A foundation deep enough to meet the ground on a gentle slope.
  m.add(Surface::concrete, box({width + 0.4f, 1.8f, depth + 0.4f}), at({0, kFloor - 0.9f, 0}));
  m.add(Surface::brick, box({width, wall_height, depth}), at({0, kFloor + 0.5f * wall_height, 0}));
  for (float side : {-1.0f, 1.0f}) {
    const float x = 0.5f * side * width;
    m.add(Surface::brick, facing({x, top, -0.5f * depth}, {x, top, 0.5f * depth},
                                 {x, top + rise, 0}, {side, 0, 0}));
  }
  // Two roof slabs meeting at the ridge, each lifted by half its thickness so its underside
  // runs from the ridge over the top edge of the wall.
  const float half = 0.5f * depth + kOverhang, slab = half / std::cos(kPitch / kDegrees);
  for (float side : {-1.0f, 1.0f}) {
    const vec3 lift =
        0.5f * kSlab * vec3(0, std::cos(kPitch / kDegrees), side * std::sin(kPitch / kDegrees));
    const vec3 centre = vec3(0, top + rise - 0.5f * half * tan_pitch, 0.5f * side * half) + lift;
    m.add(Surface::roof, box({width + 2.0f * kOverhang, kSlab, slab}),
          at(centre) * rot_x(side * kPitch));
  }
  m.add(Surface::brick, box({0.6f, 2.2f, 0.6f}),
        at({0.25f * width, top + 0.6f * rise, -0.2f * depth}));
  // The front (+Z): a door with a step, a window beside it; windows on the other walls.
  const float front = 0.5f * depth;
  m.add(Surface::wood, box({1.0f, 2.1f, 0.16f}), at({-0.2f * width, kFloor + 1.05f, front}));
  m.add(Surface::concrete, box({1.6f, 0.3f, 0.8f}), at({-0.2f * width, 0.15f, front + 0.4f}));
  m.add(window(1.1f, 1.1f), at({0.22f * width, kFloor + 1.5f, front}));
  for (float x : {-0.22f * width, 0.22f * width}) {
    m.add(window(1.1f, 1.1f), at({x, kFloor + 1.5f, -front}, 180.0f));
  }
  for (float side : {-1.0f, 1.0f}) {
    m.add(window(0.9f, 1.0f), at({0.5f * side * width, kFloor + 1.5f, 0}, side * 90.0f));
  }
  return m;
}

Model bridge(float span, float width) {
  Model m;
  m.add(Surface::wood, box({span, 0.35f, width}), at({0, -0.175f, 0}));
  const float edge = 0.5f * width - 0.1f;
  for (float z : {-edge, edge}) {
    m.add(Surface::wood, box({span, 0.5f, 0.3f}), at({0, -0.6f, z * 0.8f}));  // beams
    m.add(Surface::wood, box({span, 0.12f, 0.12f}), at({0, 1.05f, z}));       // hand rail
    m.add(Surface::wood, box({span, 0.1f, 0.1f}), at({0, 0.55f, z}));         // mid rail
    const int posts = static_cast<int>(span / 2.0f);
    for (int k = 0; k <= posts; ++k) {
      const float x = -0.5f * span + 0.3f + (span - 0.6f) * k / posts;
      m.add(Surface::wood, box({0.16f, 1.15f, 0.16f}), at({x, 0.55f, z}));
    }
  }
  // Stone abutments on the banks and two piers standing in the water.
  for (float side : {-1.0f, 1.0f}) {
    m.add(Surface::rock, box({3.0f, 5.0f, width + 0.8f}),
          at({side * (0.5f * span - 0.8f), -2.72f, 0}));
    m.add(Surface::rock, prism(8, 0.45f, 8.0f), at({side * span / 6.0f, -8.5f, 0}));
  }
  return m;
}

// --- sky -------------------------------------------------------------------------------------

Model cloud(std::uint32_t seed) {
  Model m;
  const int puffs = 4 + static_cast<int>(hash32(seed) % 3);
  for (int k = 0; k < puffs; ++k) {
    const float radius = 6.0f + 3.0f * jitter(seed, 20 + k);
    const vec3 p((k - 0.5f * (puffs - 1)) * 7.0f + 2.0f * jitter(seed, 30 + k),
                 1.5f * jitter(seed, 40 + k), 4.0f * jitter(seed, 50 + k));
    m.add_keeping_uv(Surface::cloud, uv_sphere(radius, 12, 8), at(p) * scale({1.0f, 0.55f, 0.8f}));
  }
  return m;
}

}  // namespace facet::islands
