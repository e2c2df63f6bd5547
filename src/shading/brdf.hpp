// Reflectance models: Phong and Blinn-Phong specular lobes and the Cook-Torrance microfacet
// BRDF (GGX distribution, Smith-Schlick geometry, Schlick Fresnel) — "Real Shading in
// Unreal Engine 4", Karis 2013 — the metallic-roughness model glTF uses.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "core/portable_math.hpp"

namespace facet::shading {

inline constexpr float kPi = 3.14159265358979f;

inline glm::vec3 fresnel_schlick(glm::vec3 f0, float v_dot_h) {
  float k = 1.0f - std::clamp(v_dot_h, 0.0f, 1.0f);
  float k5 = (k * k) * (k * k) * k;
  return f0 + (glm::vec3(1.0f) - f0) * k5;
}

// GGX / Trowbridge-Reitz normal distribution with alpha = roughness^2.
inline float distribution_ggx(float n_dot_h, float roughness) {
  float a = roughness * roughness;
  float a2 = a * a;
  float d = n_dot_h * n_dot_h * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
}

// Smith's shadowing-masking with the Schlick-GGX approximation, k = (r + 1)^2 / 8 for
// analytic lights.
inline float geometry_smith(float n_dot_v, float n_dot_l, float roughness) {
  float k = (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
  auto g1 = [k](float x) { return x / (x * (1.0f - k) + k); };
  return g1(n_dot_v) * g1(n_dot_l);
}

struct PbrSurface {
  glm::vec3 albedo;  // base color, linear
  float metallic;
  float roughness;  // perceptual, clamped away from 0 so highlights stay finite
};

// The two parts of the BRDF value f(l, v) (per steradian; multiply by radiance and n.l).
// Unit vectors; zero below the horizon.
struct BrdfParts {
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
};

inline BrdfParts cook_torrance_parts(const PbrSurface& s, glm::vec3 n, glm::vec3 v, glm::vec3 l) {
  float n_dot_l = glm::dot(n, l), n_dot_v = glm::dot(n, v);
  if (n_dot_l <= 0.0f || n_dot_v <= 0.0f) return {};
  glm::vec3 h = glm::normalize(v + l);
  float n_dot_h = std::max(glm::dot(n, h), 0.0f);
  float roughness = std::clamp(s.roughness, 0.04f, 1.0f);
  glm::vec3 f0 = glm::mix(glm::vec3(0.04f), s.albedo, s.metallic);
  glm::vec3 f = fresnel_schlick(f0, glm::dot(v, h));
  float d = distribution_ggx(n_dot_h, roughness);
  float g = geometry_smith(n_dot_v, n_dot_l, roughness);
  BrdfParts parts;
  parts.specular = f * (d * g / (4.0f * n_dot_v * n_dot_l));
  // Light enters the surface once through Fresnel on the way in (at n.l) and once on the way
  // out (at n.v); only what passes both is diffused, so specular plus diffuse never exceeds
  // what arrives even at grazing angles (the white-furnace test checks this). Weighting by
  // F(v.h) alone, the common shortcut, gains up to 8% energy at grazing views.
  // Metals have no diffuse part.
  glm::vec3 enter = glm::vec3(1.0f) - fresnel_schlick(f0, n_dot_l);
  glm::vec3 leave = glm::vec3(1.0f) - fresnel_schlick(f0, n_dot_v);
  parts.diffuse = enter * leave * (1.0f - s.metallic) * s.albedo / kPi;
  return parts;
}

inline glm::vec3 cook_torrance(const PbrSurface& s, glm::vec3 n, glm::vec3 v, glm::vec3 l) {
  BrdfParts parts = cook_torrance_parts(s, n, v, l);
  return parts.diffuse + parts.specular;
}

// Phong: reflect the light about the normal and compare with the view direction.
inline float phong_specular(glm::vec3 n, glm::vec3 v, glm::vec3 l, float shininess) {
  glm::vec3 r = glm::reflect(-l, n);
  return portable_pow(std::max(glm::dot(r, v), 0.0f), shininess);
}

// Blinn-Phong: the half vector between light and view against the normal.
inline float blinn_phong_specular(glm::vec3 n, glm::vec3 v, glm::vec3 l, float shininess) {
  glm::vec3 h = glm::normalize(l + v);
  return portable_pow(std::max(glm::dot(n, h), 0.0f), shininess);
}

}  // namespace facet::shading
