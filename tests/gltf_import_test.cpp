// The glTF 2.0 reader (src/import/gltf_*.cpp) on models the tests write (support/gltf_builder.hpp):
// what the assimp reader drew before it (meshes, node transforms, materials with their maps and
// samplers, vertex colors, cameras, lights, external files), files that draw nothing or require
// an unsupported extension, and damaged files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "support/gltf_builder.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"
#include "support/text.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// --- parity with what the assimp reader drew ---------------------------------------------

TEST(GltfImport, GltfAndGlbOfOneModelGiveTheSameMesh) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  // A second, non-indexed triangle.
  b.add_mesh_node({{"attributes", {{"POSITION", b.positions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}})}}}});
  const fs::path dir = gltf_test_dir("gltf_and_glb");
  for (const fs::path& file : {b.write_gltf(dir / "quad.gltf"), b.write_glb(dir / "quad.glb")}) {
    SCOPED_TRACE(file.string());
    const ImportedGltf got = import_gltf(file);
    EXPECT_TRUE(got.warnings.empty());
    EXPECT_EQ(got.scene.triangle_count(), 3u);
    const Mesh& quad = mesh_of(got.scene);
    ASSERT_EQ(quad.texcoords.size(), quad.positions.size());
    for (std::size_t i = 0; i < quad.positions.size(); ++i) {
      // glTF's v = 1 - facet's: the quad's corner (0, 0) has glTF uv (0, 1), facet's (0, 0).
      EXPECT_NEAR(quad.texcoords[i].x, quad.positions[i].x, 1e-6f);
      EXPECT_NEAR(quad.texcoords[i].y, quad.positions[i].y, 1e-6f);
    }
    EXPECT_GT(render_small(got.scene).triangles_in, 0u);
  }
}

TEST(GltfImport, NodeHierarchyComposesTranslationRotationScale) {
  GltfBuilder b;
  const int child = b.add_mesh_node(unit_quad(b), {{"translation", {1, 0, 0}},
                                                   {"rotation", {0, 0, 0.70710678, 0.70710678}},
                                                   {"scale", {2, 2, 2}}});
  b.json["scenes"][0]["nodes"] = {1};
  b.json["nodes"].push_back({{"children", {child}}, {"translation", {0, 5, 0}}, {"name", "root"}});
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("hierarchy") / "h.gltf"));
  ASSERT_EQ(got.scene.nodes.size(), 2u);
  EXPECT_EQ(got.scene.nodes[0].name, "root");
  EXPECT_EQ(got.scene.nodes[1].parent, 0);
  const glm::mat4 world = got.scene.world_transform(1);
  // x -> 2y (90 degrees about z, scale 2), then (1, 5, 0) added.
  const glm::vec3 p = glm::vec3(world * glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(p.x, 1.0f, 1e-5f);
  EXPECT_NEAR(p.y, 7.0f, 1e-5f);
  EXPECT_NEAR(p.z, 0.0f, 1e-5f);
}

