// Texture maps an imported material gets from kinds the shaders do not read themselves
// (src/import/derived_maps.cpp): an MTL height map (map_Bump) becomes a tangent-space normal map
// that lights the surface as its slopes say, a real normal map goes through as it is, and
// separate grey roughness, metalness and gloss maps (map_Pr, map_Pm, map_Ns) become the packed
// metallic-roughness map of a PBR material. Every texture is generated here, as a PGM.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "facet/texture.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

// A 2 x 2 quad in the z = 0 plane facing +z, u along +x and v along +y.
const char* const kQuadObj =
    "mtllib quad.mtl\n"
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\n"
    "usemtl surface\n"
    "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";

// A binary grey PGM (P5) of width x height, value(x, y) per texel, rows top first.
void write_pgm(const fs::path& path, int width, int height,
               const std::function<std::uint8_t(int, int)>& value) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << width << " " << height << "\n255\n";
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) out.put(static_cast<char>(value(x, y)));
  }
}

Scene import_quad(const fs::path& dir, const std::string& mtl) {
  std::ofstream(dir / "quad.obj") << kQuadObj;
  std::ofstream(dir / "quad.mtl") << "newmtl surface\nKd 0.8 0.8 0.8\n" << mtl;
  ImportOptions options;
  options.warn = [](const std::string& message) { ADD_FAILURE() << message; };
  return import_scene((dir / "quad.obj").string(), options);
}

// The quad's material (assimp puts a default material before the file's).
const Material& surface(const Scene& scene) {
  for (const Material& m : scene.materials) {
    if (m.name == "surface") return m;
  }
  ADD_FAILURE() << "no material named surface";
  return scene.materials.at(0);
}

// The quad seen head-on, lit by one directional light travelling along `direction`, no ambient:
// the mean red of the image's central quarter (where the quad is, away from the texture's
// edges).
float centre_brightness(const Scene& scene, glm::vec3 direction) {
  Renderer renderer;
  Framebuffer frame(64, 64, ColorFormat::rgba32f);
  Lighting lighting;
  lighting.ambient = glm::vec3(0.0f);
  lighting.lights = {Light::directional(direction)};
  renderer.begin_frame(Camera::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, 1.0f, 0.1f, 10.0f),
                       lighting);
  draw_scene(renderer, scene);
  renderer.finish(frame);
  double sum = 0;
  int count = 0;
  for (int y = 24; y < 40; ++y) {
    for (int x = 24; x < 40; ++x, ++count) sum += frame.rgba32f()[(y * 64 + x) * 4];
  }
  return static_cast<float>(sum / count);
}

// The heights rise along u (a ramp, -bm 3 to make it steep), so the derived normals lean
// towards -u: a light from the -x side lights the quad more than one from +x, and the normal map
// holds normalize(-slope, 0, 1) with slope = 13 texels deep (kBumpDepthTexels) x 3 x half the
// height step between a texel's neighbours.
TEST(ImportMaterialMaps, HeightMapBecomesANormalMapThatLightsItsSlopes) {
  fs::path dir = fresh_test_dir("facet_material_maps_", "height");
  constexpr int kSize = 64;
  write_pgm(dir / "heights.pgm", kSize, kSize,
            [](int x, int) { return static_cast<std::uint8_t>(x * 4); });  // 0 ... 252
  const Scene bumped = import_quad(dir, "map_Bump -bm 3 heights.pgm\n");
  const TextureMap& normal_map = surface(bumped).normal_map;
  ASSERT_TRUE(normal_map) << "the height map was dropped";
  const float slope = 13.0f * 3.0f * 0.5f * (8.0f / 255.0f);
  const glm::vec3 expected = glm::normalize(glm::vec3(-slope, 0.0f, 1.0f));
  const glm::vec4 texel = normal_map.texture->texel(0, kSize / 2, kSize / 2);
  const glm::vec3 decoded = glm::vec3(texel) * 2.0f - 1.0f;
  EXPECT_NEAR(decoded.x, expected.x, 1.5f / 255.0f);
  EXPECT_NEAR(decoded.y, 0.0f, 1.5f / 255.0f);
  EXPECT_NEAR(decoded.z, expected.z, 1.5f / 255.0f);

  const float from_left = centre_brightness(bumped, {1.0f, 0.0f, -1.0f});
  const float from_right = centre_brightness(bumped, {-1.0f, 0.0f, -1.0f});
  // Diffuse light (the bumped material is Blinn-Phong without a highlight): n . l for the
  // leaning normal against the two lights, 45 degrees either side.
  const glm::vec3 to_left = glm::normalize(glm::vec3(-1.0f, 0.0f, 1.0f));
  const glm::vec3 to_right = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
  EXPECT_GT(from_left, from_right * 1.5f);
  const float ratio = glm::dot(expected, to_left) / glm::dot(expected, to_right);
  EXPECT_NEAR(from_left / from_right, ratio, ratio * 0.03f);

  fs::path flat_dir = fresh_test_dir("facet_material_maps_", "flat");
  const Scene flat = import_quad(flat_dir, "");
  EXPECT_NEAR(centre_brightness(flat, {1.0f, 0.0f, -1.0f}),
              centre_brightness(flat, {-1.0f, 0.0f, -1.0f}), 1e-4f);
}

