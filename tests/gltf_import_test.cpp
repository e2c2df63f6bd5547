// The glTF 2.0 reader (src/import/gltf_*.cpp), each feature on a model made for it by the test
// (support/gltf_builder.hpp): meshes, node transforms, materials with their maps and samplers,
// vertex colors, cameras, lights, quantized attributes, mirrored nodes, texture coordinate sets,
// instancing, every primitive mode, files with nothing to draw and required extensions.
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>

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

namespace facet::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Imported {
  Scene scene;
  std::vector<std::string> warnings;
};

Imported import_file(const fs::path& path, bool allow_outside = false) {
  Imported out;
  ImportOptions options;
  options.allow_outside_paths = allow_outside;
  options.warn = [&](const std::string& w) { out.warnings.push_back(w); };
  out.scene = import_scene(path.string(), options);
  return out;
}

fs::path dir_for(const std::string& name) { return fresh_test_dir("facet_gltf_", name); }

// A 2x2 binary PPM (stb_image reads it; glTF readers decode by content): red, green / blue, white.
std::string ppm_2x2() {
  std::string bytes = "P6\n2 2\n255\n";
  for (unsigned char c : {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255})
    bytes += static_cast<char>(c);
  return bytes;
}

int add_embedded_image(GltfBuilder& b) {
  const std::string image = ppm_2x2();
  const int view = b.view(image.data(), image.size());
  b.json["images"].push_back({{"bufferView", view}, {"mimeType", "image/png"}});
  b.json["textures"].push_back({{"source", b.json["images"].size() - 1}});
  return static_cast<int>(b.json["textures"].size()) - 1;
}

const Material& material_of(const Scene& scene, int node = -1) {
  for (const SceneNode& n : scene.nodes) {
    if (!n.instances.empty() && node < 0) return scene.materials.at(n.instances[0].material);
  }
  return scene.materials.at(scene.nodes.at(node).instances.at(0).material);
}

const Mesh& mesh_of(const Scene& scene) {
  for (const SceneNode& n : scene.nodes) {
    if (!n.instances.empty()) return *scene.meshes.at(n.instances[0].mesh);
  }
  throw Error("no mesh");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// --- parity with what the assimp reader drew ---------------------------------------------

TEST(GltfImport, GltfAndGlbOfOneModelGiveTheSameMesh) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  // A second, non-indexed triangle.
  b.add_mesh_node({{"attributes", {{"POSITION", b.positions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}})}}}});
  const fs::path dir = dir_for("gltf_and_glb");
  for (const fs::path& file : {b.write_gltf(dir / "quad.gltf"), b.write_glb(dir / "quad.glb")}) {
    SCOPED_TRACE(file.string());
    const Imported got = import_file(file);
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
  const Imported got = import_file(b.write_gltf(dir_for("hierarchy") / "h.gltf"));
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
  const Imported got = import_file(b.write_glb(dir_for("material") / "m.glb"));
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
  const Material& m = material_of(import_file(b.write_gltf(dir_for("default") / "d.gltf")).scene);
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
  b.add_mesh_node(quad);
  json rgb_quad = unit_quad(b);
  rgb_quad["attributes"]["COLOR_0"] =
      b.vec3s({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2f, 0.2f, 0.2f}});
  b.add_mesh_node(rgb_quad, {{"translation", {2, 0, 0}}});
  const Imported got = import_file(b.write_gltf(dir_for("colors") / "c.gltf"));
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
  const Imported got = import_file(b.write_gltf(dir_for("cameras") / "c.gltf"));
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
  const fs::path dir = dir_for("external");
  std::ofstream(dir / "wood.ppm", std::ios::binary) << ppm_2x2();
  std::ofstream(dir / "quad.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(b.buffer.data()),
             static_cast<std::streamsize>(b.buffer.size()));
  json doc = b.json;
  doc["images"][0] = {{"uri", "wood.ppm"}};
  doc["buffers"] = {{{"uri", "quad.bin"}, {"byteLength", b.buffer.size()}}};
  std::ofstream(dir / "quad.gltf") << doc.dump();
  const Imported got = import_file(dir / "quad.gltf");
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
  const Imported refused = import_file(dir / "model" / "quad.gltf");
  ASSERT_EQ(refused.warnings.size(), 1u);
  EXPECT_TRUE(contains(refused.warnings[0], "texture ../wood.ppm is outside the model's folder"))
      << refused.warnings[0];
  EXPECT_EQ(material_of(refused.scene).base_color_map.texture, missing_texture());
  const Imported allowed = import_file(dir / "model" / "quad.gltf", true);
  EXPECT_TRUE(allowed.warnings.empty());
  EXPECT_NE(material_of(allowed.scene).base_color_map.texture, missing_texture());
}

