// GLSL shared by every stage (see glsl_sources.hpp): lights, reflectance models, environment.
#include "gl/glsl_sources.hpp"

namespace facet::gl {

const char* const kCommonGlsl = R"glsl(
const float kPi = 3.14159265358979;

// ---- What the vertex stage hands on, declared once for every stage that passes or reads it
// (`out Varyings VARYINGS out_v;`): the blocks of consecutive stages must match member for
// member. color: material x vertex color; normal: world, unit; position: world; tangent: world
// xyz, w handedness; diffuse, specular: Gouraud's light at the vertex. (One line: GLSL 3.30
// has no line continuation.) ----
#define VARYINGS { vec2 texcoord; vec4 color; vec3 normal; vec3 position; vec4 tangent; vec3 diffuse; vec3 specular; }

// ---- Lights (shading/light_batch-inl.h): prepared on the CPU exactly as facet prepares them. ----
#define MAX_LIGHTS 32
const int kDirectional = 0, kPoint = 1, kSpot = 2;
uniform int u_light_count;
uniform int u_light_type[MAX_LIGHTS];
uniform vec3 u_light_position[MAX_LIGHTS];
uniform vec3 u_light_to_light[MAX_LIGHTS];        // directional: unit, toward the light
uniform vec3 u_light_spot_direction[MAX_LIGHTS];  // spot: unit, where the light travels
uniform vec3 u_light_radiance[MAX_LIGHTS];        // color x intensity
uniform float u_light_inv_range_squared[MAX_LIGHTS];
uniform float u_light_cos_inner[MAX_LIGHTS];
uniform float u_light_cos_outer[MAX_LIGHTS];
uniform vec3 u_ambient;
uniform vec3 u_eye;  // Camera::shading_eye

vec3 safe_normalize(vec3 v) {
  float length_squared = dot(v, v);
  return length_squared > 0.0 ? v * (1.0 / sqrt(length_squared)) : vec3(0.0);
}

struct IncidentLight {
  vec3 direction;  // unit, toward the light
  vec3 radiance;
};

IncidentLight incident(int i, vec3 p) {
  if (u_light_type[i] == kDirectional) return IncidentLight(u_light_to_light[i], u_light_radiance[i]);
  vec3 to_light = u_light_position[i] - p;
  float distance_squared = max(dot(to_light, to_light), 1e-8);
  vec3 direction = to_light * (1.0 / sqrt(distance_squared));
  // Inverse-square falloff, windowed to reach zero at the range (glTF KHR_lights_punctual).
  float attenuation = 1.0 / distance_squared;
  if (u_light_inv_range_squared[i] > 0.0) {
    float ratio = distance_squared * u_light_inv_range_squared[i];
    float window = clamp(1.0 - ratio * ratio, 0.0, 1.0);
    attenuation *= window * window;
  }
  if (u_light_type[i] == kSpot) {
    float cos_angle = dot(-direction, u_light_spot_direction[i]);
    float t = (cos_angle - u_light_cos_outer[i]) /
              max(u_light_cos_inner[i] - u_light_cos_outer[i], 1e-4);
    t = clamp(t, 0.0, 1.0);
    attenuation *= t * t;
  }
  return IncidentLight(direction, u_light_radiance[i] * attenuation);
}

// Diffuse + ambient from every light (shade_batch.cpp's DiffuseLight).
vec3 diffuse_light(vec3 albedo, vec3 normal, vec3 position) {
  vec3 light = u_ambient;
  for (int i = 0; i < u_light_count; ++i) {
    IncidentLight light_in = incident(i, position);
    light += light_in.radiance * max(0.0, dot(normal, light_in.direction));
  }
  return albedo * light;
}

// ---- Reflectance (shading/shade_batch.cpp). ----
float phong_specular(vec3 n, vec3 v, vec3 l, float shininess) {
  vec3 r = reflect(-l, n);
  return pow(max(dot(r, v), 0.0), shininess);
}

float blinn_phong_specular(vec3 n, vec3 v, vec3 l, float shininess) {
  vec3 h = normalize(l + v);
  return pow(max(dot(n, h), 0.0), shininess);
}

vec3 fresnel_schlick(vec3 f0, float v_dot_h) {
  float k = 1.0 - clamp(v_dot_h, 0.0, 1.0);
  float k5 = (k * k) * (k * k) * k;
  return f0 + (vec3(1.0) - f0) * k5;
}

// GGX / Trowbridge-Reitz with alpha = roughness^2.
float distribution_ggx(float n_dot_h, float roughness) {
  float a = roughness * roughness;
  float a2 = a * a;
  float d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

// Smith with Schlick-GGX, k = (r + 1)^2 / 8 for analytic lights.
float geometry_g1(float x, float k) { return x / (x * (1.0 - k) + k); }
float geometry_smith(float n_dot_v, float n_dot_l, float roughness) {
  float k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
  return geometry_g1(n_dot_v, k) * geometry_g1(n_dot_l, k);
}

// Cook-Torrance f(l, v); the diffuse part weighted by Fresnel going in and coming out, as
// facet's CookTorrance (energy stays below one at grazing angles).
vec3 cook_torrance(vec3 albedo, float metallic, float roughness_in, vec3 n, vec3 v, vec3 l) {
  float n_dot_l = dot(n, l), n_dot_v = dot(n, v);
  if (n_dot_l <= 0.0 || n_dot_v <= 0.0) return vec3(0.0);
  vec3 h = normalize(v + l);
  float n_dot_h = max(dot(n, h), 0.0);
  float roughness = clamp(roughness_in, 0.04, 1.0);
  vec3 f0 = mix(vec3(0.04), albedo, metallic);
  vec3 f = fresnel_schlick(f0, dot(v, h));
  float d = distribution_ggx(n_dot_h, roughness);
  float g = geometry_smith(n_dot_v, n_dot_l, roughness);
  vec3 specular = f * (d * g / (4.0 * n_dot_v * n_dot_l));
  vec3 enter = vec3(1.0) - fresnel_schlick(f0, n_dot_l);
  vec3 leave = vec3(1.0) - fresnel_schlick(f0, n_dot_v);
  vec3 diffuse = enter * leave * (1.0 - metallic) * albedo / kPi;
  return diffuse + specular;
}

// ---- Gouraud: Blinn-Phong at a vertex (shading/vertex_batch.cpp's LightVertices). ----
uniform vec3 u_specular_color;
uniform float u_shininess;

void gouraud_light(vec3 position, vec3 normal, out vec3 diffuse, out vec3 specular) {
  vec3 view = safe_normalize(u_eye - position);
  diffuse = u_ambient;
  specular = vec3(0.0);
  for (int i = 0; i < u_light_count; ++i) {
    IncidentLight light_in = incident(i, position);
    float n_dot_l = dot(normal, light_in.direction);
    if (n_dot_l <= 0.0) continue;
    diffuse += light_in.radiance * n_dot_l;
    specular += light_in.radiance * u_specular_color *
                blinn_phong_specular(normal, view, light_in.direction, u_shininess);
  }
}

// ---- Environment (shading/sky_gradient-inl.h, environment.cpp): sky gradient or an image. ----
uniform bool u_env_has_image;
uniform bool u_env_sphere_map;  // else equirectangular
uniform float u_env_intensity;
uniform vec3 u_sky_zenith;
uniform vec3 u_sky_horizon;
uniform vec3 u_sky_ground;
uniform sampler2D u_env_map;

vec3 sky_gradient(vec3 d) {
  // Square roots widen the bright band at the horizon, as a real sky looks.
  if (d.y >= 0.0) return mix(u_sky_horizon, u_sky_zenith, sqrt(d.y));
  return mix(u_sky_horizon, u_sky_ground, sqrt(min(-d.y * 4.0, 1.0)));
}

vec2 equirectangular_uv(vec3 d) {
  // atan(y, x) is undefined at x = y = 0 in GLSL, where C's atan2 gives 0 or pi.
  float u = 0.5 + (d.x == 0.0 && d.z == 0.0 ? 0.0 : atan(d.x, -d.z)) / (2.0 * kPi);
  float v = 0.5 + asin(clamp(d.y, -1.0, 1.0)) / kPi;
  return vec2(u, v);
}

vec2 sphere_map_uv(vec3 d) {
  float m = 2.0 * sqrt(d.x * d.x + d.y * d.y + (d.z + 1.0) * (d.z + 1.0));
  if (m < 1e-6) return vec2(0.5);
  return vec2(d.x / m + 0.5, d.y / m + 0.5);
}

// The level of detail is given, never taken from screen derivatives: the equirectangular u
// jumps from 1 to 0 behind the viewer, where derivatives would pick the smallest level.
vec3 environment_radiance(vec3 d, float lod) {
  if (!u_env_has_image) return sky_gradient(d) * u_env_intensity;
  vec2 uv = u_env_sphere_map ? sphere_map_uv(d) : equirectangular_uv(d);
  return textureLod(u_env_map, uv, lod).rgb * u_env_intensity;
}
)glsl";

}  // namespace facet::gl