// glmark2's tangent-space asteroid normal map, half of it white padding, is a normal map: used
// as it is, not taken for heights.
TEST(ImportMaterialMaps, RealNormalMapGoesThroughUnchanged) {
  const fs::path asteroid = "/usr/share/glmark2/textures/asteroid-normal-map-tangent.png";
  FACET_REQUIRE_PACKAGE(fs::exists(asteroid), asteroid << " is missing (glmark2-data)");
  fs::path dir = fresh_test_dir("facet_material_maps_", "normal_map");
  fs::copy_file(asteroid, dir / "asteroid.png");
  const Scene scene = import_quad(dir, "map_Bump asteroid.png\n");
  const TextureMap& normal_map = surface(scene).normal_map;
  ASSERT_TRUE(normal_map);
  const auto original = load_texture((dir / "asteroid.png").string(), /*srgb=*/false);
  ASSERT_EQ(normal_map.texture->width(), original->width());
  EXPECT_EQ(normal_map.texture->level(0).rgba8, original->level(0).rgba8);
}

// map_Pr (4 x 4) and map_Pm (2 x 2, sampled nearest at the larger size) packed as glTF packs
// them: roughness in G, metalness in B; the material turns PBR with factors of 1.
TEST(ImportMaterialMaps, SeparateRoughnessAndMetalnessMapsArePacked) {
  fs::path dir = fresh_test_dir("facet_material_maps_", "rough_metal");
  write_pgm(dir / "rough.pgm", 4, 4,
            [](int x, int y) { return static_cast<std::uint8_t>(16 * (y * 4 + x)); });
  write_pgm(dir / "metal.pgm", 2, 2, [](int x, int y) { return x == y ? 255 : 0; });
  const Scene scene =
      import_quad(dir, "Ks 0.5 0.5 0.5\nNs 40\nmap_Pr rough.pgm\nmap_Pm metal.pgm\n");
  const Material& m = surface(scene);
  EXPECT_EQ(m.shading, ShadingModel::pbr);
  EXPECT_EQ(m.roughness, 1.0f);
  EXPECT_EQ(m.metallic, 1.0f);
  ASSERT_TRUE(m.metallic_roughness_map);
  const Texture& packed = *m.metallic_roughness_map.texture;
  ASSERT_EQ(packed.width(), 4);
  ASSERT_EQ(packed.height(), 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const glm::vec4 t = packed.texel(0, x, y);
      EXPECT_NEAR(t.g, 16.0f * (y * 4 + x) / 255.0f, 1e-6f) << x << "," << y;
      EXPECT_EQ(t.b, x / 2 == y / 2 ? 1.0f : 0.0f) << x << "," << y;
    }
  }
}

// map_Ns scales Ns; the exponent becomes roughness (2 / (n + 2))^(1/4): white at Ns 100 gives
// 0.374, black (exponent 0) 1. Metalness stays the file's (none: 0).
TEST(ImportMaterialMaps, GlossMapBecomesRoughness) {
  fs::path dir = fresh_test_dir("facet_material_maps_", "gloss");
  write_pgm(dir / "gloss.pgm", 2, 1, [](int x, int) { return x == 0 ? 255 : 0; });
  const Scene scene = import_quad(dir, "Ks 0.5 0.5 0.5\nNs 100\nmap_Ns gloss.pgm\n");
  const Material& m = surface(scene);
  EXPECT_EQ(m.shading, ShadingModel::pbr);
  EXPECT_EQ(m.metallic, 0.0f);
  ASSERT_TRUE(m.metallic_roughness_map);
  const Texture& packed = *m.metallic_roughness_map.texture;
  EXPECT_NEAR(packed.texel(0, 0, 0).g, std::pow(2.0f / 102.0f, 0.25f), 0.5f / 255.0f);
  EXPECT_EQ(packed.texel(0, 1, 0).g, 1.0f);
}

}  // namespace
}  // namespace facet::test
