// Value noise and its fractal sums (see noise.hpp).
#include "worlds/islands/noise.hpp"

#include <cmath>

namespace facet::islands {
namespace {

int wrap(int i, int period) {
  if (period <= 0) return i;
  int m = i % period;
  return m < 0 ? m + period : m;
}

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

}  // namespace

float value_noise(float x, float y, std::uint32_t seed, Period period) {
  const float fx = std::floor(x), fy = std::floor(y);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  const float tx = smooth(x - fx), ty = smooth(y - fy);
  const int x0 = wrap(ix, period.x), x1 = wrap(ix + 1, period.x);
  const int y0 = wrap(iy, period.y), y1 = wrap(iy + 1, period.y);
  const float a = random01(x0, y0, seed), b = random01(x1, y0, seed);
  const float c = random01(x0, y1, seed), d = random01(x1, y1, seed);
  return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

float fbm(float x, float y, int octaves, std::uint32_t seed, Period period) {
  float sum = 0.0f, amplitude = 1.0f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(x, y, seed + static_cast<std::uint32_t>(o) * 101U, period);
    total += amplitude;
    amplitude *= 0.5f;
    x *= 2.0f;
    y *= 2.0f;
    period = {period.x * 2, period.y * 2};
  }
  return sum / total;
}

float ridged(float x, float y, int octaves, std::uint32_t seed, Period period) {
  const float n = fbm(x, y, octaves, seed, period);
  const float crease = 1.0f - std::abs(2.0f * n - 1.0f);
  return crease * crease;
}

}  // namespace facet::islands
