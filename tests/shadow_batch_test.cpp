// Shadowed draws on every SIMD target, for random points and normals against random depth maps
// of a sun with one or three cascades (blending where they meet, or not) and of a spot light
// (points inside a map, partly over its edges, outside it, beyond its far plane and behind the
// light): the shadow lookup (shadow_batch-inl.h) gives the one-point definition's bits
// (tests/support/light_reference.hpp); the models lit per pixel (shade_batch.cpp) shade a
// shadowed pixel as the unshadowed one under the light scaled by that visibility; and the
// Gouraud models' vertex batch (vertex_batch.cpp) gives the portable target's bits.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "facet/light.hpp"
#include "shading/kernels.hpp"
#include "shading/lighting.hpp"
#include "shading/lit_models.hpp"
#include "shading/models.hpp"
#include "shading/shadow_map.hpp"
#include "support/forced_target.hpp"
#include "support/light_reference.hpp"
#include "support/shadow_batch_probe.hpp"

namespace facet::test {
namespace {

using shading::kShadeBatch;
using shading::ShadowMaps;

// A light's maps over a scene about the origin, of random depths: occluders of 6 x 6 texels at
// depths between 0.3 and 0.7, where the receivers are, give or take a little per texel, or
// nothing drawn (1), one in five. A sun's: each an orthographic view along `travel`, the cascades
// nested (each twice as wide as the one before). A spot light's: one perspective view from
// `position` along `travel`.
struct Caster {
  glm::vec3 travel{0.0f};
  glm::vec3 position{0.0f};   // a spot light's
  float cone_degrees = 0.0f;  // a spot light's view: half its field of view
  std::vector<float> depth[shading::kMaxShadowCascades];
  ShadowMaps maps;
};

// Window coordinates of the light's view -> texel coordinates and depth, as
// pipeline/shadow/shadow_passes.cpp's shadow_map_of.
glm::mat4 window_to_map(int size) {
  const float s = static_cast<float>(size);
  glm::mat4 to_map(1.0f);
  to_map[0][0] = 0.5f * s, to_map[3][0] = 0.5f * s - 0.5f;
  to_map[1][1] = -0.5f * s, to_map[3][1] = 0.5f * s - 0.5f;
  to_map[2][2] = 0.5f, to_map[3][2] = 0.5f;
  return to_map;
}

void fill_depths(std::mt19937& rng, int size, std::vector<float>& texels) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), depth(0.3f, 0.7f);
  texels.resize(static_cast<std::size_t>(size) * size);
  constexpr int kOccluder = 6;
  const int occluders = (size + kOccluder - 1) / kOccluder;
  std::vector<float> occluder(static_cast<std::size_t>(occluders) * occluders);
  for (float& o : occluder) o = rng() % 5 == 0 ? 1.0f : depth(rng);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float o = occluder[(y / kOccluder) * occluders + x / kOccluder];
      texels[static_cast<std::size_t>(y) * size + x] = o == 1.0f ? o : o + 0.02f * any(rng);
    }
  }
}

glm::vec3 up_for(glm::vec3 travel) {
  return std::abs(travel.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
}

void make_sun(std::mt19937& rng, int cascades, int size, Caster& sun) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f);
  sun.travel = glm::normalize(glm::vec3(any(rng), -1.5f, any(rng)));
  const glm::mat4 view = glm::lookAt(-20.0f * sun.travel, glm::vec3(0.0f), up_for(sun.travel));
  sun.maps.count = cascades;
  for (int c = 0; c < cascades; ++c) {
    const float half = 3.0f * static_cast<float>(1 << c);
    const glm::mat4 projection = glm::ortho(-half, half, -half, half, 1.0f, 40.0f);
    fill_depths(rng, size, sun.depth[c]);
    sun.maps.maps[c] = shading::make_shadow_map(window_to_map(size) * projection * view,
                                                sun.depth[c].data(), size, false);
  }
}

