// Shadow maps (RenderSettings::shadows): the analytic case of a square above a plane under a
// straight-down sun (the shadow's outline where geometry puts it, no acne on the lit plane: lit
// pixels bit for bit as without shadows, shadowed ones as without the sun), no light leaking
// where a box stands on the plane, the same image for any thread count, tile size and SIMD
// target, and the settings the renderer refuses.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "facet/procedural.hpp"
#include "support/forced_target.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr float kGround = 8.0f;  // the plane's side, centred on the origin at y = 0

// What casts the shadow: a box, [low, high] in world space.
struct Occluder {
  glm::vec3 low, high;
};
// A square of side 2 facing up, 1 above the plane (a box of no real thickness).
constexpr Occluder kSquare{{-1.0f, 0.999f, -1.0f}, {1.0f, 1.001f, 1.0f}};
// A thin box standing on the plane, a wall of 2 x 2 across the x axis: the map holds its side
// facing the light, a tenth from the side in shadow, so a bias of more than that leaks light
// at its foot (a thick box would hide such a bias: the map holds its far side).
constexpr Occluder kWall{{-0.05f, 0.0f, -1.0f}, {0.05f, 2.0f, 1.0f}};

Camera view_camera() {
  return Camera::look_at({2.0f, 2.5f, 6.0f}, {0.0f, 0.3f, 0.0f}, {0, 1, 0}, 50.0f,
                         static_cast<float>(kWidth) / kHeight, 0.5f, 40.0f);
}

Material lit_material(ShadingModel model) {
  Material m;
  m.shading = model;
  m.base_color = {0.8f, 0.7f, 0.6f, 1.0f};
  m.cull = CullMode::none;
  return m;
}

// A plane and an occluder under one light.
Scene shadow_scene(ShadingModel model, const Occluder& occluder, const Light& light) {
  Scene scene;
  scene.add_object(plane(kGround, kGround), lit_material(model));
  scene.add_object(box(occluder.high - occluder.low), lit_material(model),
                   glm::translate(glm::mat4(1.0f), (occluder.low + occluder.high) * 0.5f));
  scene.lighting.lights = {light};
  scene.lighting.ambient = glm::vec3(0.1f);
  return scene;
}

Light sun(glm::vec3 travel, float intensity) {
  return Light::directional(travel, glm::vec3(1.0f), intensity);
}

RenderSettings shadow_settings(bool shadows, int cascades = 1) {
  RenderSettings s;
  s.shadows = shadows;
  s.shadow_cascades = cascades;
  s.shadow_map_size = 512;  // texels of about a third of a pixel on the plane: a fair test
  return s;
}

