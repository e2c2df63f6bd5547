// The reference rasterizer (see reference.hpp). Read this file first to learn the pipeline:
// every step the fast path takes is here in its plainest form. Each pixel centre is tested
// against each triangle from scratch: edge functions give coverage and, divided by the
// vertices' clip w, the perspective-correct weights of the varyings.
#include "pipeline/reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <stdexcept>
#include <string>

#include "pipeline/geometry/clip.hpp"
#include "pipeline/geometry/primitive.hpp"
#include "pipeline/setup/back_faces.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "pipeline/setup/setup.hpp"

namespace facet::pipeline {
namespace {

// A vertex's varyings: texture coordinate, unit world normal, world position.
constexpr int kTexcoord = 0, kNormal = 2, kPosition = 5, kVaryings = 8;
using Varyings = std::array<float, kVaryings>;

// The edge function of the edge from p to q at (cx, cy), fixed point, exact in 64 bits
// (fixed_point.hpp): twice the signed area of (p, q, c), positive on the inside of a triangle
// wound clockwise on screen.
std::int64_t edge_function(const ScreenVertex& p, const ScreenVertex& q, std::int64_t cx,
                           std::int64_t cy) {
  return (std::int64_t{q.x} - p.x) * (cy - p.y) - (std::int64_t{q.y} - p.y) * (cx - p.x);
}

// A centre on the edge belongs to the triangle only if the edge is top or left (setup.hpp).
bool inside(std::int64_t e, const ScreenVertex& p, const ScreenVertex& q) {
  return e > 0 || (e == 0 && is_top_left(q.x - p.x, q.y - p.y));
}

glm::vec3 unit(glm::vec3 v) {
  const float length = glm::length(v);
  return length > 0.0f ? v / length : glm::vec3(0.0f);
}

// The varyings at a pixel centre, perspective-correct. e[i] / area is vertex i's barycentric
// weight b_i on screen; varyings are affine in clip space, not on screen, so each vertex is
// weighted by b_i / w_i (w_i its clip w) and the weights are renormalised:
//   lambda_i = (e_i / w_i) / (e_0 / w_0 + e_1 / w_1 + e_2 / w_2),   a = sum_i lambda_i a_i,
// the area cancelling. In double: the e_i are exact integers, the rest rounds little.
Varyings interpolate(const ClipVertex* const v[3], const std::int64_t e[3]) {
  double weight[3], sum = 0.0;
  for (int i = 0; i < 3; ++i) sum += weight[i] = static_cast<double>(e[i]) / v[i]->clip.w;
  Varyings out;
  for (int k = 0; k < kVaryings; ++k) {
    double a = 0.0;
    for (int i = 0; i < 3; ++i) a += weight[i] / sum * v[i]->varyings[k];
    out[k] = static_cast<float>(a);
  }
  return out;
}

// Lambert as shading/models.hpp's LambertShading computes it:
//   albedo = base color x texel,  rgb = albedo x (ambient + sum_lights radiance x max(N.L, 0)),
//   alpha = 1 (an opaque draw covers what it draws, whatever the texel's alpha),
// with radiance = color x intensity, L the unit vector against the light's direction, and N
// the interpolated world normal renormalised and, for a two-sided material (cull none),
// reversed on a triangle seen from the side its vertex normals turn away from (as
// setup_batch.cpp's ReversesNormal decides). The texel is sampled at level of detail 0: exact for
// the nearest and bilinear filters, which read the base level only (check() refuses trilinear).
glm::vec4 shade(const ReferenceScene& scene, const Varyings& v, bool reverse_normal) {
  const Material& m = scene.material;
  glm::vec4 albedo = m.base_color;
  if (m.base_color_map) {
    const glm::vec2 uv(m.base_color_map.transform * glm::vec3(v[kTexcoord], v[kTexcoord + 1], 1));
    albedo *= m.base_color_map.texture->sample(m.base_color_map.sampler, uv, 0.0f);
  }
  glm::vec3 n = unit({v[kNormal], v[kNormal + 1], v[kNormal + 2]});
  if (reverse_normal) n = -n;
  glm::vec3 light = scene.lighting.ambient;
  for (const Light& l : scene.lighting.lights) {
    light += l.color * l.intensity * std::max(glm::dot(n, -unit(l.direction)), 0.0f);
  }
  return {glm::vec3(albedo) * light, 1.0f};
}

// Rasterizes one screen triangle with its clip vertices' varyings; shades with scene unless it
// is null (coverage and depth only).
void rasterize(ScreenVertex s[3], const ClipVertex* v[3], bool front_facing, bool reverse_normal,
               const ReferenceScene* scene, ReferenceImage& image) {
  std::int64_t area = signed_area(s[0], s[1], s[2]);
  if (area == 0 || (area < 0) != front_facing) return;  // degenerate once snapped
  if (area < 0) {  // clockwise on screen for the edge functions, varyings following
    std::swap(s[1], s[2]);
    std::swap(v[1], v[2]);
  }
  // Depth is the plane through the three snapped vertices, evaluated as the fast path does
  // (setup.hpp's make_plane and evaluate), so the two agree bit for bit.
  float px[3], py[3], z[3];
  for (int i = 0; i < 3; ++i) {
    px[i] = static_cast<float>(s[i].x) / kSubpixelScale;
    py[i] = static_cast<float>(s[i].y) / kSubpixelScale;
    z[i] = s[i].z;
  }
  Plane depth = make_plane(px, py, z);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::int64_t cx = pixel_centre(x), cy = pixel_centre(y);
      std::int64_t e[3];  // e[i]: the edge opposite vertex i, from s[i + 1] to s[i + 2]
      bool covered = true;
      for (int i = 0; i < 3; ++i) {
        const ScreenVertex& p = s[(i + 1) % 3];
        const ScreenVertex& q = s[(i + 2) % 3];
        e[i] = edge_function(p, q, cx, cy);
        covered = covered && inside(e[i], p, q);
      }
      if (!covered) continue;
      std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      ++image.coverage[i];
      float d = evaluate(depth, px[0], py[0], x + 0.5f, y + 0.5f);
      if (!(d < image.depth[i])) continue;  // depth test "less": the first of equals stays
      image.depth[i] = d;
      if (scene) image.color[i] = shade(*scene, interpolate(v, e), reverse_normal);
    }
  }
}