// A spot light above the origin looking at it, its cone 40 to 100 degrees wide.
void make_spot(std::mt19937& rng, int size, Caster& spot) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), cone(40.0f, 100.0f);
  spot.position = {any(rng) * 4.0f, 6.0f + any(rng), any(rng) * 4.0f};
  spot.travel = glm::normalize(glm::vec3(any(rng), 0.0f, any(rng)) - spot.position);
  const glm::mat4 view =
      glm::lookAt(spot.position, spot.position + spot.travel, up_for(spot.travel));
  spot.cone_degrees = 0.5f * cone(rng);
  const glm::mat4 projection =
      glm::perspective(glm::radians(2.0f * spot.cone_degrees), 1.0f, 0.5f, 30.0f);
  fill_depths(rng, size, spot.depth[0]);
  spot.maps.count = 1;
  spot.maps.maps[0] = shading::make_shadow_map(window_to_map(size) * projection * view,
                                               spot.depth[0].data(), size, true);
}

// map.world_to_map applied to p, divided by w (a perspective map's): texel coordinates and depth.
glm::vec3 map_point(const shading::ShadowMap& map, glm::vec3 p) {
  const glm::vec4 h = map.world_to_map * glm::vec4(p, 1.0f);
  return map.perspective ? glm::vec3(h) / h.w : glm::vec3(h);
}

// A random point of cascade `c`'s map: mostly near it (its edges included), now and then far
// outside it or beyond its far plane, or (a spot light's) behind the light.
glm::vec3 random_point(std::mt19937& rng, const Caster& light, int c) {
  const shading::ShadowMap& map = light.maps.maps[c];
  const float size = static_cast<float>(map.size);
  std::uniform_real_distribution<float> across(-6.0f, size + 6.0f), edge(-3.0f, 3.0f),
      depth(0.25f, 0.75f), beyond(1.0f, 1.3f), far(-1e6f, 1e6f), any(-1.0f, 1.0f);
  glm::vec3 m(across(rng), across(rng), depth(rng));
  switch (rng() % 16) {
    case 0:  // far outside the map, now and then beyond 2^23 texels (no fraction left)
      m.x = far(rng), m.y = far(rng);
      if (rng() % 2) m.x *= 1000.0f;
      break;
    case 1:  // beyond the far plane (a perspective view's: also behind the light)
      m.z = beyond(rng);
      break;
    case 2:
    case 3:  // the footprint over an edge or a corner
      m.x = (rng() % 2 ? size : 0.0f) + edge(rng);
      if (rng() % 2) m.y = (rng() % 2 ? size : 0.0f) + edge(rng);
      break;
    case 4:  // behind a spot light, or level with it
      if (!map.perspective) break;
      return light.position - light.travel * (rng() % 4 == 0 ? 0.0f : 5.0f * (any(rng) + 1.0f)) +
             glm::vec3(any(rng), any(rng), any(rng)) * 3.0f;
    default:
      break;
  }
  const glm::vec4 p = glm::inverse(map.world_to_map) * glm::vec4(m, 1.0f);
  return map.perspective ? glm::vec3(p) / p.w : glm::vec3(p);
}

// A random normal: any direction and length (the models normalize it), toward the light,
// across the light ray (a receiver-plane slope beyond the clamp), or none.
glm::vec3 random_normal(std::mt19937& rng, const Caster& sun) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), length(0.5f, 2.0f);
  switch (rng() % 8) {
    case 0:
      return glm::vec3(0.0f);
    case 1:
      return -sun.travel * length(rng);
    case 2:
      return glm::cross(sun.travel, glm::vec3(any(rng), any(rng), any(rng)));
    default:
      return glm::vec3(any(rng), any(rng), any(rng)) * length(rng);
  }
}