// Whether the segment from `from` along `dir` (t in [0, t_max]) passes through the box
// occluder.
bool hits_occluder(glm::vec3 from, glm::vec3 dir, float t_max, const Occluder& occluder) {
  float t0 = 0.0f, t1 = t_max;
  const glm::vec3 lo = occluder.low, hi = occluder.high;
  for (int axis = 0; axis < 3; ++axis) {
    if (dir[axis] == 0.0f) {
      if (from[axis] < lo[axis] || from[axis] > hi[axis]) return false;
      continue;
    }
    float ta = (lo[axis] - from[axis]) / dir[axis], tb = (hi[axis] - from[axis]) / dir[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

// What geometry says of each pixel: kNotPlane where its centre's ray misses the plane or meets
// the occluder first, else whether the plane point it sees is lit or in the occluder's shadow
// (the ray from it toward the light meets the occluder). Also the plane points.
constexpr int kNotPlane = -1, kLit = 0, kShadow = 1;
struct Expected {
  std::vector<int> kind;
  std::vector<glm::vec3> on_plane;
};
Expected expected_shadow(const Camera& camera, const Light& light, const Occluder& occluder) {
  Expected e{std::vector<int>(kWidth * kHeight, kNotPlane),
             std::vector<glm::vec3>(kWidth * kHeight)};
  const glm::mat4 inverse = glm::inverse(camera.view_projection());
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float nx = (x + 0.5f) / kWidth * 2.0f - 1.0f, ny = 1.0f - (y + 0.5f) / kHeight * 2.0f;
      const glm::vec4 a = inverse * glm::vec4(nx, ny, -1.0f, 1.0f);
      const glm::vec4 b = inverse * glm::vec4(nx, ny, 1.0f, 1.0f);
      const glm::vec3 from = glm::vec3(a) / a.w, dir = glm::vec3(b) / b.w - from;
      if (!(dir.y < 0.0f)) continue;
      const glm::vec3 p = from + dir * (-from.y / dir.y);
      if (std::abs(p.x) >= kGround / 2 || std::abs(p.z) >= kGround / 2) continue;
      if (hits_occluder(from, dir, 1.0f, occluder)) continue;
      e.on_plane[y * kWidth + x] = p;
      // Toward the light: to the spot's position, or 100 along the sun's reverse direction.
      const bool spot = light.type == LightType::spot;
      const glm::vec3 to_light = spot ? light.position - p : -glm::normalize(light.direction);
      const bool shadowed = hits_occluder(p, to_light, spot ? 1.0f : 100.0f, occluder);
      e.kind[y * kWidth + x] = shadowed ? kShadow : kLit;
    }
  }
  return e;
}

glm::vec4 pixel(const Framebuffer& fb, int x, int y) { return fb.pixel(x, y); }
bool same_pixel(const Framebuffer& a, const Framebuffer& b, int x, int y) {
  return std::memcmp(&a.rgba8()[4 * (y * kWidth + x)], &b.rgba8()[4 * (y * kWidth + x)], 4) == 0;
}

// Every plane pixel more than two pixels (in the image) from the shadow's outline and from the
// occluder is exactly as it would be with the sun (lit: no acne) or without it (in the shadow).
// Returns how many of each were judged.
struct Judged {
  int lit = 0, shadow = 0;
};
Judged expect_outline(const Framebuffer& shadowed, const Framebuffer& lit, const Framebuffer& dark,
                      const Expected& expected) {
  constexpr int kReach = 2;
  Judged judged;
  for (int y = kReach; y < kHeight - kReach; ++y) {
    for (int x = kReach; x < kWidth - kReach; ++x) {
      const int want = expected.kind[y * kWidth + x];
      if (want == kNotPlane) continue;
      bool clear = true;
      for (int dy = -kReach; dy <= kReach; ++dy) {
        for (int dx = -kReach; dx <= kReach; ++dx) {
          clear = clear && expected.kind[(y + dy) * kWidth + x + dx] == want;
        }
      }
      if (!clear) continue;
      const Framebuffer& reference = want == kShadow ? dark : lit;
      EXPECT_TRUE(same_pixel(shadowed, reference, x, y))
          << "pixel (" << x << ", " << y << ") should be "
          << (want == kShadow ? "in shadow" : "lit") << ": got " << pixel(shadowed, x, y).r
          << ", lit " << pixel(lit, x, y).r << ", dark " << pixel(dark, x, y).r;
      if (testing::Test::HasFailure()) return judged;
      ++(want == kShadow ? judged.shadow : judged.lit);
    }
  }
  return judged;
}

class SquareShadow : public testing::TestWithParam<ShadingModel> {};

// Straight down, the square's shadow is the square [-1, 1]^2 on the plane.
TEST_P(SquareShadow, OutlineIsTheSquareAndTheLitPlaneHasNoAcne) {
  const glm::vec3 down(0.0f, -1.0f, 0.0f);
  const Camera camera = view_camera();
  const Framebuffer lit = render_scene_image(shadow_scene(GetParam(), kSquare, sun(down, 1.0f)),
                                             camera, kWidth, kHeight, shadow_settings(false));
  const Framebuffer dark = render_scene_image(shadow_scene(GetParam(), kSquare, sun(down, 0.0f)),
                                              camera, kWidth, kHeight, shadow_settings(false));
  // One map, and a cascade of three over the view's depths (the square in the second).
  for (int cascades : {1, 3}) {
    SCOPED_TRACE(std::to_string(cascades) + " cascades");
    const Framebuffer shadowed =
        render_scene_image(shadow_scene(GetParam(), kSquare, sun(down, 1.0f)), camera, kWidth,
                           kHeight, shadow_settings(true, cascades));
    const Judged judged =
        expect_outline(shadowed, lit, dark, expected_shadow(camera, sun(down, 1.0f), kSquare));
    EXPECT_GT(judged.shadow, 250);  // the shadow shows, not all behind the occluder
    EXPECT_GT(judged.lit, 3000);
  }
}

INSTANTIATE_TEST_SUITE_P(LitModels, SquareShadow,
                         testing::Values(ShadingModel::lambert, ShadingModel::phong,
                                         ShadingModel::blinn_phong, ShadingModel::pbr),
                         [](const testing::TestParamInfo<ShadingModel>& p) {
                           switch (p.param) {
                             case ShadingModel::lambert:
                               return std::string("lambert");
                             case ShadingModel::phong:
                               return std::string("phong");
                             case ShadingModel::blinn_phong:
                               return std::string("blinn_phong");
                             default:
                               return std::string("pbr");
                           }
                         });

// A spot light above the square, off its centre: the shadow is the square projected from the
// light's position (larger than the square, and shifted), within two pixels, with no acne.
TEST_P(SquareShadow, SpotLightCastsThePerspectiveOutline) {
  const glm::vec3 at(0.4f, 4.0f, 0.3f), down(0.0f, -1.0f, 0.0f);
  const auto spot = [&](float intensity) {
    return Light::spot(at, down, 50.0f, 65.0f, glm::vec3(1.0f), intensity);
  };
  const Camera camera = view_camera();
  const Framebuffer shadowed = render_scene_image(shadow_scene(GetParam(), kSquare, spot(16.0f)),
                                                  camera, kWidth, kHeight, shadow_settings(true));
  const Framebuffer lit = render_scene_image(shadow_scene(GetParam(), kSquare, spot(16.0f)), camera,
                                             kWidth, kHeight, shadow_settings(false));
  const Framebuffer dark = render_scene_image(shadow_scene(GetParam(), kSquare, spot(0.0f)), camera,
                                              kWidth, kHeight, shadow_settings(false));
  const Judged judged =
      expect_outline(shadowed, lit, dark, expected_shadow(camera, spot(1.0f), kSquare));
  EXPECT_GT(judged.shadow, 500);
  EXPECT_GT(judged.lit, 3000);
}

// A thin box (a wall) on the plane under an oblique sun: the outline where geometry puts it and
// no acne on the plane, which the sun lights at 45 degrees (a map texel spans a range of its
// depths); and the plane right at the wall's foot on the shadow side (within 0.2 of it: a
// tenth of its height) is dark, as dark as without the sun but for a sliver of filter: no
// light leaks under it.
TEST(Shadows, ObliqueSunNoAcneAndNoLightLeaksWhereABoxStands) {
  const glm::vec3 travel(1.0f, -1.0f, 0.2f);
  const Camera camera = Camera::look_at({6.0f, 5.0f, 2.0f}, {0.5f, 0.0f, 0.0f}, {0, 1, 0}, 50.0f,
                                        static_cast<float>(kWidth) / kHeight, 0.5f, 40.0f);
  const Scene scene = shadow_scene(ShadingModel::lambert, kWall, sun(travel, 1.0f));
  const Framebuffer shadowed =
      render_scene_image(scene, camera, kWidth, kHeight, shadow_settings(true));
  const Framebuffer lit =
      render_scene_image(scene, camera, kWidth, kHeight, shadow_settings(false));
  const Framebuffer dark =
      render_scene_image(shadow_scene(ShadingModel::lambert, kWall, sun(travel, 0.0f)), camera,
                         kWidth, kHeight, shadow_settings(false));
  const Expected expected = expected_shadow(camera, sun(travel, 1.0f), kWall);
  const Judged judged = expect_outline(shadowed, lit, dark, expected);
  EXPECT_GT(judged.shadow, 500);
  EXPECT_GT(judged.lit, 3000);
  int foot_pixels = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (expected.kind[y * kWidth + x] == kNotPlane) continue;
      const glm::vec3 p = expected.on_plane[y * kWidth + x];
      const bool at_foot = p.x > kWall.high.x && p.x < kWall.high.x + 0.2f && std::abs(p.z) < 0.6f;
      if (!at_foot) continue;
      const float got = pixel(shadowed, x, y).g, with_sun = pixel(lit, x, y).g,
                  without = pixel(dark, x, y).g;
      ASSERT_GT(with_sun, without + 0.1f);
      EXPECT_LE(got, without + 0.1f * (with_sun - without))
          << "light leaks at (" << x << ", " << y << "), plane point " << p.x << ", " << p.z;
      ++foot_pixels;
    }
  }
  EXPECT_GT(foot_pixels, 20);
}

