// The islands world's textures (see textures.hpp). Each painter returns the sRGB color of one
// texel from its integer coordinates (x right, y down, as the rows are stored); every noise is
// periodic over the image so the textures tile without seams.
#include "worlds/islands/textures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

#include "worlds/islands/noise.hpp"

namespace facet::islands {
namespace {

using glm::vec3;
constexpr float kTau = 6.28318530717958647692f;

template <class Paint>
TexturePtr paint(int width, int height, const char* name, Paint color_at) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const vec3 c = glm::clamp(color_at(x, y), vec3(0.0f), vec3(1.0f));
      std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      for (int i = 0; i < 3; ++i) p[i] = static_cast<std::uint8_t>(c[i] * 255.0f + 0.5f);
      p[3] = 255;
    }
  }
  return Texture::from_rgba8(width, height, std::move(rgba), true, name);
}

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// --- ground ----------------------------------------------------------------------------------

TexturePtr grass() {
  return paint(256, 256, "islands:grass", [](int x, int y) {
    const float patches = fbm(x / 64.0f, y / 64.0f, 4, 1, {4, 4});
    const float blades = value_noise(x / 2.0f, y / 2.0f, 2, {128, 128});
    const vec3 c = glm::mix(vec3(0.30f, 0.46f, 0.16f), vec3(0.50f, 0.66f, 0.26f), patches);
    return c * (0.82f + 0.32f * blades);
  });
}

TexturePtr sand() {
  return paint(256, 256, "islands:sand", [](int x, int y) {
    const float patches = fbm(x / 32.0f, y / 32.0f, 4, 3, {8, 8});
    const float grain = random01(x, y, 4);
    // Wind ripples: 16 crests over the tile, bent by low noise.
    const float bend = fbm(x / 64.0f, y / 64.0f, 2, 5, {4, 4});
    const float ripple = std::sin(kTau * (y / 16.0f + 1.5f * bend));
    return vec3(0.88f, 0.79f, 0.58f) * (0.88f + 0.12f * patches + 0.07f * grain + 0.03f * ripple);
  });
}

// Layered stone: on cliffs v runs up the face, so the bands lie horizontal like strata.
TexturePtr rock() {
  return paint(256, 256, "islands:rock", [](int x, int y) {
    const float n = fbm(x / 32.0f, y / 32.0f, 5, 6, {8, 8});
    const float strata = fbm(x / 128.0f, y / 8.0f, 3, 7, {2, 32});
    const float cracks = ridged(x / 32.0f, y / 32.0f, 3, 8, {8, 8});
    const float speckle = random01(x, y, 9);
    vec3 c = glm::mix(vec3(0.40f, 0.39f, 0.37f), vec3(0.63f, 0.61f, 0.57f), n);
    c *= (0.82f + 0.22f * strata) * (0.94f + 0.1f * speckle);
    return c * (1.0f - 0.35f * std::pow(cracks, 16.0f));
  });
}

// --- water -----------------------------------------------------------------------------------

TexturePtr water() {
  return paint(256, 256, "islands:water", [](int x, int y) {
    const float depth = fbm(x / 32.0f, y / 32.0f, 4, 9, {8, 8});
    const float crests = ridged(x / 32.0f, y / 32.0f, 3, 10, {8, 8});
    const vec3 c = glm::mix(vec3(0.07f, 0.29f, 0.45f), vec3(0.12f, 0.43f, 0.56f), depth);
    return glm::mix(c, vec3(0.62f, 0.80f, 0.88f), 0.7f * smoothstep(0.72f, 0.97f, crests));
  });
}

// Streaks run along v (down the fall), so they are narrow in x and long in y.
TexturePtr falls() {
  return paint(64, 256, "islands:falls", [](int x, int y) {
    const float streak = fbm(x / 4.0f, y / 64.0f, 4, 11, {16, 4});
    const float foam = value_noise(x / 2.0f, y / 4.0f, 12, {32, 64});
    const vec3 c = glm::mix(vec3(0.45f, 0.66f, 0.82f), vec3(0.90f, 0.96f, 1.0f),
                            smoothstep(0.3f, 0.7f, streak));
    return c * (0.92f + 0.1f * foam);
  });
}

// --- building materials ---------------------------------------------------------------------

// Planks along u, 32 texels wide, with dark gaps and staggered end joints.
TexturePtr wood() {
  return paint(256, 256, "islands:wood", [](int x, int y) {
    const int row = y / 32;
    const float board = random01(row, 0, 13);
    const float grain =
        std::sin(kTau * (y / 8.0f + 2.0f * fbm(x / 64.0f, y / 8.0f, 3, 14, {4, 32})));
    vec3 c = vec3(0.60f, 0.42f, 0.25f) * (0.78f + 0.35f * board) * (0.92f + 0.08f * grain);
    const bool joint = (x + row * 77) % 128 < 2;
    if (y % 32 < 2 || joint) c = vec3(0.24f, 0.16f, 0.09f);
    return c;
  });
}

// Fibres along v, for trunks.
TexturePtr bark() {
  return paint(128, 256, "islands:bark", [](int x, int y) {
    const float fibres = fbm(x / 4.0f, y / 32.0f, 4, 15, {32, 8});
    const float patches = fbm(x / 32.0f, y / 32.0f, 2, 16, {4, 8});
    return vec3(0.38f, 0.27f, 0.18f) * (0.55f + 0.55f * fibres) * (0.85f + 0.25f * patches);
  });
}