TEST(GltfImport, MaterialHasEveryMapFactorSamplerAndAlphaMode) {
  GltfBuilder b;
  const int texture = add_embedded_image(b);
  b.json["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}}};
  b.json["textures"][texture]["sampler"] = 0;
  b.json["materials"] = {{{"name", "all"},
                          {"pbrMetallicRoughness",
                           {{"baseColorFactor", {0.5, 0.25, 1, 0.75}},
                            {"baseColorTexture", {{"index", texture}}},
                            {"metallicFactor", 0.3},
                            {"roughnessFactor", 0.7},
                            {"metallicRoughnessTexture", {{"index", texture}}}}},
                          {"normalTexture", {{"index", texture}, {"scale", 0.5}}},
                          {"occlusionTexture", {{"index", texture}, {"strength", 0.25}}},
                          {"emissiveTexture", {{"index", texture}}},
                          {"emissiveFactor", {1, 0.5, 0}},
                          {"alphaMode", "MASK"},
                          {"alphaCutoff", 0.3},
                          {"doubleSided", true}},
                         {{"name", "glass"}, {"alphaMode", "BLEND"}}};
  json quad = unit_quad(b);
  quad["material"] = 0;
  b.add_mesh_node(quad);
  quad["material"] = 1;
  b.add_mesh_node(quad);
  const ImportedGltf got = import_gltf(b.write_glb(gltf_test_dir("material") / "m.glb"));
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  const Material& m = material_of(got.scene, 0);
  EXPECT_EQ(m.name, "all");
  EXPECT_EQ(m.shading, ShadingModel::pbr);
  EXPECT_EQ(m.base_color, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
  EXPECT_FLOAT_EQ(m.metallic, 0.3f);
  EXPECT_FLOAT_EQ(m.roughness, 0.7f);
  EXPECT_FLOAT_EQ(m.normal_scale, 0.5f);
  EXPECT_FLOAT_EQ(m.occlusion_strength, 0.25f);
  EXPECT_EQ(m.emissive, glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_EQ(m.alpha_mode, AlphaMode::mask);
  EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.3f);
  EXPECT_EQ(m.cull, CullMode::none);
  for (const TextureMap* map : {&m.base_color_map, &m.metallic_roughness_map, &m.normal_map,
                                &m.occlusion_map, &m.emissive_map}) {
    ASSERT_TRUE(*map);
    EXPECT_NE(map->texture, missing_texture());
    EXPECT_EQ(map->texture->level(0).width, 2);
    EXPECT_EQ(map->sampler.wrap_u, Wrap::clamp_to_edge);
    EXPECT_EQ(map->sampler.wrap_v, Wrap::mirrored_repeat);
    EXPECT_EQ(map->sampler.filter, Filter::nearest);
  }
  EXPECT_TRUE(m.base_color_map.texture->srgb());
  EXPECT_TRUE(m.emissive_map.texture->srgb());
  EXPECT_FALSE(m.normal_map.texture->srgb());
  EXPECT_EQ(m.base_color_map.texture->name(), "embedded:0");
  EXPECT_EQ(got.scene.textures.size(), 2u);           // the image as sRGB and as linear data
  EXPECT_FALSE(mesh_of(got.scene).tangents.empty());  // made for the normal map
  EXPECT_EQ(material_of(got.scene, 1).alpha_mode, AlphaMode::blend);
}

TEST(GltfImport, PrimitiveWithoutMaterialGetsTheGltfDefault) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("default") / "d.gltf"));
  const Material& m = material_of(got.scene);
  EXPECT_EQ(m.shading, ShadingModel::pbr);
  EXPECT_EQ(m.base_color, glm::vec4(1.0f));
  EXPECT_FLOAT_EQ(m.metallic, 1.0f);
  EXPECT_FLOAT_EQ(m.roughness, 1.0f);
}

TEST(GltfImport, VertexColorsFromBytesAndFloats) {
  GltfBuilder b;
  json quad = unit_quad(b);
  const std::vector<std::uint8_t> rgba = {255, 0, 0,   255, 0,  255, 0,  128,
                                          0,   0, 255, 0,   51, 51,  51, 255};
  quad["attributes"]["COLOR_0"] =
      b.accessor(b.view(rgba.data(), rgba.size()), kGlUnsignedByte, 4, "VEC4", true);
  b.json["materials"] = {{{"alphaMode", "BLEND"}}};  // keeps the colors' alpha
  quad["material"] = 0;
  b.add_mesh_node(quad);
  json rgb_quad = unit_quad(b);
  rgb_quad["attributes"]["COLOR_0"] =
      b.vec3s({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2f, 0.2f, 0.2f}});
  b.add_mesh_node(rgb_quad, {{"translation", {2, 0, 0}}});
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("colors") / "c.gltf"));
  for (int node : {0, 1}) {
    const Mesh& mesh = *got.scene.meshes.at(got.scene.nodes.at(node).instances.at(0).mesh);
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::vec3 p = mesh.positions[i];
      // Colors are linear as stored (no sRGB decoding): corner (1, 1) is blue, (0, 1) grey.
      if (p == glm::vec3(1, 1, 0)) {
        EXPECT_EQ(glm::vec3(mesh.colors[i]), glm::vec3(0, 0, 1));
      }
      if (p == glm::vec3(0, 1, 0)) {
        EXPECT_NEAR(mesh.colors[i].r, 0.2f, 1e-6f);
      }
      if (p == glm::vec3(1, 0, 0) && node == 0) {
        EXPECT_NEAR(mesh.colors[i].a, 128 / 255.0f, 1e-6f);
      }
      if (node == 1) {
        EXPECT_EQ(mesh.colors[i].a, 1.0f);
      }
    }
  }
}