// The view the cascades split: their far depths at a third and two thirds of the points', and
// (two times in three) blend bands over the last tenth to half of each slice but the last, drawn
// from a generator of their own seeded by the split (so they leave `rng`'s draws to the rest of
// the test as they are).
void split_cascades(std::mt19937& rng, const std::vector<glm::vec3>& points, Caster& sun) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), share(0.1f, 0.5f);
  sun.maps.eye = {any(rng) * 10.0f, 5.0f, any(rng) * 10.0f};
  sun.maps.forward = glm::normalize(-sun.maps.eye + glm::vec3(any(rng), 0.0f, any(rng)));
  std::vector<float> depths;
  for (const glm::vec3& p : points) depths.push_back(glm::dot(p - sun.maps.eye, sun.maps.forward));
  std::sort(depths.begin(), depths.end());
  for (int c = 0; c < sun.maps.count; ++c) {
    sun.maps.far_depth[c] = depths[(depths.size() - 1) * (c + 1) / sun.maps.count];
    sun.maps.blend_from[c] = sun.maps.far_depth[c], sun.maps.blend_rate[c] = 0.0f;
  }
  std::mt19937 bands(std::bit_cast<std::uint32_t>(sun.maps.far_depth[0]));
  if (sun.maps.count == 1 || bands() % 3 == 0) return;
  for (int c = 0; c + 1 < sun.maps.count; ++c) {
    const float slice_start = c == 0 ? depths.front() : sun.maps.far_depth[c - 1];
    const float band = share(bands) * (sun.maps.far_depth[c] - slice_start);
    if (!(band > 0.0f)) continue;
    sun.maps.blend_from[c] = sun.maps.far_depth[c] - band;
    sun.maps.blend_rate[c] = 1.0f / band;
  }
}

// What the scalar lookup gives the points: fully lit, fully shadowed or in between, from
// footprints inside a map and partly over its edges, and (a sun's cascades) in a blend band
// between two maps that differ there. Each kind must be compared.
struct Seen {
  int lit = 0, shadowed = 0, partly = 0, partly_at_edge = 0, blended = 0;
  void add(const ShadowMaps& maps, glm::vec3 p, glm::vec3 n) {
    n = shading::safe_normalize(n);
    const float v = shadow_visibility(maps, p, n);
    if (v == 1.0f) ++lit;
    if (v == 0.0f) ++shadowed;
    const float depth = glm::dot(p - maps.eye, maps.forward);
    int c = 0;
    while (c + 1 < maps.count && depth > maps.far_depth[c]) ++c;
    if (c + 1 < maps.count && maps.blend_rate[c] > 0.0f && depth > maps.blend_from[c] &&
        shadow_visibility(maps.maps[c], p, n) != shadow_visibility(maps.maps[c + 1], p, n)) {
      ++blended;
    }
    if (v <= 0.0f || v >= 1.0f) return;
    ++partly;
    const glm::vec3 m = map_point(maps.maps[c], p);
    const float size = static_cast<float>(maps.maps[c].size);
    if (m.x < 2.0f || m.y < 2.0f || m.x >= size - 2.0f || m.y >= size - 2.0f) ++partly_at_edge;
  }
  void expect_each_kind() const {
    EXPECT_GT(lit, 50);
    EXPECT_GT(shadowed, 50);
    EXPECT_GT(partly, 50);
    EXPECT_GT(partly_at_edge, 10);
  }
};

struct Draw {
  Material material;
  Lighting lighting;
  shading::LightData lights[2];
  shading::ShadingKernels kernels;
  shading::FrameUniforms frame;
  shading::DrawUniforms uniforms;
};

// One or two directional lights, the first the sun casting through `maps`, the second
// (when there) unshadowed or casting too.
void make_draw(std::mt19937& rng, const Caster& sun, Draw& d) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), unit(0.0f, 1.0f);
  d.uniforms.material = &d.material;
  d.uniforms.frame = &d.frame;
  d.kernels = shading::shading_kernels(chosen_simd_target());  // the forced target's
  d.frame.kernels = &d.kernels;
  d.frame.lighting = &d.lighting;
  d.frame.eye = {any(rng) * 5.0f, any(rng) * 5.0f, any(rng) * 5.0f};
  d.frame.ambient = {unit(rng) * 0.2f, unit(rng) * 0.2f, unit(rng) * 0.2f};
  d.frame.light_count = 1 + static_cast<int>(rng() % 2);
  d.lights[0].to_light = -sun.travel;
  d.lights[0].shadow = &sun.maps;
  d.lights[1].to_light = glm::normalize(glm::vec3(any(rng), any(rng), any(rng)) + 0.01f);
  d.lights[1].shadow = rng() % 2 ? &sun.maps : nullptr;
  for (shading::LightData& light : d.lights) {
    light.radiance = {0.5f + unit(rng) * 3.0f, 0.5f + unit(rng) * 3.0f, 0.5f + unit(rng) * 3.0f};
  }
  d.frame.lights = d.lights;
  d.material.cull = rng() % 2 ? CullMode::none : CullMode::back;
  d.material.base_color = {0.2f + unit(rng), 0.2f + unit(rng), 0.2f + unit(rng), 1.0f};
  d.material.specular_color = {unit(rng), unit(rng), unit(rng)};
  d.material.shininess = rng() % 5 == 0 ? 0.0f : 1.0f + unit(rng) * 127.0f;
}

