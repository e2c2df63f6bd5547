// Deterministic noise for the islands world: the terrain and every procedural texture are made
// from it, so the world comes out the same on every run and every thread count.
#pragma once

#include <cstdint>

namespace facet::islands {

// lowbias32 (Chris Wellons' integer hash): well mixed and branch-free, so neighbouring lattice
// points get unrelated values without a table.
inline std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

inline std::uint32_t hash32(int x, int y, std::uint32_t seed) {
  return hash32(static_cast<std::uint32_t>(x) * 0x9E3779B1U ^
                hash32(static_cast<std::uint32_t>(y) + seed * 0x85EBCA77U));
}

// Uniform in [0, 1): the top 24 bits of the hash, exactly representable in a float.
inline float random01(int x, int y, std::uint32_t seed) {
  return static_cast<float>(hash32(x, y, seed) >> 8) * (1.0f / 16777216.0f);
}

// Lattice cells after which the noise repeats, per axis; 0 = never. A texture spanning exactly
// that many cells tiles without a seam.
struct Period {
  int x = 0;
  int y = 0;
};

// Value noise in [0, 1]: random values on the integer lattice blended with a smoothstep.
float value_noise(float x, float y, std::uint32_t seed, Period period = {});

// Fractal sum of `octaves` value noises, each at twice the frequency and half the amplitude of
// the one before; normalized to [0, 1]. The period doubles with the frequency.
float fbm(float x, float y, int octaves, std::uint32_t seed, Period period = {});

// 1 along the creases of the noise, 0 far from them: cracks in rock, ridges on mountains.
float ridged(float x, float y, int octaves, std::uint32_t seed, Period period = {});

}  // namespace facet::islands