// Running bond: 4 bricks of 64 x 32 texels per row, every other row shifted by half a brick.
TexturePtr brick() {
  return paint(256, 256, "islands:brick", [](int x, int y) {
    const int row = y / 32, shifted = x + (row % 2) * 32;
    const int column = (shifted / 64) % 4, lx = shifted % 64, ly = y % 32;
    const float fine = fbm(x / 8.0f, y / 8.0f, 3, 17, {32, 32});
    if (lx < 4 || ly < 4) return vec3(0.74f, 0.71f, 0.64f) * (0.85f + 0.2f * fine);
    const float k = random01(column, row, 18);
    return glm::mix(vec3(0.55f, 0.22f, 0.15f), vec3(0.74f, 0.38f, 0.25f), k) *
           (0.85f + 0.25f * fine);
  });
}

// Rows of clay tiles, 32 texels tall, each tile darker toward its lower edge (where it laps
// over the row below) and at its sides.
TexturePtr roof() {
  return paint(256, 256, "islands:roof", [](int x, int y) {
    const int row = y / 32, shifted = x + (row % 2) * 16;
    const int column = (shifted / 32) % 8;
    const float lx = (shifted % 32) / 31.0f, ly = (y % 32) / 31.0f;
    const float k = random01(column, row, 19);
    const vec3 c = glm::mix(vec3(0.60f, 0.24f, 0.14f), vec3(0.80f, 0.40f, 0.22f), k);
    const float round = 1.0f - 0.35f * std::pow(std::abs(2.0f * lx - 1.0f), 3.0f);
    return c * round * (1.05f - 0.4f * ly * ly);
  });
}

// --- airport -----------------------------------------------------------------------------------

float asphalt(int x, int y, int height) {
  const float n = fbm(x / 16.0f, y / 16.0f, 4, 20, {8, height / 16});
  return 0.21f + 0.07f * n + 0.05f * (random01(x, y, 21) - 0.5f);
}

bool edge_line(int x) { return (x >= 4 && x < 12) || (x >= 116 && x < 124); }
bool centre_line(int x) { return x >= 60 && x < 68; }

// u across the runway (128 texels), v along it; the centre dash fills half the tile.
TexturePtr runway() {
  return paint(128, 256, "islands:runway", [](int x, int y) {
    if (edge_line(x) || (centre_line(x) && y < 128)) return vec3(0.88f, 0.88f, 0.84f);
    return vec3(asphalt(x, y, 256));
  });
}

// The runway's end: a bar across it, then the "piano keys" of the threshold (v grows away
// from the end; rows are stored top first, so v = 0 is y = 255).
TexturePtr threshold() {
  return paint(128, 256, "islands:threshold", [](int x, int y) {
    const bool bar = y >= 240 && y < 250;
    const bool keys =
        y >= 130 && y < 230 && x >= 14 && x < 114 && (x - 14) % 13 < 9 && !(x >= 57 && x < 71);
    const bool dash = centre_line(x) && y < 80;
    if (edge_line(x) || bar || keys || dash) return vec3(0.88f, 0.88f, 0.84f);
    return vec3(asphalt(x, y, 256));
  });
}

TexturePtr concrete() {
  return paint(128, 128, "islands:concrete", [](int x, int y) {
    const float n = fbm(x / 16.0f, y / 16.0f, 4, 22, {8, 8});
    if (x % 64 < 2 || y % 64 < 2) return vec3(0.42f);
    return vec3(0.55f + 0.08f * n + 0.03f * (random01(x, y, 23) - 0.5f));
  });
}

// Light, brushed panels with seams and a line of rivets beside each horizontal seam.
TexturePtr metal() {
  return paint(256, 256, "islands:metal", [](int x, int y) {
    const float brushed = fbm(x / 64.0f, y / 2.0f, 3, 24, {4, 128});
    vec3 c = vec3(0.70f, 0.72f, 0.75f) * (0.94f + 0.1f * brushed);
    if (x % 128 < 2 || y % 64 < 2) return c * 0.62f;
    const int rx = x % 8 - 4, ry = y % 64 - 6;
    if (rx * rx + ry * ry <= 2) c *= 0.8f;
    return c;
  });
}

// Clusters of leaves: broad light/dark masses with small bright leaf blobs.
TexturePtr foliage() {
  return paint(256, 256, "islands:foliage", [](int x, int y) {
    const float masses = fbm(x / 32.0f, y / 32.0f, 4, 25, {8, 8});
    const float leaves = value_noise(x / 4.0f, y / 4.0f, 26, {64, 64});
    const vec3 c = glm::mix(vec3(0.15f, 0.32f, 0.10f), vec3(0.34f, 0.56f, 0.20f), masses);
    return c * (0.65f + 0.6f * leaves * leaves);
  });
}

}  // namespace

IslandTextures make_island_textures() {
  IslandTextures t;
  t.grass = grass();
  t.sand = sand();
  t.rock = rock();
  t.water = water();
  t.falls = falls();
  t.wood = wood();
  t.bark = bark();
  t.brick = brick();
  t.roof = roof();
  t.runway = runway();
  t.threshold = threshold();
  t.concrete = concrete();
  t.metal = metal();
  t.foliage = foliage();
  return t;
}

}  // namespace facet::islands