constexpr int kRounds = 30;

// Pixel n of varyings v shaded as the draw without shadows, each shadowed light's radiance
// scaled by the scalar shadow_visibility at the pixel: what the batch kernel gives the shadowed
// draw if its lookup gives shadow_visibility's bits (received_radiance is radiance x visibility).
template <class Shading>
glm::vec4 unshadowed_with_scalar_visibility(const Draw& shadowed, const float (*v)[kShadeBatch],
                                            int n) {
  Draw d = shadowed;
  d.uniforms.material = &d.material;
  d.uniforms.frame = &d.frame;
  d.frame.kernels = &d.kernels;
  d.frame.lighting = &d.lighting;
  d.frame.lights = d.lights;
  alignas(64) float one[shading::kMaxVaryings][kShadeBatch] = {};
  for (int k = 0; k < shading::kMaxVaryings; ++k) one[k][0] = v[k][n];
  const glm::vec3 p(v[shading::kPositionSlot][n], v[shading::kPositionSlot + 1][n],
                    v[shading::kPositionSlot + 2][n]);
  const glm::vec3 normal = shading::safe_normalize(
      {v[shading::kNormalSlot][n], v[shading::kNormalSlot + 1][n], v[shading::kNormalSlot + 2][n]});
  for (shading::LightData& light : d.lights) {
    if (light.shadow == nullptr) continue;
    light.radiance = light.radiance * shadow_visibility(*light.shadow, p, normal);
    light.shadow = nullptr;
  }
  alignas(64) float w[kShadeBatch] = {1.0f}, z[kShadeBatch] = {};
  alignas(64) float rgba[kShadeBatch][4];
  Shading::fragment_batch(d.uniforms, {1, w, z, one, nullptr, &d.lighting.fog}, rgba);
  return {rgba[0][0], rgba[0][1], rgba[0][2], rgba[0][3]};
}