// One triangle in clip space, as primitive assembly treats it: dropped if not finite, outside
// the frustum, degenerate or culled; clipped against near, far and the guard band; drawn as
// a fan.
void draw_triangle(ClipPolygon& polygon, CullMode cull, const ReferenceScene* scene,
                   ReferenceImage& image) {
  const ClipBounds frustum{1.0f, 1.0f};
  const ClipBounds guard = guard_band_bounds(image.width, image.height);
  const ClipVertex* v = polygon.vertices;
  for (int i = 0; i < 3; ++i) {
    const glm::vec4& c = v[i].clip;
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || !std::isfinite(c.w))
      return;
  }
  if (outcode(v[0].clip, frustum) & outcode(v[1].clip, frustum) & outcode(v[2].clip, frustum)) {
    return;
  }
  double orientation = homogeneous_orientation(v[0].clip, v[1].clip, v[2].clip);
  bool front = orientation > 0.0;
  if (orientation == 0.0 || (cull == CullMode::back && !front) ||
      (cull == CullMode::front && front)) {
    return;
  }
  unsigned planes =
      outcode(v[0].clip, guard) | outcode(v[1].clip, guard) | outcode(v[2].clip, guard);
  if (planes) clip_polygon(polygon, planes, guard, kVaryings);
  for (int i = 1; i + 1 < polygon.count; ++i) {
    const ClipVertex* corner[3] = {&v[0], &v[i], &v[i + 1]};
    ScreenVertex s[3];
    for (int k = 0; k < 3; ++k) s[k] = to_screen(corner[k]->clip, image.width, image.height);
    bool reverse_normal = false;
    if (scene && scene->material.cull == CullMode::none) {
      // Decided on the values setup reads: each varying times 1 / w.
      float over_w[3][kVaryings], inv_w[3];
      for (int k = 0; k < 3; ++k) {
        inv_w[k] = s[k].inv_w;
        for (int j = 0; j < kVaryings; ++j) over_w[k][j] = corner[k]->varyings[j] * inv_w[k];
      }
      const float* const corners[3] = {over_w[0], over_w[1], over_w[2]};
      reverse_normal = reverses_normal(corners, inv_w, kPosition, kNormal, front);
    }
    rasterize(s, corner, front, reverse_normal, scene, image);
  }
}

