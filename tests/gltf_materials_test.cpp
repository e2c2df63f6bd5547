// The glTF 2.0 reader's materials on models the tests write (support/gltf_builder.hpp):
// texture coordinate sets, KHR_texture_transform, and the material extensions.
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

// --- texture coordinate sets and KHR_texture_transform -----------------------------------

// The quad with a second texture coordinate set, TEXCOORD_1 = (1 - u, v) of TEXCOORD_0.
json two_set_quad(GltfBuilder& b) {
  json quad = unit_quad(b);
  quad["attributes"]["TEXCOORD_1"] = b.vec2s({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
  return quad;
}

TEST(GltfImport, TexCoordPicksTheSetAndTextureTransformEachMapsOwn) {
  GltfBuilder b;
  const int texture = add_embedded_image(b);
  b.json["extensionsUsed"] = {"KHR_texture_transform"};
  const json transform = {{"offset", {0.5, 0.25}}, {"rotation", 0.3}, {"scale", {2, 3}}};
  b.json["materials"] = {{{"name", "second set"},
                          {"pbrMetallicRoughness",
                           {{"baseColorTexture",
                             {{"index", texture},
                              {"texCoord", 0},
                              {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}}}}},
                          {"emissiveTexture",
                           {{"index", texture},
                            {"texCoord", 1},
                            {"extensions", {{"KHR_texture_transform", transform}}}}}}};
  json quad = two_set_quad(b);
  quad["material"] = 0;
  b.add_mesh_node(quad);
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("texcoord") / "t.gltf"));
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  const Mesh& mesh = mesh_of(got.scene);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_NEAR(mesh.texcoords[v].x, 1.0f - mesh.positions[v].x, 1e-6f);  // set 1
    EXPECT_NEAR(mesh.texcoords[v].y, mesh.positions[v].y, 1e-6f);
  }
  const Material& m = material_of(got.scene);
  EXPECT_EQ(m.base_color_map.transform, glm::mat3(1.0f));
  // glTF's uv' = T R S uv with v down; facet's v is up: the map's transform is glTF's
  // conjugated by v -> 1 - v.
  const float c = std::cos(0.3f), s = std::sin(0.3f);
  for (glm::vec2 p : {glm::vec2(0.1f, 0.2f), glm::vec2(0.9f, 0.6f)}) {
    glm::vec2 g(p.x, 1.0f - p.y);
    g *= glm::vec2(2, 3);
    g = glm::vec2(c * g.x + s * g.y, -s * g.x + c * g.y) + glm::vec2(0.5f, 0.25f);
    const glm::vec3 got_uv = m.emissive_map.transform * glm::vec3(p, 1.0f);
    EXPECT_NEAR(got_uv.x, g.x, 1e-5f);
    EXPECT_NEAR(got_uv.y, 1.0f - g.y, 1e-5f);
  }
}

// facet meshes carry one set: maps of one material that ask for different sets keep the base
// color map's, with one warning naming the material.
TEST(GltfImport, MapsOnDifferentSetsWarnOnceAndKeepTheBaseColorSet) {
  GltfBuilder b;
  const int texture = add_embedded_image(b);
  b.json["materials"] = {{{"name", "two sets"},
                          {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}},
                          {"normalTexture", {{"index", texture}, {"texCoord", 1}}},
                          {"occlusionTexture", {{"index", texture}, {"texCoord", 1}}}}};
  json quad = two_set_quad(b);
  quad["material"] = 0;
  b.add_mesh_node(quad);
  const ImportedGltf got = import_gltf(b.write_glb(gltf_test_dir("two_sets") / "t.glb"));
  ASSERT_EQ(got.warnings.size(), 1u);
  EXPECT_TRUE(
      contains(got.warnings[0], "material 'two sets' reads texture coordinate sets 0 and 1"))
      << got.warnings[0];
  const Mesh& mesh = mesh_of(got.scene);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    EXPECT_NEAR(mesh.texcoords[v].x, mesh.positions[v].x, 1e-6f);  // set 0
}

// --- material extensions ------------------------------------------------------------------