// Compares Shading::fragment_batch on shadowed draws with the same draws unshadowed but for the
// scalar shadow_visibility (unshadowed_with_scalar_visibility) over random batches, on every
// SIMD target, with one and three cascades.
template <class Shading>
void expect_shadowed_pixels_bits() {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), w(0.2f, 50.0f);
  Seen seen;
  int compared = 0;
  for (std::int64_t target : targets) {
    ForcedTarget forced(target);
    for (int round = 0; round < kRounds; ++round) {
      Caster sun;
      make_sun(rng, round % 2 == 0 ? 1 : 3, round % 3 == 0 ? 16 : 40, sun);
      alignas(64) float in_w[kShadeBatch], in_z[kShadeBatch];
      alignas(64) float v[shading::kMaxVaryings][kShadeBatch];
      std::vector<glm::vec3> points(kShadeBatch), normals(kShadeBatch);
      for (int n = 0; n < kShadeBatch; ++n) {
        points[n] = random_point(rng, sun, static_cast<int>(rng() % sun.maps.count));
        normals[n] = random_normal(rng, sun);
        in_w[n] = w(rng), in_z[n] = unit(rng);
        for (int k = 0; k < shading::kMaxVaryings; ++k) v[k][n] = unit(rng);
        for (int c = 0; c < 3; ++c) {
          v[shading::kPositionSlot + c][n] = points[n][c];
          v[shading::kNormalSlot + c][n] = normals[n][c];
        }
      }
      split_cascades(rng, points, sun);
      Draw draw;
      make_draw(rng, sun, draw);
      const int count = round % 4 == 0 ? kShadeBatch : 1 + static_cast<int>(rng() % kShadeBatch);
      alignas(64) float rgba[kShadeBatch][4];
      const shading::ShadeInput input{count, in_w, in_z, v, nullptr, &draw.lighting.fog};
      Shading::fragment_batch(draw.uniforms, input, rgba);
      for (int n = 0; n < count; ++n) {
        const glm::vec4 expected = unshadowed_with_scalar_visibility<Shading>(draw, v, n);
        ASSERT_EQ(std::memcmp(&expected, rgba[n], sizeof expected), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel " << n << ": ("
            << rgba[n][0] << ", " << rgba[n][1] << ", " << rgba[n][2] << "), expected ("
            << expected.r << ", " << expected.g << ", " << expected.b << "), visibility "
            << shadow_visibility(sun.maps, points[n], shading::safe_normalize(normals[n]));
        seen.add(sun.maps, points[n], normals[n]);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 500 * static_cast<int>(targets.size()));
  seen.expect_each_kind();
  EXPECT_GT(seen.blended, 20);
}

TEST(ShadowBatch, LambertShadesShadowedPixelsOnEveryTarget) {
  expect_shadowed_pixels_bits<shading::LambertShading>();
}

TEST(ShadowBatch, PhongAndBlinnPhongShadeShadowedPixelsOnEveryTarget) {
  expect_shadowed_pixels_bits<shading::PhongShading>();
  expect_shadowed_pixels_bits<shading::BlinnPhongShading>();
}

// The Gouraud models look the shadow up per vertex: their vertex batch on every target against
// the portable target's.
template <class Model>
void expect_vertexs_bits() {
  const std::vector<std::int64_t> targets = simd_targets();
  const std::int64_t portable = portable_simd_target();
  ASSERT_NE(portable, 0);
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Seen seen, seen_spot;
  int compared = 0;
  for (int round = 0; round < 6 * kRounds; ++round) {
    // A sun of one or three cascades, or a spot light, the first light of the draw.
    const bool spot = round % 2 == 1;
    const int r = round / 2;
    Caster sun;
    if (spot) {
      make_spot(rng, r % 2 == 0 ? 16 : 40, sun);
    } else {
      make_sun(rng, r % 2 == 0 ? 1 : 3, r % 3 == 0 ? 16 : 40, sun);
    }
    Draw draw;
    const int count = 1 + static_cast<int>(rng() % shading::kVertexBatch);
    // World positions through a model transform: object positions from the random points.
    draw.uniforms.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, -0.25f, 1.0f));
    const glm::mat4 to_object = glm::inverse(draw.uniforms.model);
    std::vector<glm::vec3> positions(count), points(count);
    alignas(64) float normal[3][shading::kVertexBatch] = {};
    for (int n = 0; n < count; ++n) {
      points[n] = random_point(rng, sun, static_cast<int>(rng() % sun.maps.count));
      positions[n] = glm::vec3(to_object * glm::vec4(points[n], 1.0f));
      const glm::vec3 nv = shading::safe_normalize(random_normal(rng, sun));  // unit, or none
      for (int c = 0; c < 3; ++c) normal[c][n] = nv[c];
    }
    split_cascades(rng, points, sun);
    make_draw(rng, sun, draw);
    if (spot) {
      const float outer = sun.cone_degrees * (0.8f + 0.4f * unit(rng));
      draw.lights[0] = shading::prepare_light(Light::spot(
          sun.position, sun.travel, outer * unit(rng), outer, glm::vec3(1.0f, 0.9f, 0.8f),
          1.0f + unit(rng) * 4.0f, rng() % 2 ? 0.0f : 2.0f + unit(rng) * 2.0f));
      draw.lights[0].shadow = &sun.maps;
    }
    shading::VertexBatchInput in;
    in.count = count;
    in.positions = positions.data();
    for (int c = 0; c < 3; ++c) in.normal[c] = normal[c];
    compared += expect_rows_alike_on_every_target<shading::kVertexBatch>(
        Model::kVaryings, count,
        [&](float(*out)[shading::kVertexBatch]) {
          draw.kernels = shading::shading_kernels(chosen_simd_target());
          Model::vertex_batch(draw.uniforms, in, out);
        },
        "round " + std::to_string(round));
    for (int n = 0; n < count; ++n) {
      const glm::vec3 world(draw.uniforms.model * glm::vec4(positions[n], 1.0f));
      const glm::vec3 nv(normal[0][n], normal[1][n], normal[2][n]);
      if (!spot) {
        seen.add(sun.maps, world, nv);
      } else if (glm::dot(nv, incident(draw.lights[0], world).direction) > 0.0f &&
                 incident(draw.lights[0], world).radiance != glm::vec3(0.0f)) {
        seen_spot.add(sun.maps, world, nv);  // the spot's shadow is seen
      }
    }
  }
  EXPECT_GT(compared, 500 * static_cast<int>(targets.size()));
  seen.expect_each_kind();
  EXPECT_GT(seen.blended, 20);
  EXPECT_GT(seen_spot.lit, 50);
  EXPECT_GT(seen_spot.shadowed, 50);
  EXPECT_GT(seen_spot.partly, 50);
}

TEST(ShadowBatch, GouraudVerticesGivePortableBitsOnEveryTarget) {
  expect_vertexs_bits<shading::GouraudShading>();
  expect_vertexs_bits<shading::ConstantColorGouraudShading>();
  expect_vertexs_bits<shading::GrayLightGouraudShading>();
}

// The lookup itself (shadow_batch-inl.h's ShadowVisibility) against shadow_visibility, point by
// point on every SIMD target: a spot light's perspective map, points behind the light included,
// and a sun's one or three cascades, points in their blend bands included.
TEST(ShadowBatch, LookupGivesShadowVisibilitysBitsOnEveryTarget) {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  std::mt19937 rng(20261204);
  Seen seen_sun, seen_spot;
  int behind = 0, compared = 0;
  for (std::int64_t target : targets) {
    ForcedTarget forced(target);
    for (int round = 0; round < 2 * kRounds; ++round) {
      const bool spot = round % 2 == 0;
      Caster light;
      if (spot) {
        make_spot(rng, round % 3 == 0 ? 16 : 40, light);
      } else {
        make_sun(rng, round % 4 == 1 ? 1 : 3, 40, light);
      }
      const int count = 1 + static_cast<int>(rng() % 64);
      std::vector<glm::vec3> points(count), normals(count);
      for (int n = 0; n < count; ++n) {
        points[n] = random_point(rng, light, static_cast<int>(rng() % light.maps.count));
        normals[n] = shading::safe_normalize(random_normal(rng, light));
      }
      if (!spot) split_cascades(rng, points, light);
      std::vector<float> visibility(count);
      shadow_visibility_batch(chosen_simd_target(), light.maps, points.data(), normals.data(),
                              count, visibility.data());
      for (int n = 0; n < count; ++n) {
        const float expected = shadow_visibility(light.maps, points[n], normals[n]);
        ASSERT_EQ(std::memcmp(&expected, &visibility[n], sizeof expected), 0)
            << hwy::TargetName(target) << ", round " << round << ", point " << n << ": "
            << visibility[n] << ", shadow_visibility gives " << expected;
        ++compared;
        if (!spot) {
          seen_sun.add(light.maps, points[n], normals[n]);
          continue;
        }
        seen_spot.add(light.maps, points[n], normals[n]);
        const glm::vec4 h = light.maps.maps[0].world_to_map * glm::vec4(points[n], 1.0f);
        if (!(h.w > 0.0f)) ++behind;
      }
    }
  }
  EXPECT_GT(compared, 1000 * static_cast<int>(targets.size()));
  seen_spot.expect_each_kind();
  EXPECT_GT(seen_sun.blended, 20);
  EXPECT_GT(behind, 20);
}

}  // namespace
}  // namespace facet::test