// --- KHR_mesh_quantization ----------------------------------------------------------------

// The unit quad with quantized attributes: positions as unnormalized shorts 0..100 (the node
// scales them by 0.01), padded to 8 bytes a vertex as glTF aligns them; normals as normalized
// signed bytes; texture coordinates as normalized unsigned shorts.
TEST(GltfImport, QuantizedPositionsNormalsAndTextureCoordinates) {
  GltfBuilder b;
  b.json["extensionsUsed"] = {"KHR_mesh_quantization"};
  b.json["extensionsRequired"] = {"KHR_mesh_quantization"};
  const std::vector<std::int16_t> positions = {0,   0,   0, 0, 100, 0,   0, 0,
                                               100, 100, 0, 0, 0,   100, 0, 0};
  const std::vector<std::int8_t> normals = {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0};
  const std::vector<std::uint16_t> uvs = {0, 65535, 65535, 65535, 65535, 0, 0, 0};
  const int p = b.accessor(b.view(positions.data(), positions.size() * 2, 8), kGlShort, 4, "VEC3");
  b.json["accessors"][p]["min"] = {0, 0, 0};
  b.json["accessors"][p]["max"] = {100, 100, 0};
  const int n = b.accessor(b.view(normals.data(), normals.size(), 4), kGlByte, 4, "VEC3", true);
  const int uv = b.accessor(b.view(uvs.data(), uvs.size() * 2), kGlUnsignedShort, 4, "VEC2", true);
  const int i = b.indices({0, 1, 2, 0, 2, 3});
  b.add_mesh_node(
      {{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", uv}}}, {"indices", i}},
      {{"scale", {0.01, 0.01, 0.01}}});
  const Imported got = import_file(b.write_glb(dir_for("quantized") / "q.glb"));
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  const Mesh& mesh = mesh_of(got.scene);
  ASSERT_EQ(mesh.positions.size(), 4u);
  for (std::size_t v = 0; v < 4; ++v) {
    const glm::vec3 q = mesh.positions[v];
    EXPECT_TRUE(q.x == 0 || q.x == 100) << q.x;
    EXPECT_NEAR(glm::length(mesh.normals[v] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(mesh.texcoords[v].x, q.x / 100, 1e-6f);  // glTF v down, facet's up
    EXPECT_NEAR(mesh.texcoords[v].y, q.y / 100, 1e-6f);
  }
  const Bounds bounds = got.scene.bounds();
  EXPECT_NEAR(bounds.max.x, 1.0f, 1e-6f);
  EXPECT_NEAR(bounds.max.y, 1.0f, 1e-6f);
  EXPECT_GT(render_small(got.scene).triangles_in, 0u);
}

// Normalized unsigned byte positions (0..255 -> 0..1) and a normalized short, -32768, clamped
// to -1 as glTF 2.0 §3.11 says.
TEST(GltfImport, NormalizedIntegerPositionsAreScaledToUnitRange) {
  GltfBuilder b;
  const std::vector<std::uint8_t> positions = {0, 0, 0, 0, 255, 0, 0, 0, 0, 255, 0, 0};
  const int p =
      b.accessor(b.view(positions.data(), positions.size(), 4), kGlUnsignedByte, 3, "VEC3", true);
  const std::vector<std::int16_t> shorts = {-32768, 0, 0, 0, 32767, 0, 0, 0, 0, 32767, 0, 0};
  const int s = b.accessor(b.view(shorts.data(), shorts.size() * 2, 8), kGlShort, 3, "VEC3", true);
  b.add_mesh_node({{"attributes", {{"POSITION", p}}}});
  b.add_mesh_node({{"attributes", {{"POSITION", s}}}});
  const Imported got = import_file(b.write_gltf(dir_for("normalized") / "n.gltf"));
  const Mesh& bytes = *got.scene.meshes.at(0);
  const Mesh& halves = *got.scene.meshes.at(1);
  EXPECT_EQ(bytes.positions[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(bytes.positions[2], glm::vec3(0, 1, 0));
  EXPECT_EQ(halves.positions[0], glm::vec3(-1, 0, 0));
  EXPECT_EQ(halves.positions[1], glm::vec3(1, 0, 0));
}

// --- mirrored nodes -------------------------------------------------------------------------

// A quad facing +Z under a node that mirrors x (determinant < 0) still faces +Z: glTF makes its
// clockwise triangles the front ones (glTF 2.0 section 3.7.2.1). Seen from the front (the
// automatic view looks from +Z), nothing may be culled, in a mirrored cube as in the quad; the
// normals facet computes for a mesh without them face out of the mirrored surface.
TEST(GltfImport, MirroredNodesKeepTheirFrontFaces) {
  for (const char* scale_name : {"plain", "mirrored"}) {
    SCOPED_TRACE(scale_name);
    const bool mirrored = std::string(scale_name) == "mirrored";
    GltfBuilder b;
    json quad = unit_quad(b);
    quad["attributes"].erase("NORMAL");
    b.add_mesh_node(quad, {{"scale", {mirrored ? -1 : 1, 1, 1}}});
    const Imported got = import_file(b.write_gltf(dir_for(scale_name) / "m.gltf"));
    const glm::mat4 world = got.scene.world_transform(0);
    const Mesh& mesh = mesh_of(got.scene);
    for (const glm::vec3& n : mesh.normals) {
      const glm::vec3 world_normal = glm::transpose(glm::inverse(glm::mat3(world))) * n;
      EXPECT_NEAR(glm::length(world_normal - glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
    }
    const FrameStats stats = render_small(got.scene);
    EXPECT_EQ(stats.triangles_in, 2u);
    EXPECT_EQ(stats.culled, 0u);
    EXPECT_GT(stats.pixels_shaded, 0u);
  }
}

TEST(GltfImport, MirroredAndPlainUsesOfOneMeshGetTheirOwnWinding) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  b.json["nodes"].push_back({{"mesh", 0}, {"scale", {1, 1, -1}}, {"translation", {2, 0, 0}}});
  b.json["scenes"][0]["nodes"].push_back(1);
  const Imported got = import_file(b.write_gltf(dir_for("shared_mirror") / "s.gltf"));
  ASSERT_EQ(got.scene.meshes.size(), 2u);  // the mesh, and its reversed copy
  const Mesh& plain = *got.scene.meshes[got.scene.nodes[0].instances[0].mesh];
  const Mesh& flipped = *got.scene.meshes[got.scene.nodes[1].instances[0].mesh];
  ASSERT_EQ(plain.indices.size(), flipped.indices.size());
  EXPECT_EQ(plain.indices[0], flipped.indices[0]);
  EXPECT_EQ(plain.indices[1], flipped.indices[2]);
  EXPECT_EQ(plain.indices[2], flipped.indices[1]);
}

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
  const Imported got = import_file(b.write_gltf(dir_for("texcoord") / "t.gltf"));
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
  const Imported got = import_file(b.write_glb(dir_for("two_sets") / "t.glb"));
  ASSERT_EQ(got.warnings.size(), 1u);
  EXPECT_TRUE(
      contains(got.warnings[0], "material 'two sets' reads texture coordinate sets 0 and 1"))
      << got.warnings[0];
  const Mesh& mesh = mesh_of(got.scene);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    EXPECT_NEAR(mesh.texcoords[v].x, mesh.positions[v].x, 1e-6f);  // set 0
}

// --- EXT_mesh_gpu_instancing and primitive modes ------------------------------------------

TEST(GltfImport, GpuInstancesBecomeChildNodes) {
  GltfBuilder b;
  b.json["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  const int node = b.add_mesh_node(unit_quad(b), {{"translation", {0, 10, 0}}});
  const int translations = b.vec3s({{0, 0, 0}, {2, 0, 0}, {4, 0, 0}});
  const int scales = b.vec3s({{1, 1, 1}, {1, 1, 1}, {-1, 1, 1}});
  const int rotations = b.vec4s({{0, 0, 0, 1}, {0, 0, 0.70710678f, 0.70710678f}, {0, 0, 0, 1}});
  b.json["nodes"][node]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {
      {"TRANSLATION", translations}, {"ROTATION", rotations}, {"SCALE", scales}};
  const Imported got = import_file(b.write_glb(dir_for("instancing") / "i.glb"));
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  ASSERT_EQ(got.scene.nodes.size(), 4u);
  EXPECT_TRUE(got.scene.nodes[0].instances.empty());
  EXPECT_EQ(got.scene.triangle_count(), 6u);
  for (int i = 1; i <= 3; ++i) {
    EXPECT_EQ(got.scene.nodes[i].parent, 0);
    const glm::vec3 origin = glm::vec3(got.scene.world_transform(i)[3]);
    EXPECT_NEAR(glm::length(origin - glm::vec3(2.0f * (i - 1), 10, 0)), 0.0f, 1e-5f);
  }
  // Instance 1 turned 90 degrees about z: its x axis is world y.
  const glm::vec3 x_axis = glm::vec3(got.scene.world_transform(2)[0]);
  EXPECT_NEAR(glm::length(x_axis - glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
  // Instance 2 is mirrored: its own, reversed copy of the mesh, drawn from the front.
  EXPECT_NE(got.scene.nodes[3].instances[0].mesh, got.scene.nodes[1].instances[0].mesh);
  EXPECT_EQ(render_small(got.scene).culled, 0u);
}

// Four vertices (0, 0), (1, 0), (0, 1), (1, 1) in each glTF mode (a fan: round the quad).
TEST(GltfImport, EveryPrimitiveModeIsDrawn) {
  struct Case {
    int mode;
    Topology topology;
    std::size_t primitives;
  };
  const Case cases[] = {{0, Topology::points, 4},    {1, Topology::lines, 2},
                        {2, Topology::lines, 4},     {3, Topology::lines, 3},
                        {4, Topology::triangles, 1}, {5, Topology::triangles, 2},
                        {6, Topology::triangles, 2}};
  for (const Case& c : cases) {
    SCOPED_TRACE("mode " + std::to_string(c.mode));
    GltfBuilder b;
    // A fan walks round its first vertex: the quad's corners in order.
    const int p = c.mode == 6 ? b.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})
                              : b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    b.add_mesh_node({{"attributes", {{"POSITION", p}}}, {"mode", c.mode}});
    const Imported got =
        import_file(b.write_gltf(dir_for("mode" + std::to_string(c.mode)) / "m.gltf"));
    const Mesh& mesh = mesh_of(got.scene);
    EXPECT_EQ(mesh.topology, c.topology);
    EXPECT_EQ(mesh.primitive_count(), c.primitives);
    if (c.topology == Topology::triangles) {
      // Strips and fans turn every triangle the same way: all face +Z.
      for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]],
                        e1 = mesh.positions[mesh.indices[t + 1]] - a,
                        e2 = mesh.positions[mesh.indices[t + 2]] - a;
        EXPECT_GT(glm::cross(e1, e2).z, 0.0f) << "triangle " << t / 3;
      }
    }
    const FrameStats stats = render_small(got.scene);
    EXPECT_EQ(stats.points_drawn, c.topology == Topology::points ? c.primitives : 0u);
    if (c.topology == Topology::lines) {
      EXPECT_EQ(stats.lines_drawn, c.primitives);
    }
    if (c.topology == Topology::triangles) {
      EXPECT_EQ(stats.culled, 0u);
    }
  }
}

// --- nothing to draw, unsupported required extensions -----------------------------------

TEST(GltfImport, ValidFileWithNothingToDrawIsAnErrorAndTheCliExitsNonZero) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  b.json["scenes"][0]["nodes"] = json::array();
  b.json["nodes"].push_back({{"name", "camera holder"}});
  b.json["scenes"][0]["nodes"].push_back(1);  // the mesh is in the file, but not in the scene
  const fs::path dir = dir_for("nothing");
  const fs::path file = b.write_gltf(dir / "empty.gltf");
  try {
    import_file(file);
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
  const fs::path file = b.write_glb(dir_for("basisu") / "b.glb");
  const Imported got = import_file(file);
  ASSERT_EQ(got.warnings.size(), 1u);
  EXPECT_TRUE(contains(got.warnings[0], "requires KHR_texture_basisu")) << got.warnings[0];
  EXPECT_FALSE(material_of(got.scene).base_color_map);
  EXPECT_EQ(material_of(got.scene).base_color, glm::vec4(0, 0, 1, 1));
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
  return import_file(b.write_gltf(dir_for(name) / "m.gltf")).scene;
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

// --- compressed meshes ----------------------------------------------------------------------

// The Draco-compressed copy of 2CylinderEngine in assimp-testmodels draws in the same place as
// the uncompressed GLB. The compressed copy holds 110336 triangles to the GLB's 121496 (the
// copies differ; assimp's own Draco decoding gave the same 110336).
TEST(GltfImport, DracoCompressedModelMatchesItsUncompressedCopy) {
  const fs::path draco = kSampleModels / "glTF2/draco/2CylinderEngine.gltf";
  const fs::path plain = kSampleModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  FACET_REQUIRE_PACKAGE(fs::exists(draco) && fs::exists(plain),
                        "assimp-testmodels is not installed");
  const Imported compressed = import_file(draco);
  const Imported uncompressed = import_file(plain);
  EXPECT_TRUE(compressed.warnings.empty()) << compressed.warnings[0];
  EXPECT_EQ(compressed.scene.triangle_count(), 110336u);
  EXPECT_EQ(uncompressed.scene.triangle_count(), 121496u);
  const Bounds a = compressed.scene.bounds(), b = uncompressed.scene.bounds();
  const float size = glm::length(b.max - b.min);
  EXPECT_LT(glm::length(a.min - b.min), size * 1e-3f);  // Draco quantizes positions
  EXPECT_LT(glm::length(a.max - b.max), size * 1e-3f);
}

// KHR_draco_mesh_compression on a model made here: the unit quad's two triangles with texture
// coordinates, encoded by Draco (positions quantized to 14 bits), indices only in the Draco data.
TEST(GltfImport, DracoPrimitiveDecodesPositionsTextureCoordinatesAndTriangles) {
  draco::TriangleSoupMeshBuilder soup;
  soup.Start(2);
  const int pos = soup.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int tex = soup.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  const glm::vec3 corner[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (int f = 0; f < 2; ++f) {
    glm::vec3 p[3];
    glm::vec2 uv[3];
    for (int c = 0; c < 3; ++c) {
      p[c] = corner[faces[f][c]];
      uv[c] = glm::vec2(p[c].x, 1.0f - p[c].y);  // glTF's v runs down
    }
    soup.SetAttributeValuesForFace(pos, draco::FaceIndex(f), &p[0], &p[1], &p[2]);
    soup.SetAttributeValuesForFace(tex, draco::FaceIndex(f), &uv[0], &uv[1], &uv[2]);
  }
  std::unique_ptr<draco::Mesh> mesh = soup.Finalize();
  ASSERT_TRUE(mesh);
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  draco::EncoderBuffer encoded;
  ASSERT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &encoded).ok());

  GltfBuilder b;
  b.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  b.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  const int view = b.view(encoded.data(), encoded.size());
  const std::size_t points = mesh->num_points();
  b.json["accessors"] = {{{"componentType", kGlFloat},
                          {"count", points},
                          {"type", "VEC3"},
                          {"min", {0, 0, 0}},
                          {"max", {1, 1, 0}}},
                         {{"componentType", kGlFloat}, {"count", points}, {"type", "VEC2"}},
                         {{"componentType", kGlUnsignedShort}, {"count", 6}, {"type", "SCALAR"}}};
  b.add_mesh_node({{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                   {"indices", 2},
                   {"extensions",
                    {{"KHR_draco_mesh_compression",
                      {{"bufferView", view},
                       {"attributes",
                        {{"POSITION", mesh->attribute(pos)->unique_id()},
                         {"TEXCOORD_0", mesh->attribute(tex)->unique_id()}}}}}}}});
  const fs::path dir = dir_for("draco");
  for (const fs::path& file : {b.write_glb(dir / "d.glb"), b.write_gltf(dir / "d.gltf")}) {
    SCOPED_TRACE(file.string());
    const Imported got = import_file(file);
    EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
    const Mesh& quad = mesh_of(got.scene);
    EXPECT_EQ(quad.primitive_count(), 2u);
    ASSERT_EQ(quad.texcoords.size(), quad.positions.size());
    for (std::size_t v = 0; v < quad.positions.size(); ++v) {
      EXPECT_NEAR(quad.texcoords[v].x, quad.positions[v].x, 1e-3f);
      EXPECT_NEAR(quad.texcoords[v].y, quad.positions[v].y, 1e-3f);
    }
    const Bounds bounds = got.scene.bounds();
    EXPECT_NEAR(glm::length(bounds.max - glm::vec3(1, 1, 0)), 0.0f, 1e-3f);
    EXPECT_EQ(render_small(got.scene).culled, 0u);  // the winding survived
  }
}

// EXT_meshopt_compression: positions and indices encoded with meshoptimizer, in a GLB and in a
// .gltf whose fallback buffer has no URI (as gltfpack writes them).
TEST(GltfImport, MeshoptCompressedViewsAreDecoded) {
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<unsigned> indices = {0, 1, 2, 0, 2, 3};
  std::vector<unsigned char> vertices(meshopt_encodeVertexBufferBound(4, 12));
  vertices.resize(
      meshopt_encodeVertexBuffer(vertices.data(), vertices.size(), positions.data(), 4, 12));
  std::vector<unsigned char> triangles(meshopt_encodeIndexBufferBound(6, 4));
  triangles.resize(
      meshopt_encodeIndexBuffer(triangles.data(), triangles.size(), indices.data(), 6));
  GltfBuilder b;
  b.json["extensionsUsed"] = {"EXT_meshopt_compression"};
  b.json["extensionsRequired"] = {"EXT_meshopt_compression"};
  b.view(vertices.data(), vertices.size());
  b.view(triangles.data(), triangles.size());
  const json compressed = b.json["bufferViews"];
  auto meshopt = [&](int i, int stride, int count, const char* mode) {
    return json{{"buffer", 0},
                {"byteOffset", compressed[i]["byteOffset"]},
                {"byteLength", compressed[i]["byteLength"]},
                {"byteStride", stride},
                {"count", count},
                {"mode", mode}};
  };
  b.json["buffers"] = {
      nullptr,
      {{"byteLength", 72}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
  b.json["bufferViews"] = {
      {{"buffer", 1},
       {"byteLength", 48},
       {"byteStride", 12},
       {"extensions", {{"EXT_meshopt_compression", meshopt(0, 12, 4, "ATTRIBUTES")}}}},
      {{"buffer", 1},
       {"byteOffset", 48},
       {"byteLength", 24},
       {"extensions", {{"EXT_meshopt_compression", meshopt(1, 4, 6, "TRIANGLES")}}}}};
  const int p = b.accessor(0, kGlFloat, 4, "VEC3");
  b.json["accessors"][p]["min"] = {0, 0, 0};
  b.json["accessors"][p]["max"] = {1, 1, 0};
  const int i = b.accessor(1, kGlUnsignedInt, 6, "SCALAR");
  b.add_mesh_node({{"attributes", {{"POSITION", p}}}, {"indices", i}});
  const fs::path dir = dir_for("meshopt");
  for (const fs::path& file : {b.write_glb(dir / "m.glb"), b.write_gltf(dir / "m.gltf")}) {
    SCOPED_TRACE(file.string());
    const Imported got = import_file(file);
    EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
    const Mesh& mesh = mesh_of(got.scene);
    EXPECT_EQ(mesh.primitive_count(), 2u);
    const Bounds bounds = got.scene.bounds();
    EXPECT_EQ(bounds.min, glm::vec3(0, 0, 0));
    EXPECT_EQ(bounds.max, glm::vec3(1, 1, 0));
  }
  // A count the compressed bytes cannot hold is refused before anything is allocated.
  b.json["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 100000000;
  try {
    import_file(b.write_glb(dir / "liar.glb"));
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "more than the codec can hold")) << e.what();
  }
}

// --- damaged files ---------------------------------------------------------------------

TEST(GltfImport, AccessorReachingPastItsBufferFailsNamingIt) {
  GltfBuilder b;
  b.add_mesh_node(unit_quad(b));
  b.json["accessors"][0]["count"] = 1000000;
  const fs::path dir = dir_for("damaged");
  try {
    import_file(b.write_glb(dir / "long.glb"));
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "accessor 0: 1000000 elements of 12 bytes")) << e.what();
  }
  b.json["accessors"][0]["count"] = 4;
  b.json["bufferViews"][0]["byteLength"] = 1u << 30;
  try {
    import_file(b.write_glb(dir / "view.glb"));
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
  EXPECT_THROW(import_file(b.write_gltf(dir_for("two_parents") / "t.gltf")), Error);
}

TEST(GltfImport, DeepJsonIsRefusedBeforeParsing) {
  const fs::path dir = dir_for("json_limits");
  std::ofstream(dir / "deep.gltf") << std::string(100000, '[') << std::string(100000, ']');
  try {
    import_file(dir / "deep.gltf");
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "nests more than")) << e.what();
  }
}

}  // namespace
}  // namespace facet::test
