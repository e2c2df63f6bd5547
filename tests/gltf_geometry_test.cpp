// The glTF 2.0 reader's geometry on models the tests write (support/gltf_builder.hpp):
// quantized attributes, mirrored nodes, GPU instancing, every primitive mode, Draco and meshopt
// compression.
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
#include "support/text.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

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
  const ImportedGltf got = import_gltf(b.write_glb(gltf_test_dir("quantized") / "q.glb"));
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
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("normalized") / "n.gltf"));
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
    const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir(scale_name) / "m.gltf"));
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
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("shared_mirror") / "s.gltf"));
  ASSERT_EQ(got.scene.meshes.size(), 2u);  // the mesh, and its reversed copy
  const Mesh& plain = *got.scene.meshes[got.scene.nodes[0].instances[0].mesh];
  const Mesh& flipped = *got.scene.meshes[got.scene.nodes[1].instances[0].mesh];
  ASSERT_EQ(plain.indices.size(), flipped.indices.size());
  EXPECT_EQ(plain.indices[0], flipped.indices[0]);
  EXPECT_EQ(plain.indices[1], flipped.indices[2]);
  EXPECT_EQ(plain.indices[2], flipped.indices[1]);
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
  const ImportedGltf got = import_gltf(b.write_glb(gltf_test_dir("instancing") / "i.glb"));
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
    const ImportedGltf got =
        import_gltf(b.write_gltf(gltf_test_dir("mode" + std::to_string(c.mode)) / "m.gltf"));
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

// --- compressed meshes ----------------------------------------------------------------------

// The Draco-compressed copy of 2CylinderEngine in assimp-testmodels draws in the same place as
// the uncompressed GLB. The compressed copy holds 110336 triangles to the GLB's 121496 (the
// copies differ; assimp's own Draco decoding gave the same 110336).
TEST(GltfImport, DracoCompressedModelMatchesItsUncompressedCopy) {
  const fs::path draco = kSampleModels / "glTF2/draco/2CylinderEngine.gltf";
  const fs::path plain = kSampleModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  FACET_REQUIRE_PACKAGE(fs::exists(draco) && fs::exists(plain),
                        "assimp-testmodels is not installed");
  const ImportedGltf compressed = import_gltf(draco);
  const ImportedGltf uncompressed = import_gltf(plain);
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
  const fs::path dir = gltf_test_dir("draco");
  for (const fs::path& file : {b.write_glb(dir / "d.glb"), b.write_gltf(dir / "d.gltf")}) {
    SCOPED_TRACE(file.string());
    const ImportedGltf got = import_gltf(file);
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
  const fs::path dir = gltf_test_dir("meshopt");
  for (const fs::path& file : {b.write_glb(dir / "m.glb"), b.write_gltf(dir / "m.gltf")}) {
    SCOPED_TRACE(file.string());
    const ImportedGltf got = import_gltf(file);
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
    import_gltf(b.write_glb(dir / "liar.glb"));
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "more than the codec can hold")) << e.what();
  }
}

}  // namespace
}  // namespace facet::test