// alphaMode OPAQUE ignores alpha (glTF 2.0 §3.9.4), and the pipeline writes a draw's alpha into
// the image: an opaque material's base color and vertex colors come in with alpha 1, a blended
// one's as the file has them. (Khronos's BoxVertexColors, made by FBX2glTF, has vertex colors
// of alpha 0 on an opaque material: it came out see-through in a PNG.)
TEST(GltfImport, OpaqueMaterialsIgnoreAlpha) {
  for (const std::string mode : {"OPAQUE", "BLEND"}) {
    GltfBuilder b;
    json quad = unit_quad(b);
    quad["attributes"]["COLOR_0"] =
        b.vec4s({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0.5f}, {1, 1, 1, 0}});
    b.json["materials"] = {
        {{"alphaMode", mode}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.25}}}}}};
    quad["material"] = 0;
    b.add_mesh_node(quad);
    const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("alpha_" + mode) / "a.gltf"));
    const bool opaque = mode == "OPAQUE";
    EXPECT_EQ(material_of(got.scene).base_color.a, opaque ? 1.0f : 0.25f) << mode;
    const Mesh& mesh = mesh_of(got.scene);
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.colors.size(); ++i) {
      const glm::vec3 p = mesh.positions[i];
      const float file_alpha = p == glm::vec3(1, 1, 0) ? 0.5f : 0.0f;  // vertex 2 is (1, 1)
      EXPECT_EQ(mesh.colors[i].a, opaque ? 1.0f : file_alpha) << mode << " vertex " << i;
    }
    EXPECT_EQ(glm::vec3(mesh.colors[0]) + glm::vec3(mesh.colors[1]) + glm::vec3(mesh.colors[2]) +
                  glm::vec3(mesh.colors[3]),
              glm::vec3(2, 2, 2))
        << "the colors themselves are kept";
  }
}

