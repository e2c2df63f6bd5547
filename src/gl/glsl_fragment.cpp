// GLSL fragment stage: facet's shading models (the SIMD kernel of shading/shade_batch.cpp),
// one per MODEL_* define, then the alpha mask and fog as facet's raster loop applies them
// (pipeline/raster/pixel_writer.hpp). Colors are linear; the sRGB encode comes after readback.
#include "gl/glsl_sources.hpp"

namespace facet::gl {

const char* const kFragmentGlsl = R"glsl(
in Varyings VARYINGS in_v;
#ifdef NO_GEOMETRY_STAGE
// Straight from the vertex stage: the draw reads none of the geometry stage's values
// (gl_renderer.cpp's needs_geometry_stage).
const int normals_front = 1;
const vec4 face_color = vec4(0.0);
const vec3 edge_lines[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
#else
flat in int normals_front;
flat in vec4 face_color;
flat in vec3 edge_lines[3];
#endif

out vec4 out_color;

// The material (facet/material.hpp).
uniform vec4 u_base_color;
uniform vec3 u_emissive;
uniform float u_reflectivity;
uniform float u_metallic;
uniform float u_roughness;
uniform float u_normal_scale;
uniform float u_occlusion_strength;
uniform float u_alpha_cutoff;
uniform vec4 u_wire_color;
// Two-sided lit draws see the back of the surface: its normal is reversed on the faces whose
// normals point away from the side seen (back_faces.hpp).
uniform bool u_two_sided;

// A texture map: its texture (with its sampler object: filter and wrap modes) and the texture
// coordinate transform (KHR_texture_transform).
struct TextureMap {
  bool present;
  sampler2D texture;
  mat3 transform;
};
uniform TextureMap u_base_color_map;
uniform TextureMap u_normal_map;
uniform TextureMap u_specular_map;
uniform TextureMap u_metallic_roughness_map;
uniform TextureMap u_occlusion_map;
uniform TextureMap u_emissive_map;
// The level of detail comes from the hardware's 2x2-quad differences of uv; facet computes the
// exact derivatives per pixel instead (docs/gl_twin.md).
#define SAMPLE_MAP(map) texture(map.texture, (map.transform * vec3(in_v.texcoord, 1.0)).xy)

// Fog (facet/light.hpp's Fog, shading/shade_batch.cpp).
uniform int u_fog_mode;  // 0 none, 1 linear, 2 exponential
uniform vec3 u_fog_color;
uniform float u_fog_start, u_fog_end, u_fog_density;
// Distance along the view axis from the fragment's w and window depth (uniforms.hpp's ViewDepth).
uniform vec3 u_view_depth;  // from_w, from_z, offset
uniform bool u_env_reflections;

// Debug views.
uniform bool u_display_exact;  // a float target: display values unrounded
uniform float u_depth_view_near, u_depth_view_far;

float view_depth() {
  return u_view_depth.x * (1.0 / gl_FragCoord.w) + u_view_depth.y * gl_FragCoord.z +
         u_view_depth.z;
}

float srgb_to_linear(float c) {
  return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

// A value to show as it is (models.hpp's display_value): an 8-bit code, stored decoded to
// linear so that the sRGB encode at the end gives the code back.
vec3 display_value(vec3 shown) {
  vec3 unit = clamp(shown, 0.0, 1.0);
  if (u_display_exact) return unit;
  vec3 code = floor(unit * 255.0 + 0.5) / 255.0;
  return vec3(srgb_to_linear(code.r), srgb_to_linear(code.g), srgb_to_linear(code.b));
}

vec3 emission() {
  vec3 e = u_emissive;
  if (e != vec3(0.0) && u_emissive_map.present) e *= SAMPLE_MAP(u_emissive_map).rgb;
  return e;
}

// The lit models' common start (shade_batch.cpp: view, normal, normal map, albedo).
struct SurfacePoint {
  vec3 position;
  vec3 normal;  // unit, normal map applied, reversed on a two-sided back face
  vec3 view;    // unit, toward the eye
  vec4 albedo;  // color x base color map
};

SurfacePoint surface_point() {
  SurfacePoint s;
  vec3 interpolated = in_v.normal;
  if (u_two_sided && (normals_front == 1) != gl_FrontFacing) interpolated = -interpolated;
  vec3 n = safe_normalize(interpolated);
  s.position = in_v.position;
  s.view = safe_normalize(u_eye - s.position);
  vec4 tangent = in_v.tangent;
  if (u_normal_map.present && dot(tangent.xyz, tangent.xyz) > 0.0) {
    // Tangent space -> world: Gram-Schmidt the interpolated tangent against the normal.
    vec3 t = safe_normalize(tangent.xyz - n * dot(n, tangent.xyz));
    vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 texel = SAMPLE_MAP(u_normal_map).rgb * 2.0 - 1.0;
    texel.xy *= u_normal_scale;
    vec3 mapped = safe_normalize(t * texel.x + b * texel.y + n * texel.z);
    if (mapped != vec3(0.0)) n = mapped;
  }
  s.normal = n;
  s.albedo = in_v.color;
  if (u_base_color_map.present) s.albedo *= SAMPLE_MAP(u_base_color_map);
  return s;
}

// Phong models: mix toward the environment's mirror reflection.
vec3 reflect_environment(vec3 color, SurfacePoint s) {
  if (u_reflectivity <= 0.0 || !u_env_reflections) return color;
  return mix(color, environment_radiance(reflect(-s.view, s.normal), 0.0), u_reflectivity);
}

vec4 phong(bool blinn) {
  SurfacePoint s = surface_point();
  vec3 albedo = s.albedo.rgb, spec = u_specular_color;
  if (u_specular_map.present) spec *= SAMPLE_MAP(u_specular_map).rgb;
  vec3 color = albedo * u_ambient;
  for (int i = 0; i < u_light_count; ++i) {
    IncidentLight light_in = incident(i, s.position);
    float n_dot_l = dot(s.normal, light_in.direction);
    if (n_dot_l <= 0.0) continue;
    float highlight = blinn ? blinn_phong_specular(s.normal, s.view, light_in.direction, u_shininess)
                            : phong_specular(s.normal, s.view, light_in.direction, u_shininess);
    color += light_in.radiance * (albedo * n_dot_l + spec * highlight);
  }
  color = reflect_environment(color, s);
  return vec4(color + emission(), s.albedo.a);
}

// Cook-Torrance; lights scaled by pi so a white Lambertian surface under a unit light is as
// bright as under the Lambert model (shade_batch.cpp's PbrLight).
vec4 pbr() {
  SurfacePoint s = surface_point();
  vec3 albedo = s.albedo.rgb;
  float metallic = u_metallic, roughness = u_roughness;
  if (u_metallic_roughness_map.present) {
    vec4 mr = SAMPLE_MAP(u_metallic_roughness_map);
    roughness *= mr.g;  // glTF packing: roughness in green, metallic in blue
    metallic *= mr.b;
  }
  float occlusion = 1.0;
  if (u_occlusion_map.present) {
    occlusion = 1.0 + u_occlusion_strength * (SAMPLE_MAP(u_occlusion_map).r - 1.0);
  }
  vec3 color = vec3(0.0);
  for (int i = 0; i < u_light_count; ++i) {
    IncidentLight light_in = incident(i, s.position);
    float n_dot_l = dot(s.normal, light_in.direction);
    if (n_dot_l <= 0.0) continue;
    color += cook_torrance(albedo, metallic, roughness, s.normal, s.view, light_in.direction) *
             light_in.radiance * (n_dot_l * kPi);
  }
  vec3 f0 = mix(vec3(0.04), albedo, metallic);
  vec3 diffuse_albedo = albedo * (1.0 - metallic);
  vec3 ambient = u_ambient * (diffuse_albedo + f0 * 0.5);
  if (u_env_reflections) {
    vec3 mirror = reflect(-s.view, s.normal);
    vec3 fresnel = fresnel_schlick(f0, dot(s.normal, s.view));
    float blur = roughness * 8.0;
    ambient += environment_radiance(mirror, blur) * fresnel * (1.0 - roughness * 0.7);
  }
  color += ambient * occlusion;
  return vec4(color + emission(), s.albedo.a);
}

vec4 shade() {
#if defined(MODEL_UNLIT)
  vec4 color = in_v.color;
  if (u_base_color_map.present) color *= SAMPLE_MAP(u_base_color_map);
  return color + vec4(emission(), 0.0);
#elif defined(MODEL_VERTEX_COLOR)
  return in_v.color;  // the vertex stage was given a white base color
#elif defined(MODEL_FLAT)
  return face_color;
#elif defined(MODEL_LAMBERT)
  SurfacePoint s = surface_point();
  return vec4(diffuse_light(s.albedo.rgb, s.normal, s.position) + emission(), s.albedo.a);
#elif defined(MODEL_GOURAUD)
  vec4 albedo = in_v.color;
  if (u_base_color_map.present) albedo *= SAMPLE_MAP(u_base_color_map);
  return vec4(albedo.rgb * in_v.diffuse + in_v.specular + emission(), albedo.a);
#elif defined(MODEL_PHONG)
  return phong(false);
#elif defined(MODEL_BLINN_PHONG)
  return phong(true);
#elif defined(MODEL_PBR)
  return pbr();
#elif defined(MODEL_DEPTH)
  float t = (view_depth() - u_depth_view_near) / max(u_depth_view_far - u_depth_view_near, 1e-30);
  return vec4(display_value(vec3(clamp(1.0 - t, 0.0, 1.0))), 1.0);
#elif defined(MODEL_NORMALS)
  return vec4(display_value(safe_normalize(in_v.normal) * 0.5 + 0.5), 1.0);
#elif defined(MODEL_TEXCOORDS)
  return vec4(display_value(vec3(fract(in_v.texcoord), 0.0)), 1.0);
#elif defined(MODEL_WIRE)
  return u_wire_color;
#else
#error "no MODEL_* defined"
#endif
}

void main() {
  vec4 color = shade();
#ifdef WIRE_OVERLAY
  // Pixels within half a pixel of an edge take the wire color (pixel_writer.hpp's overlay).
  for (int i = 0; i < 3; ++i) {
    vec3 line = edge_lines[i];
    if (abs(dot(line, vec3(gl_FragCoord.xy, 1.0))) < 0.5 * length(line.xy)) color = u_wire_color;
  }
#endif
#if defined(ALPHA_MASK) && defined(ALPHA_TO_COVERAGE) && defined(GL_ARB_sample_shading)
  // MSAA: alpha to coverage as pixel_writer.hpp's alpha_to_coverage, the cutoff keeping half the
  // samples and the first ones of the pattern kept (a fixed subset, where GL's own
  // GL_SAMPLE_ALPHA_TO_COVERAGE is the driver's choice). The mask is ANDed with the coverage.
  {
    float c = u_alpha_cutoff, kept;
    if (isnan(color.a)) discard;
    if (color.a >= c) {
      kept = c >= 1.0 ? 1.0 : 0.5 + 0.5 * (color.a - c) / (1.0 - c);
    } else {
      kept = c <= 0.0 ? 0.0 : 0.5 * color.a / c;
    }
    int n = int(clamp(kept, 0.0, 1.0) * float(ALPHA_TO_COVERAGE) + 0.5);
    if (n == 0) discard;
    gl_SampleMask[0] = n >= 32 ? -1 : (1 << n) - 1;
  }
#elif defined(ALPHA_MASK)
  if (!(color.a >= u_alpha_cutoff)) discard;  // cut-out: no color, no depth
#endif
#ifdef MODEL_WIRE
  out_color = color;  // facet's lines are not fogged (pipeline/raster/line.cpp)
  return;
#endif
#ifdef ALPHA_OPAQUE
  color.a = 1.0;  // pixel_writer.hpp's blend_into: an opaque surface covers what it draws
#endif
  if (u_fog_mode != 0) {
    float depth = view_depth();
    float keep = u_fog_mode == 1 ? (u_fog_end - depth) / max(u_fog_end - u_fog_start, 1e-6)
                                 : exp(-u_fog_density * depth);
    color.rgb = mix(u_fog_color, color.rgb, clamp(keep, 0.0, 1.0));
  }
  out_color = color;
}
)glsl";

const char* const kSkyVertexGlsl = R"glsl(
// One triangle over the whole viewport, on the far plane (depth 1): it shows only where the
// depth test finds nothing drawn, as facet fills its background after the opaque draws.
void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(corner, 1.0, 1.0);
}
)glsl";

const char* const kSkyFragmentGlsl = R"glsl(
uniform mat4 u_inverse_view_projection;
uniform vec2 u_viewport;  // width, height in pixels
out vec4 out_color;

// The pixel centre's point on the far plane, seen from the eye (sky_row.cpp's
// FillSkyRow). GL counts rows from the bottom, facet from the top: the same NDC.
void main() {
  vec2 ndc = gl_FragCoord.xy / u_viewport * 2.0 - 1.0;
  vec4 far = u_inverse_view_projection * vec4(ndc, 1.0, 1.0);
  vec3 direction = normalize(far.xyz / far.w - u_eye);
  out_color = vec4(environment_radiance(direction, 0.0), 1.0);
}
)glsl";

}  // namespace facet::gl