// One quad per material; `builder` may hold images the materials use.
Scene import_materials(const json& materials, const std::string& name,
                       GltfBuilder* builder = nullptr) {
  GltfBuilder own;
  GltfBuilder& b = builder ? *builder : own;
  b.json["materials"] = materials;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    json quad = unit_quad(b);
    quad["material"] = i;
    b.add_mesh_node(quad, {{"translation", {2.0 * i, 0, 0}}});
  }
  return import_gltf(b.write_gltf(gltf_test_dir(name) / "m.gltf")).scene;
}

TEST(GltfImport, SpecularGlossinessBecomesMetallicRoughness) {
  GltfBuilder b;
  const int texture = add_embedded_image(b);  // opaque: gloss 1 in alpha
  const Scene scene = import_materials(
      {{{"extensions",
         {{"KHR_materials_pbrSpecularGlossiness",
           {{"diffuseFactor", {0.8, 0.2, 0.2, 1}},
            {"specularFactor", {0.04, 0.04, 0.04}},
            {"glossinessFactor", 0.75}}}}}},
       {{"extensions",
         {{"KHR_materials_pbrSpecularGlossiness",
           {{"diffuseFactor", {0, 0, 0, 1}}, {"specularFactor", {1, 0.8, 0.3}}}}}}},
       {{"extensions",
         {{"KHR_materials_pbrSpecularGlossiness",
           {{"glossinessFactor", 0.25}, {"specularGlossinessTexture", {{"index", texture}}}}}}}}},
      "spec_gloss", &b);
  const Material& plastic = material_of(scene, 0);
  EXPECT_EQ(plastic.shading, ShadingModel::pbr);
  EXPECT_NEAR(plastic.metallic, 0.0f, 1e-6f);  // a dielectric's 4 %
  EXPECT_NEAR(plastic.roughness, 0.25f, 1e-6f);
  EXPECT_NEAR(glm::length(glm::vec3(plastic.base_color) - glm::vec3(0.8f, 0.2f, 0.2f)), 0, 1e-5f);
  const Material& gold = material_of(scene, 1);
  EXPECT_GT(gold.metallic, 0.9f);
  EXPECT_NEAR(gold.roughness, 0.0f, 1e-6f);  // glossiness 1
  EXPECT_NEAR(glm::length(glm::vec3(gold.base_color) - glm::vec3(1, 0.8f, 0.3f)), 0, 0.05f);
  // The gloss map (alpha 1, factor 0.25) baked into roughness 0.75, which the factor 1 keeps.
  const Material& mapped = material_of(scene, 2);
  EXPECT_FLOAT_EQ(mapped.roughness, 1.0f);
  ASSERT_TRUE(mapped.metallic_roughness_map);
  EXPECT_NEAR(mapped.metallic_roughness_map.texture->texel(0, 0, 0).g, 0.75f, 0.5f / 255);
  EXPECT_EQ(scene.textures.size(), 1u);  // the baked map only
}

TEST(GltfImport, UnlitEmissiveStrengthTransmissionAndClearcoat) {
  const Scene scene = import_materials(
      {{{"extensions", {{"KHR_materials_unlit", json::object()}}}},
       {{"emissiveFactor", {1, 0.5, 0}},
        {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}},
       {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}},
       {{"pbrMetallicRoughness", {{"roughnessFactor", 0.8}}},
        {"extensions",
         {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.5}, {"clearcoatRoughness", 0.2}}}}}}},
      "material_extensions");
  EXPECT_EQ(material_of(scene, 0).shading, ShadingModel::unlit);
  EXPECT_EQ(material_of(scene, 1).emissive, glm::vec3(4, 2, 0));
  const Material& glass = material_of(scene, 2);
  EXPECT_EQ(glass.alpha_mode, AlphaMode::blend);
  EXPECT_LT(glass.base_color.a, 0.5f);
  EXPECT_NEAR(material_of(scene, 3).roughness, 0.5f, 1e-6f);
}

