// Golden images of the content features through the library API: lit models (Phong, PBR),
// normal mapping, environment reflections and sky, fog, transparency, imported files.
// Goldens are tests/golden/content_<name>.png; FACET_UPDATE_GOLDENS=1 rewrites them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/image_io.hpp"
#include "facet/import.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/teapot.hpp"
#include "facet/texture.hpp"
#include "facet/worlds.hpp"
#include "support/golden.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 320;
constexpr int kHeight = 180;

void expect_golden(const Scene& scene, const std::string& name,
                   glm::vec4 clear = {0.05f, 0.05f, 0.06f, 1.0f}) {
  RenderSettings settings;
  settings.clear_color = clear;
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight);
  Camera camera = scene.camera;
  camera.aspect = static_cast<float>(kWidth) / kHeight;
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(fb);
  std::string path = (fs::path(::testing::TempDir()) / ("content_" + name + ".png")).string();
  write_image(fb, path);
  expect_matches_golden(path, "content_" + name);
}

Scene teapot_with(ShadingModel model) {
  Scene scene = make_teapot_scene();
  for (auto& m : scene.materials) m.shading = model;
  return scene;
}

TEST(ContentGolden, PhongTeapot) {
  expect_golden(teapot_with(ShadingModel::phong), "teapot_phong");
}

TEST(ContentGolden, GouraudTeapot) {
  expect_golden(teapot_with(ShadingModel::gouraud), "teapot_gouraud");
}

TEST(ContentGolden, PbrGoldTeapotInTheSky) {
  Scene scene = teapot_with(ShadingModel::pbr);
  for (auto& m : scene.materials) {
    m.base_color = {1.0f, 0.78f, 0.34f, 1.0f};
    m.metallic = 1.0f;
    m.roughness = 0.3f;
  }
  scene.lighting.environment.reflections = true;
  scene.lighting.environment.show_as_background = true;
  expect_golden(scene, "teapot_pbr");
}

// A tangent-space normal map of round bumps, generated: the normal of a hemisphere per cell.
std::shared_ptr<const Texture> bump_normal_map() {
  const int size = 128, cells = 4;
  std::vector<std::uint8_t> rgba(size * size * 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      float cx = (x % (size / cells) + 0.5f) / (size / cells) * 2.0f - 1.0f;
      float cy = -((y % (size / cells) + 0.5f) / (size / cells) * 2.0f - 1.0f);
      float r2 = cx * cx + cy * cy;
      glm::vec3 n =
          r2 < 0.8f ? glm::normalize(glm::vec3(cx, cy, std::sqrt(1.0f - r2))) : glm::vec3(0, 0, 1);
      std::uint8_t* p = &rgba[(y * size + x) * 4];
      for (int c = 0; c < 3; ++c)
        p[c] = static_cast<std::uint8_t>((n[c] * 0.5f + 0.5f) * 255.0f + 0.5f);
      p[3] = 255;
    }
  }
  return Texture::from_rgba8(size, size, rgba, false, "bumps");
}

TEST(ContentGolden, NormalMappedSurface) {
  Scene scene;
  Material material;
  material.shading = ShadingModel::blinn_phong;
  material.base_color = {0.7f, 0.7f, 0.75f, 1.0f};
  material.specular_color = glm::vec3(0.4f);
  material.shininess = 40.0f;
  material.normal_map.texture = bump_normal_map();
  scene.add_object(rectangle(4.0f, 4.0f), material);
  scene.lighting.lights = {Light::directional({1.0f, -0.6f, -0.8f})};
  scene.lighting.ambient = glm::vec3(0.08f);
  scene.camera = Camera::look_at({0, 0, 3.2f}, {0, 0, 0});
  expect_golden(scene, "normal_map");
}

// An equirectangular test environment: latitude bands, longitude hue, so reflections are
// recognisable.
std::shared_ptr<const Texture> test_environment() {
  const int w = 256, h = 128;
  std::vector<std::uint8_t> rgba(w * h * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &rgba[(y * w + x) * 4];
      bool band = (y / 16) % 2 == 0, stripe = (x / 32) % 2 == 0;
      p[0] = static_cast<std::uint8_t>(y < h / 2 ? 90 + x * 160 / w : 60);
      p[1] = static_cast<std::uint8_t>(band ? 170 : 90);
      p[2] = static_cast<std::uint8_t>(stripe ? 220 : 120);
      p[3] = 255;
    }
  }
  return Texture::from_rgba8(w, h, rgba, true, "test environment");
}