// A light that does not cast shadows, an occluder whose material casts none, or shadows off for
// the frame: the image without them.
TEST(Shadows, ALightOrMaterialThatDoesNotCastLeavesTheImageAsWithout) {
  const glm::vec3 down(0.0f, -1.0f, 0.0f);
  Scene scene = shadow_scene(ShadingModel::blinn_phong, kSquare, sun(down, 1.0f));
  const Framebuffer without =
      render_scene_image(scene, view_camera(), kWidth, kHeight, shadow_settings(false));
  scene.lighting.lights[0].casts_shadows = false;
  const Framebuffer not_casting =
      render_scene_image(scene, view_camera(), kWidth, kHeight, shadow_settings(true));
  EXPECT_TRUE(without.rgba8() == not_casting.rgba8());
  scene.lighting.lights[0].casts_shadows = true;
  const Framebuffer casting =
      render_scene_image(scene, view_camera(), kWidth, kHeight, shadow_settings(true));
  EXPECT_FALSE(without.rgba8() == casting.rgba8());
  ASSERT_EQ(scene.materials.size(), 2u);  // the plane's, the occluder's
  scene.materials[1].casts_shadows = false;
  const Framebuffer material_not_casting =
      render_scene_image(scene, view_camera(), kWidth, kHeight, shadow_settings(true));
  EXPECT_TRUE(without.rgba8() == material_not_casting.rgba8());
}