TEST(GltfImport, CamerasAndPunctualLightsArePlacedByTheirNodes) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  b.json["cameras"] = {
      {{"type", "perspective"},
       {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.5}, {"znear", 0.1}}}},
      {{"type", "orthographic"},
       {"orthographic", {{"xmag", 3}, {"ymag", 1.5}, {"znear", 0}, {"zfar", 50}}}}};
  b.json["extensionsUsed"] = {"KHR_lights_punctual"};
  b.json["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"},
       {"color", {1, 0.5, 0.25}},
       {"intensity", 20},
       {"range", 9},
       {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.4}}}},
      {{"type", "directional"}, {"intensity", 3}}};
  // Camera 0 and the spot at (0, 0, 4) looking down -Z; camera 1 and the sun turned to look
  // down -X (90 degrees about +Y).
  const double s = std::sqrt(0.5);
  b.json["nodes"].push_back({{"camera", 0},
                             {"translation", {0, 0, 4}},
                             {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.json["nodes"].push_back({{"camera", 1},
                             {"rotation", {0, s, 0, s}},
                             {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  b.json["scenes"][0]["nodes"] = {0, 1, 2};
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("cameras") / "c.gltf"));
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  ASSERT_EQ(got.scene.cameras.size(), 2u);
  const Camera& perspective = got.scene.cameras[0];
  EXPECT_EQ(perspective.projection_kind, Projection::perspective);
  EXPECT_NEAR(perspective.fov_y_degrees, glm::degrees(0.5f), 1e-4f);
  EXPECT_FLOAT_EQ(perspective.aspect, 1.5f);
  EXPECT_FLOAT_EQ(perspective.near_plane, 0.1f);
  EXPECT_GT(perspective.far_plane, 4.0f);  // zfar absent: infinite, so beyond the model
  EXPECT_NEAR(glm::length(perspective.eye - glm::vec3(0, 0, 4)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(perspective.forward() - glm::vec3(0, 0, -1)), 0.0f, 1e-5f);
  const Camera& ortho = got.scene.cameras[1];
  EXPECT_EQ(ortho.projection_kind, Projection::orthographic);
  EXPECT_FLOAT_EQ(ortho.aspect, 2.0f);
  EXPECT_FLOAT_EQ(ortho.view_height, 3.0f);
  EXPECT_NEAR(glm::length(ortho.forward() - glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);

  ASSERT_TRUE(got.scene.has_file_lights);
  ASSERT_EQ(got.scene.lighting.lights.size(), 2u);
  const Light& spot = got.scene.lighting.lights[0];
  EXPECT_EQ(spot.type, LightType::spot);
  EXPECT_EQ(spot.color, glm::vec3(1, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(spot.intensity, 20.0f);
  EXPECT_FLOAT_EQ(spot.range, 9.0f);
  EXPECT_NEAR(spot.inner_cone_degrees, glm::degrees(0.2f), 1e-4f);
  EXPECT_NEAR(spot.outer_cone_degrees, glm::degrees(0.4f), 1e-4f);
  EXPECT_NEAR(glm::length(spot.position - glm::vec3(0, 0, 4)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(spot.direction - glm::vec3(0, 0, -1)), 0.0f, 1e-5f);
  const Light& sun = got.scene.lighting.lights[1];
  EXPECT_EQ(sun.type, LightType::directional);
  EXPECT_FLOAT_EQ(sun.intensity, 3.0f);
  EXPECT_NEAR(glm::length(sun.direction - glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);
}

TEST(GltfImport, ExternalBufferAndTextureBesideTheModel) {
  GltfBuilder b;
  const int texture = add_embedded_image(b);
  b.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}}};
  json quad = unit_quad(b);
  quad["material"] = 0;
  b.add_mesh_node(quad);
  const fs::path dir = gltf_test_dir("external");
  std::ofstream(dir / "wood.ppm", std::ios::binary) << ppm_2x2();
  std::ofstream(dir / "quad.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(b.buffer.data()),
             static_cast<std::streamsize>(b.buffer.size()));
  json doc = b.json;
  doc["images"][0] = {{"uri", "wood.ppm"}};
  doc["buffers"] = {{{"uri", "quad.bin"}, {"byteLength", b.buffer.size()}}};
  std::ofstream(dir / "quad.gltf") << doc.dump();
  const ImportedGltf got = import_gltf(dir / "quad.gltf");
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  const Material& m = material_of(got.scene);
  ASSERT_TRUE(m.base_color_map);
  EXPECT_NE(m.base_color_map.texture, missing_texture());
  EXPECT_EQ(m.base_color_map.texture->name(), "wood.ppm");

  // The same texture from outside the model's folder: refused, one warning, the checker.
  fs::create_directories(dir / "model");
  fs::copy_file(dir / "quad.bin", dir / "model" / "quad.bin");
  doc["images"][0] = {{"uri", "../wood.ppm"}};
  std::ofstream(dir / "model" / "quad.gltf") << doc.dump();
  const ImportedGltf refused = import_gltf(dir / "model" / "quad.gltf");
  ASSERT_EQ(refused.warnings.size(), 1u);
  EXPECT_TRUE(contains(refused.warnings[0], "texture ../wood.ppm is outside the model's folder"))
      << refused.warnings[0];
  EXPECT_EQ(material_of(refused.scene).base_color_map.texture, missing_texture());
  const ImportedGltf allowed = import_gltf(dir / "model" / "quad.gltf", true);
  EXPECT_TRUE(allowed.warnings.empty());
  EXPECT_NE(material_of(allowed.scene).base_color_map.texture, missing_texture());
}

// --- nothing to draw, unsupported required extensions -----------------------------------

TEST(GltfImport, ValidFileWithNothingToDrawIsAnErrorAndTheCliExitsNonZero) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  b.json["scenes"][0]["nodes"] = json::array();
  b.json["nodes"].push_back({{"name", "camera holder"}});
  b.json["scenes"][0]["nodes"].push_back(1);  // the mesh is in the file, but not in the scene
  const fs::path dir = gltf_test_dir("nothing");
  const fs::path file = b.write_gltf(dir / "empty.gltf");
  try {
    import_gltf(file);
    FAIL() << "imported";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ": nothing to draw", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  const CommandResult r = run_command(std::string(FACET_CLI) + " render '" + file.string() +
                                      "' -o '" + (dir / "out.png").string() + "' --size 64x64");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  EXPECT_TRUE(contains(r.stderr_text, "nothing to draw")) << r.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

// KHR_texture_basisu (KTX2 images facet cannot decode): one warning naming the extension; the
// texture that has no other source is left out (the material's factors alone), not a checker.
TEST(GltfImport, UnsupportedRequiredExtensionIsOneWarningNamingIt) {
  GltfBuilder b;
  b.json["extensionsUsed"] = {"KHR_texture_basisu"};
  b.json["extensionsRequired"] = {"KHR_texture_basisu"};
  const std::string ktx2 = "\xABKTX 20\xBB\r\n\x1A\n";
  b.json["images"] = {
      {{"bufferView", b.view(ktx2.data(), ktx2.size())}, {"mimeType", "image/ktx2"}}};
  b.json["textures"] = {{{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}}};
  b.json["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0, 0, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
  json quad = unit_quad(b);
  quad["material"] = 0;
  b.add_mesh_node(quad);
  const fs::path file = b.write_glb(gltf_test_dir("basisu") / "b.glb");
  const ImportedGltf got = import_gltf(file);
  ASSERT_EQ(got.warnings.size(), 1u);
  EXPECT_TRUE(contains(got.warnings[0], "requires KHR_texture_basisu")) << got.warnings[0];
  EXPECT_FALSE(material_of(got.scene).base_color_map);
  EXPECT_EQ(material_of(got.scene).base_color, glm::vec4(0, 0, 1, 1));
}

// --- damaged files ---------------------------------------------------------------------

TEST(GltfImport, AccessorReachingPastItsBufferFailsNamingIt) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  b.json["accessors"][0]["count"] = 1000000;
  const fs::path dir = gltf_test_dir("damaged");
  try {
    import_gltf(b.write_glb(dir / "long.glb"));
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "accessor 0: 1000000 elements of 12 bytes")) << e.what();
  }
  b.json["accessors"][0]["count"] = 4;
  b.json["bufferViews"][0]["byteLength"] = 1u << 30;
  try {
    import_gltf(b.write_glb(dir / "view.glb"));
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "buffer view 0")) << e.what();
  }
}

TEST(GltfImport, NodeWithTwoParentsFails) {
  GltfBuilder b;
  const int child = b.add_mesh_node(unit_quad(b));
  b.json["nodes"].push_back({{"children", {child}}});
  b.json["nodes"].push_back({{"children", {child}}});
  b.json["scenes"][0]["nodes"] = {1, 2};
  EXPECT_THROW(import_gltf(b.write_gltf(gltf_test_dir("two_parents") / "t.gltf")), Error);
}

TEST(GltfImport, DeepJsonIsRefusedBeforeParsing) {
  const fs::path dir = gltf_test_dir("json_limits");
  std::ofstream(dir / "deep.gltf") << std::string(100000, '[') << std::string(100000, ']');
  try {
    import_gltf(dir / "deep.gltf");
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "nests more than")) << e.what();
  }
}

}  // namespace
}  // namespace facet::test