TEST(ContentGolden, EnvironmentMappedSphere) {
  Scene scene;
  Material chrome;
  chrome.shading = ShadingModel::phong;
  chrome.base_color = glm::vec4(0.1f, 0.1f, 0.1f, 1.0f);
  chrome.reflectivity = 0.9f;
  scene.add_object(uv_sphere(1.0f, 64, 32), chrome);
  scene.lighting.environment.image = test_environment();
  scene.lighting.environment.reflections = true;
  scene.lighting.environment.show_as_background = true;
  scene.camera = Camera::look_at({0.5f, 0.6f, 3.5f}, {0, 0, 0});
  expect_golden(scene, "environment_sphere");
}

TEST(ContentGolden, LinearAndExponentialFog) {
  Scene scene = make_shapes_scene();
  scene.lighting.fog.mode = FogMode::linear;
  scene.lighting.fog.start = 4.0f;
  scene.lighting.fog.end = 25.0f;
  scene.lighting.fog.color = {0.5f, 0.55f, 0.6f};
  expect_golden(scene, "fog_linear", glm::vec4(scene.lighting.fog.color, 1.0f));
  scene.lighting.fog.mode = FogMode::exponential;
  scene.lighting.fog.density = 0.12f;
  expect_golden(scene, "fog_exponential", glm::vec4(scene.lighting.fog.color, 1.0f));
}

TEST(ContentGolden, AlphaBlendedMaskedAndAdditive) {
  Scene scene;
  Material ground;
  ground.base_color = {0.5f, 0.5f, 0.5f, 1.0f};
  scene.add_object(plane(8, 8, 4, 4), ground, glm::translate(glm::mat4(1), {0, -1, 0}));
  // Blended glass panes, submitted front to back on purpose: sorting must fix the order.
  const glm::vec4 colors[] = {{1, 0.2f, 0.2f, 0.5f}, {0.2f, 1, 0.2f, 0.5f}, {0.2f, 0.3f, 1, 0.5f}};
  for (int i = 0; i < 3; ++i) {
    Material glass;
    glass.shading = ShadingModel::unlit;
    glass.base_color = colors[i];
    glass.alpha_mode = AlphaMode::blend;
    glass.cull = CullMode::none;
    scene.add_object(rectangle(1.6f, 1.6f), glass,
                     glm::translate(glm::mat4(1), {-0.9f + 0.6f * i, 0.3f * i, 1.0f - i}));
  }
  // A cut-out: the missing-texture checker's black cells have alpha 1, so use a generated
  // alpha checker instead.
  std::vector<std::uint8_t> rgba(16 * 16 * 4);
  for (int i = 0; i < 16 * 16; ++i) {
    bool hole = ((i % 16) / 4 + (i / 16) / 4) % 2 == 0;
    rgba[i * 4] = 230, rgba[i * 4 + 1] = 200, rgba[i * 4 + 2] = 60,
             rgba[i * 4 + 3] = hole ? 0 : 255;
  }
  Material fence;
  fence.shading = ShadingModel::lambert;
  fence.alpha_mode = AlphaMode::mask;
  fence.cull = CullMode::none;
  fence.base_color_map.texture = Texture::from_rgba8(16, 16, rgba, true, "fence");
  fence.base_color_map.sampler.filter = Filter::nearest;
  scene.add_object(rectangle(2.0f, 2.0f), fence, glm::translate(glm::mat4(1), {2.0f, 0.0f, -0.5f}));
  Material glow;
  glow.shading = ShadingModel::unlit;
  glow.base_color = {1.0f, 0.5f, 0.1f, 0.8f};
  glow.alpha_mode = AlphaMode::additive;
  scene.add_object(uv_sphere(0.5f, 24, 12), glow,
                   glm::translate(glm::mat4(1), {-2.2f, 0.2f, 0.0f}));
  scene.camera = Camera::look_at({0, 1.0f, 5.0f}, {0, 0, 0});
  expect_golden(scene, "transparency");
}

TEST(ContentGolden, TexturedBoxFromGlb) {
  const std::string path = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  FACET_REQUIRE_PACKAGE(fs::exists(path), path << " missing (Debian package assimp-testmodels)");
  Scene scene = import_scene(path);  // lit by import's three-point lights: the file has none
  expect_golden(scene, "box_textured");
}

TEST(ContentGolden, CourseFormatModel) {
  // A small .d model written at test time: an octahedron with one quad-split face pair.
  const std::string path = (fs::path(::testing::TempDir()) / "octahedron.d").string();
  std::ofstream(path) << "data 6 8\n# an octahedron\n"
                         "1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n\n"
                         "3 1 3 5\n3 5 3 2\n3 2 3 6\n3 6 3 1\n"
                         "3 5 4 1\n3 2 4 5\n3 6 4 2\n3 1 4 6\n";
  Scene scene = import_scene(path);  // lit by import's three-point lights
  expect_golden(scene, "course_d");
}

}  // namespace
}  // namespace facet::test