// Shadows of a sun and a spot over a few shapes of every lit model are the same bytes for any
// thread count, tile size and SIMD target.
TEST(Shadows, SameImageForAnyThreadsTilesAndSimdTarget) {
  Scene scene = shadow_scene(ShadingModel::lambert, kWall, sun({0.6f, -1.0f, 0.3f}, 1.0f));
  scene.add_object(uv_sphere(0.7f), lit_material(ShadingModel::pbr),
                   glm::translate(glm::mat4(1.0f), {-2.0f, 0.7f, 1.0f}));
  scene.add_object(cone(0.6f, 1.5f), lit_material(ShadingModel::gouraud),
                   glm::translate(glm::mat4(1.0f), {1.5f, 0.0f, -2.0f}));
  scene.add_object(uv_sphere(0.5f), lit_material(ShadingModel::blinn_phong),
                   glm::translate(glm::mat4(1.0f), {-0.5f, 2.7f, -0.5f}));
  scene.lighting.lights.push_back(
      Light::spot({-1.0f, 5.0f, 2.0f}, {0.3f, -1.0f, -0.4f}, 30.0f, 45.0f, glm::vec3(1.0f), 20.0f));
  const Camera camera = view_camera();
  RenderSettings base = shadow_settings(true);
  base.threads = 1;
  base.tile_size = 64;
  const Framebuffer expected = render_scene_image(scene, camera, kWidth, kHeight, base);
  const Framebuffer unshadowed =
      render_scene_image(scene, camera, kWidth, kHeight, shadow_settings(false));
  ASSERT_FALSE(expected.rgba8() == unshadowed.rgba8());
  for (int msaa : {1, 4}) {
    RenderSettings first = base;
    first.msaa = msaa;
    first.shadow_cascades = msaa == 4 ? 3 : 1;
    const Framebuffer reference = render_scene_image(scene, camera, kWidth, kHeight, first);
    for (int threads : {2, 3, 7}) {
      for (int tile : {16, 32, 128}) {
        RenderSettings s = first;
        s.threads = threads;
        s.tile_size = tile;
        const Framebuffer fb = render_scene_image(scene, camera, kWidth, kHeight, s);
        EXPECT_TRUE(fb.rgba8() == reference.rgba8())
            << threads << " threads, tiles of " << tile << ", msaa " << msaa << ", cascades "
            << first.shadow_cascades;
      }
    }
  }
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const Framebuffer fb = render_scene_image(scene, camera, kWidth, kHeight, base);
    EXPECT_TRUE(fb.rgba8() == expected.rgba8()) << hwy::TargetName(target);
  }
}

// The map size and the cascades are checked where the settings are: a size of 0 or 100000, or
// -1 or 5 cascades, is refused with a message that names the setting and its range; 0 cascades
// is kAutoShadowCascades.
TEST(Shadows, ShadowMapSizeOutOfRangeIsAClearError) {
  for (int size : {0, -5, 15, 8193, 100000}) {
    RenderSettings s;
    s.shadow_map_size = size;
    try {
      Renderer renderer(s);
      ADD_FAILURE() << "shadow map size " << size << " accepted";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("shadow map size"), std::string::npos) << message;
      EXPECT_NE(message.find(std::to_string(size)), std::string::npos) << message;
    }
  }
  for (int cascades : {-1, 5, 100}) {
    RenderSettings s;
    s.shadow_cascades = cascades;
    try {
      Renderer renderer(s);
      ADD_FAILURE() << cascades << " shadow cascades accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("shadow cascades"), std::string::npos) << e.what();
    }
  }
  RenderSettings fine;
  fine.shadow_cascades = RenderSettings::kAutoShadowCascades;
  EXPECT_NO_THROW(Renderer{fine});
  fine.shadow_cascades = RenderSettings::kMaxShadowCascades;
  EXPECT_NO_THROW(Renderer{fine});
  fine.shadow_map_size = 16;
  EXPECT_NO_THROW(Renderer{fine});
  fine.shadow_map_size = 8192;
  EXPECT_NO_THROW(Renderer{fine});
}

}  // namespace
}  // namespace facet::test