ReferenceImage blank_image(int width, int height) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  return {width, height, std::vector<int>(pixels, 0), std::vector<float>(pixels, 1.0f), {}};
}

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("reference_render: ") + what);
}

// What reference_render draws, and nothing else.
void check(const ReferenceScene& scene) {
  const Mesh& mesh = scene.mesh;
  const Material& m = scene.material;
  mesh.validate();
  require(mesh.topology == Topology::triangles, "triangle lists only");
  require(mesh.normals.size() == mesh.positions.size(), "a normal per vertex is needed");
  require(mesh.colors.empty() || !m.use_vertex_colors, "no vertex colors");
  require(m.shading == ShadingModel::lambert && m.alpha_mode == AlphaMode::opaque &&
              m.emissive == glm::vec3(0.0f),
          "opaque Lambert without emission only");
  require(!m.base_color_map || m.base_color_map.sampler.filter != Filter::trilinear,
          "no mip selection: the base color map must be nearest or bilinear");
  require(scene.lighting.fog.mode == FogMode::none, "no fog");
  for (const Light& l : scene.lighting.lights) {
    require(l.type == LightType::directional && l.direction != glm::vec3(0.0f),
            "directional lights with a direction only");
  }
}

}  // namespace

ReferenceImage reference_rasterize(const std::vector<glm::vec3>& positions,
                                   const glm::mat4& model_view_projection, CullMode cull, int width,
                                   int height) {
  ReferenceImage image = blank_image(width, height);
  for (std::size_t t = 0; t + 2 < positions.size(); t += 3) {
    ClipPolygon polygon{};  // varyings zero: clip_polygon interpolates them all the same
    polygon.count = 3;
    for (int i = 0; i < 3; ++i) {
      polygon.vertices[i].clip = model_view_projection * glm::vec4(positions[t + i], 1.0f);
    }
    draw_triangle(polygon, cull, nullptr, image);
  }
  return image;
}

ReferenceImage reference_render(const ReferenceScene& scene, int width, int height) {
  check(scene);
  const Mesh& mesh = scene.mesh;
  ReferenceImage image = blank_image(width, height);
  image.color.assign(image.depth.size(), scene.clear_color);
  const glm::mat4 model_view_projection = scene.camera.view_projection() * scene.model;
  // Normals go to world space by the inverse transpose of the model matrix's linear part.
  const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(scene.model));
  const std::size_t count = mesh.element_count();
  for (std::size_t t = 0; t + 2 < count; t += 3) {
    ClipPolygon polygon{};
    polygon.count = 3;
    for (int i = 0; i < 3; ++i) {
      const std::size_t k = mesh.indices.empty() ? t + i : mesh.indices[t + i];
      const glm::vec4 position(mesh.positions[k], 1.0f);
      const glm::vec2 uv = mesh.texcoords.empty() ? glm::vec2(0.0f) : mesh.texcoords[k];
      const glm::vec3 normal = unit(normal_matrix * mesh.normals[k]);
      const glm::vec3 world(scene.model * position);
      ClipVertex& c = polygon.vertices[i];
      c.clip = model_view_projection * position;
      const float values[kVaryings] = {uv.x,     uv.y,    normal.x, normal.y,
                                       normal.z, world.x, world.y,  world.z};
      std::copy_n(values, kVaryings, c.varyings);
    }
    draw_triangle(polygon, scene.material.cull, &scene, image);
  }
  return image;
}

}  // namespace facet::pipeline