// A velvet: dark base, navy sheen. Its base color becomes base (1 - 0.5 x 0.5) + 0.5 sheen =
// (0.02 x 0.75 + 0.025, 0.02 x 0.75 + 0.05, 0.02 x 0.75 + 0.25): navy, not the near-black base.
TEST(GltfImport, SheenColourContributesToTheBaseColour) {
  GltfBuilder b;
  const int texture = add_embedded_image(b);
  const Scene scene = import_materials(
      {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.02, 0.02, 0.02, 1}}}},
        {"extensions",
         {{"KHR_materials_sheen",
           {{"sheenColorFactor", {0.05, 0.1, 0.5}}, {"sheenRoughnessFactor", 0.6}}}}}},
       {{"pbrMetallicRoughness",
         {{"baseColorFactor", {1, 1, 1, 1}}, {"baseColorTexture", {{"index", texture}}}}},
        {"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {0, 0, 1}}}}}}}},
      "sheen", &b);
  const glm::vec4 velvet = material_of(scene, 0).base_color;
  EXPECT_NEAR(velvet.r, 0.04f, 1e-5f);
  EXPECT_NEAR(velvet.g, 0.065f, 1e-5f);
  EXPECT_NEAR(velvet.b, 0.265f, 1e-5f);
  // With a base color map the sheen is baked into it: its red texel (1, 0, 0) becomes
  // (1 x 0.5, 0, 0.5) in linear light.
  const Material& mapped = material_of(scene, 1);
  ASSERT_TRUE(mapped.base_color_map);
  const glm::vec4 red = mapped.base_color_map.texture->texel(0, 0, 0);
  const glm::vec3 linear(red);  // texel() decodes sRGB
  EXPECT_NEAR(linear.r, 0.5f, 0.01f);
  EXPECT_NEAR(linear.g, 0.0f, 0.01f);
  EXPECT_NEAR(linear.b, 0.5f, 0.01f);
  EXPECT_EQ(mapped.base_color, glm::vec4(1.0f));
}

// facet's lobe has F0 0.04 (ior 1.5): a weaker specular spreads the highlight (roughness toward
// 1 by 1 - weight); ior 1.5 and specular 1 change nothing; a metal keeps its roughness.
TEST(GltfImport, SpecularAndIorSetTheHighlightsWeight) {
  const json rough = {{"roughnessFactor", 0.2}, {"metallicFactor", 0}};
  const Scene scene = import_materials(
      {{{"pbrMetallicRoughness", rough},
        {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0}}}}}},
       {{"pbrMetallicRoughness", rough},
        {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.5}}}}}},
       {{"pbrMetallicRoughness", rough}, {"extensions", {{"KHR_materials_ior", {{"ior", 1.5}}}}}},
       {{"pbrMetallicRoughness", rough}, {"extensions", {{"KHR_materials_ior", {{"ior", 1.0}}}}}},
       {{"pbrMetallicRoughness", {{"roughnessFactor", 0.2}, {"metallicFactor", 1}}},
        {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0}}}}}}},
      "specular_ior");
  EXPECT_NEAR(material_of(scene, 0).roughness, 1.0f, 1e-6f);
  EXPECT_NEAR(material_of(scene, 1).roughness, 0.6f, 1e-6f);  // weight 0.5: halfway to 1
  EXPECT_NEAR(material_of(scene, 2).roughness, 0.2f, 1e-6f);
  EXPECT_NEAR(material_of(scene, 3).roughness, 1.0f, 1e-6f);  // ior 1: no reflection at all
  EXPECT_NEAR(material_of(scene, 4).roughness, 0.2f, 1e-6f);
}

// A green glass lets through transmission x (1 - F0) x its luminance (0.2126 x 0.2 + 0.7152 x
// 0.8 + 0.0722 x 0.2 = 0.6292): alpha 1 - 0.96 x 0.6292 = 0.396, so it tints what is behind it;
// a clear glass is drawn at the floor of 0.1.
TEST(GltfImport, TransmissionIsSeeThroughWithATint) {
  const Scene scene = import_materials(
      {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.8, 0.2, 1}}}},
        {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}},
       {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}}},
      "transmission");
  const Material& green = material_of(scene, 0);
  EXPECT_EQ(green.alpha_mode, AlphaMode::blend);
  EXPECT_NEAR(green.base_color.a, 1.0f - 0.96f * 0.6292f, 1e-3f);
  EXPECT_NEAR(material_of(scene, 1).base_color.a, 0.1f, 1e-6f);
}

}  // namespace
}  // namespace facet::test
