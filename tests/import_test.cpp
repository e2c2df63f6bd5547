// Model import (src/io/import*.cpp) and the normals and tangents it computes
// (src/scene/normals.cpp): every model of Debian's assimp-testmodels for OBJ, glTF 2.0, PLY,
// STL, 3DS and OFF imports and renders or fails with a facet::Error; broken files never crash;
// materials, missing textures, node transforms, cameras and the glmark2 bunny come out right.
#include "facet/import.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/renderer.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = kSampleModels;                         // Debian package assimp-testmodels
const fs::path kBunny = "/usr/share/glmark2/models/bunny.obj";  // Debian package glmark2-data

// Files that must fail with a facet::Error, and why. Everything else must import and render.
const std::map<std::string, std::string> kExpectedFailures = {
    {"OBJ/box_UTF16BE.obj", "UTF-16 text; assimp 5.2's OBJ reader finds no mesh in it"},
    {"PLY/pond.0.ply",
     "a binary point cloud damaged in packaging (CRs stripped): 69 bytes short of the vertices "
     "its header declares"},
    {"OFF/invalid.off", "deliberately invalid (no faces)"},
    {"glTF2/TestNoRootNode/NoScene.gltf", "no scene at all"},
    {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", "a scene without nodes: nothing to draw"},
    {"glTF2/SchemaFailures/sceneWrongType.gltf", "deliberate schema error"},
    {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "deliberately recursive node graph"},
};

ImportOptions quiet() {
  ImportOptions options;
  options.warn = [](const std::string&) {};
  return options;
}

// Imports and renders every model in a directory of the testmodels; expected failures must fail.
void import_directory(const std::string& directory) {
  FACET_REQUIRE_PACKAGE(fs::exists(kModels / directory), "assimp-testmodels is not installed");
  int rendered = 0;
  for (const fs::path& file : wellformed_model_files(directory)) {
    const std::string relative = fs::relative(file, kModels).string();
    SCOPED_TRACE(relative);
    auto expected = kExpectedFailures.find(relative);
    try {
      Scene scene = import_scene(file.string(), quiet());
      EXPECT_EQ(expected, kExpectedFailures.end())
          << "imported, but listed to fail because: " << expected->second;
      EXPECT_GT(render_small(scene).triangles_in, 0u);
      ++rendered;
    } catch (const Error& e) {
      EXPECT_NE(expected, kExpectedFailures.end()) << "failed: " << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "not one line";
    }
  }
  EXPECT_GT(rendered, 0);
}

TEST(ImportModels, Obj) { import_directory("OBJ"); }
TEST(ImportModels, Gltf2) { import_directory("glTF2"); }
TEST(ImportModels, Ply) { import_directory("PLY"); }
TEST(ImportModels, Stl) { import_directory("STL"); }
TEST(ImportModels, ThreeDs) { import_directory("3DS"); }
TEST(ImportModels, Off) { import_directory("OFF"); }

// Every file under an `invalid` directory (any format) and the broken glTF samples: an error or
// a clean render, never a crash. All run in this process: none of them crashes assimp 5.2 (the
// one that made it allocate 15 GB, invalid/OutOfMemory.off, is refused before assimp reads it).
TEST(ImportModels, BrokenFilesFailCleanly) {
  FACET_REQUIRE_PACKAGE(fs::exists(kModels), "assimp-testmodels is not installed");
  int checked = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kModels)) {
    const fs::path relative = fs::relative(entry.path(), kModels);
    if (!entry.is_regular_file() || entry.path().extension() == ".txt") continue;
    if (!under_invalid_directory(relative) && !is_robustness_sample(relative.string())) continue;
    if (!under_invalid_directory(relative) && !is_model_file(entry.path())) continue;  // .bin, .png
    SCOPED_TRACE(relative.string());
    ++checked;
    try {
      Scene scene = import_scene(entry.path().string(), quiet());
      render_small(scene);
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos);
      EXPECT_EQ(message.rfind(entry.path().string(), 0), 0u) << "names the file: " << message;
    }
  }
  EXPECT_GE(checked, 20);
}

// Point clouds (vertices without faces in PLY and OBJ, POINTS primitives in glTF) import as
// Topology::points meshes with their colors, are framed from their positions and drawn whole.
TEST(ImportContent, PointCloudsImportAsPoints) {
  FACET_REQUIRE_PACKAGE(fs::exists(kModels), "assimp-testmodels is not installed");
  const std::string modes = "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_";
  const std::map<std::string, std::size_t> clouds = {
      {"PLY/points.ply", 4},      {"PLY/issue623.ply", 24},  {"OBJ/point_cloud.obj", 3},
      {"OBJ/testpoints.obj", 24}, {modes + "00.gltf", 1024}, {modes + "07.gltf", 1024}};
  for (const auto& [file, count] : clouds) {
    SCOPED_TRACE(file);
    const Scene scene = import_scene((kModels / file).string(), quiet());
    std::size_t points = 0;
    for (const auto& mesh : scene.meshes) {
      EXPECT_EQ(mesh->topology, Topology::points);
      points += mesh->primitive_count();
    }
    EXPECT_EQ(points, count);
    EXPECT_EQ(scene.triangle_count(), 0u);
    const FrameStats stats = render_small(scene);
    EXPECT_EQ(stats.points_drawn, count);  // framing keeps every point in view
    EXPECT_EQ(stats.culled, 0u);
  }
  // points.ply's colors: white, magenta, ... (sRGB 255 and 0 are linear 1 and 0).
  const Scene ply = import_scene((kModels / "PLY/points.ply").string(), quiet());
  ASSERT_EQ(ply.meshes.size(), 1u);
  ASSERT_EQ(ply.meshes[0]->colors.size(), 4u);
  EXPECT_EQ(ply.meshes[0]->colors[0], glm::vec4(1.0f));
  EXPECT_EQ(ply.meshes[0]->colors[1], glm::vec4(1.0f, 0.0f, 1.0f, 1.0f));
}

// A binary PLY of vertices only (the scanner's form): every point, in its colors (sRGB bytes
// made linear), a non-finite one left out with a warning.
TEST(ImportContent, BinaryPlyPointCloudKeepsItsColors) {
  const fs::path file = fresh_test_dir("facet_import_", "binary_points") / "cloud.ply";
  {
    std::ofstream out(file, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
           "property float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
           "property uchar blue\nend_header\n";
    const float nan = std::nanf("");
    const float xyz[3][3] = {{0, 0, 0}, {nan, 1, 0}, {1, 2, 3}};
    const unsigned char rgb[3][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
    for (int i = 0; i < 3; ++i) {  // little-endian floats: this machine's own order
      out.write(reinterpret_cast<const char*>(xyz[i]), sizeof xyz[i]);
      out.write(reinterpret_cast<const char*>(rgb[i]), sizeof rgb[i]);
    }
  }
  std::vector<std::string> warnings;
  ImportOptions options;
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  const Scene scene = import_scene(file.string(), options);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = *scene.meshes[0];
  EXPECT_EQ(mesh.topology, Topology::points);
  ASSERT_EQ(mesh.positions.size(), 2u);
  EXPECT_EQ(mesh.positions[1], glm::vec3(1, 2, 3));
  ASSERT_EQ(mesh.colors.size(), 2u);
  EXPECT_EQ(mesh.colors[0], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(mesh.colors[1], glm::vec4(0, 0, 1, 1));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 points with a non-finite position left out"), std::string::npos);
  EXPECT_EQ(render_small(scene).points_drawn, 2u);
}

// A point cloud whose positions are garbage near the float limit (what a damaged binary PLY
// reads as) is one clear error; its NaN points are left out with a warning first.
TEST(ImportErrors, PointsBeyondWhatAFloatSpansAreOneClearError) {
  const fs::path file = fresh_test_dir("facet_import_", "float_limit") / "garbage.ply";
  {
    std::ofstream out(file, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
           "property float y\nproperty float z\nend_header\n";
    const float xyz[3][3] = {{-3.4e38f, 0, 0}, {std::nanf(""), 0, 0}, {3.4e38f, 1, 0}};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);  // this machine's byte order
  }
  std::vector<std::string> warnings;
  ImportOptions options;
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  try {
    import_scene(file.string(), options);
    FAIL() << "imported";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("positions span more than a float can hold"),
              std::string::npos)
        << e.what();
  }
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 points with a non-finite position left out"), std::string::npos)
      << warnings[0];
}

TEST(ImportErrors, MissingFileIsOneLine) {
  try {
    import_scene("/nonexistent/model.obj");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/model.obj: no such file");
  }
}

TEST(ImportErrors, UnreadableFileNamesAssimpsReason) {
  fs::path file = fs::path(::testing::TempDir()) / "facet_garbage.obj";
  std::ofstream(file) << "f 1 2 3\nthis is not\nan obj file\n";
  try {
    import_scene(file.string(), quiet());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": cannot import: ", 0), 0u) << e.what();
  }
}

// --- content: materials, textures, nodes, cameras ---------------------------------------------

// A cube with a blinn-phong material whose texture is missing, used by two materials.
fs::path write_cube_obj(const fs::path& dir) {
  std::ofstream(dir / "cube.mtl") << "newmtl shiny\nKd 0.8 0.2 0.1\nKs 0.5 0.5 0.5\nNs 64\n"
                                     "map_Kd textures/missing.png\n"
                                     "newmtl dull\nKd 0.3 0.3 0.3\nmap_Kd textures/missing.png\n";
  std::ofstream obj(dir / "cube.obj");
  obj << "mtllib cube.mtl\n";
  for (int i = 0; i < 8; ++i)
    obj << "v " << (i & 1 ? 1 : -1) << " " << (i & 2 ? 1 : -1) << " " << (i & 4 ? 1 : -1) << "\n";
  obj << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  // Faces wound counter-clockwise seen from outside; the last two use the second material.
  const int faces[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                           {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
  for (int f = 0; f < 6; ++f) {
    if (f == 0) obj << "usemtl shiny\n";
    if (f == 4) obj << "usemtl dull\n";
    obj << "f";
    for (int k = 0; k < 4; ++k) obj << " " << faces[f][k] << "/" << k + 1;
    obj << "\n";
  }
  return dir / "cube.obj";
}

TEST(ImportContent, ObjWithMissingTextureWarnsOnceAndRenders) {
  fs::path file = write_cube_obj(fresh_test_dir("facet_import_", "cube"));
  std::vector<std::string> warnings;
  ImportOptions options;
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  Scene scene = import_scene(file.string(), options);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            file.string() + ": texture textures/missing.png is missing; drawing a checker");
  EXPECT_EQ(scene.triangle_count(), 12u);
  ASSERT_GE(scene.materials.size(), 2u);
  auto shiny = std::find_if(scene.materials.begin(), scene.materials.end(),
                            [](const Material& m) { return m.name == "shiny"; });
  ASSERT_NE(shiny, scene.materials.end());
  EXPECT_EQ(shiny->shading, ShadingModel::blinn_phong);
  EXPECT_FLOAT_EQ(shiny->shininess, 64.0f);
  EXPECT_NEAR(shiny->base_color.r, 0.8f, 1e-6f);
  ASSERT_TRUE(shiny->base_color_map);
  EXPECT_EQ(shiny->base_color_map.texture, missing_texture());
  EXPECT_FALSE(scene.has_file_lights);
  EXPECT_EQ(scene.lighting.lights.size(), 3u);  // three-point lights: the file has none
  // A cube keeps its hard edges: 6 faces x 4 corners, each face flat.
  EXPECT_GT(render_small(scene).pixels_shaded, 0u);
  std::size_t vertices = 0;
  for (const auto& mesh : scene.meshes) vertices += mesh->positions.size();
  EXPECT_EQ(vertices, 24u);
}

// A file without lights comes lit, as the command line draws it: three lights around the framing
// view and an ambient term, so a library user's first frame is not a grey silhouette.
TEST(ImportContent, FilesWithoutLightsGetThreePointLights) {
  fs::path file = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  FACET_REQUIRE_PACKAGE(fs::exists(file), "assimp-testmodels is not installed");
  Scene scene = import_scene(file.string());
  ASSERT_FALSE(scene.has_file_lights);
  const std::vector<Light> expected =
      three_point_lights(scene.camera.forward(), scene.camera.right());
  ASSERT_EQ(scene.lighting.lights.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(scene.lighting.lights[i].direction, expected[i].direction);
    EXPECT_EQ(scene.lighting.lights[i].intensity, expected[i].intensity);
  }
  EXPECT_EQ(scene.lighting.ambient, glm::vec3(0.12f));
}

TEST(ImportContent, GltfTexturedBoxIsPbrWithEmbeddedTexture) {
  fs::path file = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  FACET_REQUIRE_PACKAGE(fs::exists(file), "assimp-testmodels is not installed");
  Scene scene = import_scene(file.string());
  ASSERT_FALSE(scene.materials.empty());
  const Material& m = scene.materials[scene.nodes.back().instances.at(0).material];
  EXPECT_EQ(m.shading, ShadingModel::pbr);
  EXPECT_FLOAT_EQ(m.metallic, 0.0f);
  ASSERT_TRUE(m.base_color_map);
  EXPECT_TRUE(m.base_color_map.texture->srgb());
  EXPECT_EQ(m.base_color_map.texture->name(), "embedded:0");
  EXPECT_GT(m.base_color_map.texture->level_count(), 1);
  ASSERT_EQ(scene.textures.size(), 1u);
}

TEST(ImportContent, SpecularGlossinessIsConvertedToMetallicRoughness) {
  fs::path file = kModels / "glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf";
  FACET_REQUIRE_PACKAGE(fs::exists(file), "assimp-testmodels is not installed");
  Scene scene = import_scene(file.string());
  const Material& m = scene.materials[scene.nodes.back().instances.at(0).material];
  EXPECT_EQ(m.shading, ShadingModel::pbr);
  // specularFactor 0.2 grey, glossiness 1, diffuse white: a mostly dielectric, glossy surface.
  EXPECT_NEAR(m.roughness, 0.0f, 1e-6f);
  EXPECT_GT(m.metallic, 0.0f);
  EXPECT_LT(m.metallic, 0.5f);
  EXPECT_TRUE(m.base_color_map);
}

TEST(ImportContent, TextureTransformAndNestedNodes) {
  fs::path file = kModels / "glTF2/textureTransform/TextureTransformTest.gltf";
  FACET_REQUIRE_PACKAGE(fs::exists(file), "assimp-testmodels is not installed");
  Scene scene = import_scene(file.string());
  auto node = [&](const std::string& name) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
      if (scene.nodes[i].name == name) return static_cast<int>(i);
    }
    return -1;
  };
  // "Rotation - Correct" (translation, scale 0.15) is a child of "Rotation" (translation).
  const int child = node("Rotation - Correct"), parent = node("Rotation");
  ASSERT_GE(child, 0);
  ASSERT_GE(parent, 0);
  EXPECT_EQ(scene.nodes[child].parent, parent);
  glm::mat4 world = scene.world_transform(child);
  EXPECT_NEAR(world[3].x, -1.1f - 0.07904822f, 1e-5f);
  EXPECT_NEAR(world[3].y, -0.55f - 0.51626749f, 1e-5f);
  EXPECT_NEAR(world[3].z, 0.01f, 1e-6f);
  EXPECT_NEAR(world[0].x, 0.15f, 1e-6f);
  // "Offset U": KHR_texture_transform offset (0.5, 0) moves u by 0.5 and leaves v alone.
  auto offset_u = std::find_if(scene.materials.begin(), scene.materials.end(),
                               [](const Material& m) { return m.name == "Offset U"; });
  ASSERT_NE(offset_u, scene.materials.end());
  glm::vec3 uv = offset_u->base_color_map.transform * glm::vec3(0.25f, 0.25f, 1.0f);
  EXPECT_NEAR(uv.x, 0.75f, 1e-5f);
  EXPECT_NEAR(uv.y, 0.25f, 1e-5f);
  EXPECT_EQ(offset_u->base_color_map.sampler.wrap_u, Wrap::clamp_to_edge);
  EXPECT_EQ(offset_u->base_color_map.sampler.filter, Filter::bilinear);  // minFilter LINEAR
  // "All": offset (-0.2, -0.1), rotation 0.3, scale 1.5, defined with v pointing down; facet's
  // v points up, so the expected transform is glTF's conjugated by v -> 1 - v.
  auto all = std::find_if(scene.materials.begin(), scene.materials.end(),
                          [](const Material& m) { return m.name == "All"; });
  ASSERT_NE(all, scene.materials.end());
  const float c = std::cos(0.3f), s = std::sin(0.3f);
  for (glm::vec2 p : {glm::vec2(0.1f, 0.2f), glm::vec2(0.9f, 0.6f)}) {
    glm::vec2 g(p.x, 1.0f - p.y);  // to glTF's v-down
    g *= 1.5f;
    g = glm::vec2(c * g.x + s * g.y, -s * g.x + c * g.y) + glm::vec2(-0.2f, -0.1f);
    glm::vec3 got = all->base_color_map.transform * glm::vec3(p, 1.0f);
    EXPECT_NEAR(got.x, g.x, 1e-5f);
    EXPECT_NEAR(got.y, 1.0f - g.y, 1e-5f);
  }
}

TEST(ImportContent, RowMajorMatricesBecomeColumnMajor) {
  // BoxTextured.gltf: the root's matrix turns +Y into -Z; the box hangs below it.
  fs::path file = kModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf";
  FACET_REQUIRE_PACKAGE(fs::exists(file), "assimp-testmodels is not installed");
  Scene scene = import_scene(file.string());
  int mesh_node = -1;
  for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
    if (!scene.nodes[i].instances.empty()) mesh_node = static_cast<int>(i);
  }
  ASSERT_GE(mesh_node, 0);
  ASSERT_GE(scene.nodes[mesh_node].parent, 0);
  glm::mat4 world = scene.world_transform(mesh_node);
  EXPECT_EQ(world[1], glm::vec4(0, 0, -1, 0));  // glTF column 1 of the matrix
  EXPECT_EQ(world[2], glm::vec4(0, 1, 0, 0));
}

TEST(ImportContent, CameraFromTheFile) {
  fs::path file = kModels / "glTF2/cameras/Cameras.gltf";
  FACET_REQUIRE_PACKAGE(fs::exists(file), "assimp-testmodels is not installed");
  std::vector<std::string> warnings;
  ImportOptions options;
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  Scene scene = import_scene(file.string(), options);
  // Camera 0: perspective, yfov 0.7 rad, aspect 1, at its node's translation (0.5, 0.5, 3).
  // Camera 1: orthographic, xmag = ymag = 1 (half sizes), at the same place.
  ASSERT_EQ(scene.cameras.size(), 2u);
  EXPECT_TRUE(warnings.empty()) << warnings[0];
  for (const Camera& c : scene.cameras) {
    EXPECT_NEAR(c.eye.x, 0.5f, 1e-5f);
    EXPECT_NEAR(c.eye.y, 0.5f, 1e-5f);
    EXPECT_NEAR(c.eye.z, 3.0f, 1e-5f);
    EXPECT_NEAR(glm::length(c.forward() - glm::vec3(0, 0, -1)), 0.0f, 1e-5f);
    EXPECT_FLOAT_EQ(c.aspect, 1.0f);
    EXPECT_FLOAT_EQ(c.near_plane, 0.01f);
    EXPECT_FLOAT_EQ(c.far_plane, 100.0f);
    EXPECT_NO_THROW(c.validate());
  }
  EXPECT_EQ(scene.cameras[0].projection_kind, Projection::perspective);
  EXPECT_NEAR(scene.cameras[0].fov_y_degrees, glm::degrees(0.7f), 1e-3f);
  EXPECT_EQ(scene.cameras[1].projection_kind, Projection::orthographic);
  EXPECT_FLOAT_EQ(scene.cameras[1].view_height, 2.0f);
}

// A glTF orthographic camera wider than tall: xmag 2, ymag 1 are half sizes, so the view is
// 4 x 2 scene units (aspect 2).
TEST(ImportContent, OrthographicCameraKeepsItsSize) {
  const fs::path dir = fresh_test_dir("facet_import_", "orthographic");
  std::ofstream(dir / "ortho.gltf") << R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0, 1]}],
  "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 5]}],
  "cameras": [{"type": "orthographic",
               "orthographic": {"xmag": 2.0, "ymag": 1.0, "znear": 0.5, "zfar": 20}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "buffers": [{"byteLength": 36,
    "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]
})";
  Scene scene = import_scene((dir / "ortho.gltf").string(), quiet());
  ASSERT_EQ(scene.cameras.size(), 1u);
  const Camera& c = scene.cameras[0];
  EXPECT_EQ(c.projection_kind, Projection::orthographic);
  EXPECT_FLOAT_EQ(c.aspect, 2.0f);
  EXPECT_FLOAT_EQ(c.view_height, 2.0f);
  EXPECT_FLOAT_EQ(c.near_plane, 0.5f);
  EXPECT_FLOAT_EQ(c.far_plane, 20.0f);
  EXPECT_NEAR(c.eye.z, 5.0f, 1e-5f);
  EXPECT_NO_THROW(c.validate());
}

TEST(ImportContent, GlmarkBunnyLoadsWithSmoothNormalsQuickly) {
  FACET_REQUIRE_PACKAGE(fs::exists(kBunny), "glmark2-data is not installed");
  auto start = std::chrono::steady_clock::now();
  Scene scene = import_scene(kBunny.string());
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(scene.triangle_count(), 69666u);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = *scene.meshes[0];
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
  // Smooth: the 34835 positions are split only along the few creases sharper than 80 degrees.
  EXPECT_LT(mesh.positions.size(), 34835u * 102 / 100);
  // Smooth also means neighbouring corners agree: most triangles' corner normals are close.
  std::size_t smooth = 0;
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    glm::vec3 a = mesh.normals[mesh.indices[i]], b = mesh.normals[mesh.indices[i + 1]];
    if (glm::dot(a, b) > 0.9f) ++smooth;
  }
  EXPECT_GT(smooth, mesh.indices.size() / 3 * 9 / 10);
  // A bound that catches a pass quadratic in the vertices (minutes here), not a speed claim: a
  // busy machine under a sanitizer must not fail it.
  EXPECT_LT(seconds, 20.0);
}

// --- compute_smooth_normals and compute_tangents ----------------------------------------------

Mesh unit_cube_soup() {  // 12 triangles, 36 unindexed vertices, counter-clockwise from outside
  Mesh mesh;
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  auto corner = [](int i) {
    return glm::vec3(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f);
  };
  for (const auto& f : faces) {
    for (int k : {0, 1, 2, 0, 2, 3}) mesh.positions.push_back(corner(f[k]));
  }
  return mesh;
}

TEST(SmoothNormals, CubeKeepsHardEdgesAndIsIndexed) {
  Mesh mesh = unit_cube_soup();
  compute_smooth_normals(mesh, 80.0f);
  EXPECT_EQ(mesh.positions.size(), 24u);  // 8 corners x 3 faces: split at every 90-degree edge
  ASSERT_EQ(mesh.indices.size(), 36u);
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::vec3* p = &mesh.positions[0];
    glm::vec3 face = glm::normalize(glm::cross(p[mesh.indices[i + 1]] - p[mesh.indices[i]],
                                               p[mesh.indices[i + 2]] - p[mesh.indices[i]]));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(glm::dot(mesh.normals[mesh.indices[i + k]], face), 1.0f, 1e-6f);
    }
  }
}

TEST(SmoothNormals, WideCreaseSmoothsTheCubeCorners) {
  Mesh mesh = unit_cube_soup();
  compute_smooth_normals(mesh, 100.0f);
  EXPECT_EQ(mesh.positions.size(), 8u);
  // Area weighting counts each triangle: a corner touching both triangles of a face leans
  // toward that face, so the normals are near the diagonal rather than on it.
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_GT(glm::dot(mesh.normals[i], glm::normalize(mesh.positions[i])), 0.94f);
  }
}

TEST(SmoothNormals, AreaWeightedAndDegenerateFacesIgnored) {
  // Two triangles sharing vertex 0 at a shallow angle (within the crease), the first with four
  // times the area; plus a zero-area triangle that must not disturb anything.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, 0, 0.2f}, {0, -1, 0}, {1, 0, 0}};
  mesh.indices = {0, 1, 2, 0, 3, 4, 0, 5, 1};
  compute_smooth_normals(mesh, 80.0f);
  glm::vec3 big = glm::cross(glm::vec3(2, 0, 0), glm::vec3(0, 2, 0));
  glm::vec3 small = glm::cross(glm::vec3(-1, 0, 0.2f), glm::vec3(0, -1, 0));
  glm::vec3 expected = glm::normalize(big + small);
  EXPECT_NEAR(glm::dot(mesh.normals[mesh.indices[0]], expected), 1.0f, 1e-6f);
  for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

TEST(SmoothNormals, KeepsOtherAttributesAndSplitsUvSeamsOnlyForUv) {
  // A flat quad whose two triangles carry different uvs at the shared corners (a seam):
  // the normals agree, the uvs stay apart.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0.5f, 0}, {1, 1}, {0, 1}};
  mesh.colors.assign(6, glm::vec4(0.5f));
  compute_smooth_normals(mesh);
  EXPECT_EQ(mesh.positions.size(), 5u);  // the two (1,1,0) corners are identical: welded
  EXPECT_EQ(mesh.texcoords.size(), 5u);
  EXPECT_EQ(mesh.colors.size(), 5u);
  for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

// --- join_identical_vertices -----------------------------------------------------------------

// Corner k of triangle t: every attribute, for comparing meshes triangle by triangle.
struct Corner {
  glm::vec3 position, normal;
  glm::vec2 texcoord;
  bool operator==(const Corner&) const = default;
};
Corner corner_of(const Mesh& mesh, std::size_t t, int k) {
  const std::size_t i = mesh.indices.empty() ? 3 * t + k : mesh.indices[3 * t + k];
  return {mesh.positions[i], mesh.normals[i],
          mesh.texcoords.empty() ? glm::vec2(-1.0f) : mesh.texcoords[i]};
}

TEST(JoinIdenticalVertices, JoinsOnlyIdenticalCornersAndKeepsEveryTriangle) {
  Mesh mesh = unit_cube_soup();  // 36 corners, one normal per face
  for (std::size_t i = 0; i < mesh.positions.size(); i += 6) {
    const glm::vec3* p = &mesh.positions[i];
    const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    for (int k = 0; k < 6; ++k) mesh.normals.push_back(n);
  }
  mesh.texcoords.assign(36, glm::vec2(0.25f));
  mesh.texcoords[3] = glm::vec2(0.5f);  // the first face's second triangle: a uv seam corner
  const Mesh before = mesh;
  join_identical_vertices(mesh);
  // Each face's 4 corners, plus the seam corner that differs from its twin only in uv.
  EXPECT_EQ(mesh.positions.size(), 25u);
  EXPECT_EQ(mesh.normals.size(), 25u);
  EXPECT_EQ(mesh.texcoords.size(), 25u);
  ASSERT_EQ(mesh.indices.size(), 36u);
  for (std::size_t t = 0; t < 12; ++t) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(corner_of(mesh, t, k), corner_of(before, t, k)) << "triangle " << t;
    }
  }
  // An indexed mesh keeps its triangles too, and joining twice changes nothing more.
  const Mesh joined = mesh;
  join_identical_vertices(mesh);
  EXPECT_EQ(mesh.positions, joined.positions);
  EXPECT_EQ(mesh.indices, joined.indices);
}

TEST(ImportContent, ModelsWithNormalsAreIndexedWithTheirCornersKept) {
  const fs::path path = kModels / "OBJ" / "WusonOBJ.obj";  // v, vt and vn, 3732 faces
  FACET_REQUIRE_PACKAGE(fs::exists(path), "assimp-testmodels is not installed");
  Scene scene = import_scene(path.string());
  std::size_t vertices = 0, corners = 0;
  for (const auto& mesh : scene.meshes) {
    ASSERT_FALSE(mesh->indices.empty());
    ASSERT_EQ(mesh->normals.size(), mesh->positions.size());
    vertices += mesh->positions.size();
    corners += mesh->indices.size();
  }
  EXPECT_GT(corners, 3 * vertices) << "each vertex is shared by several corners";
}

TEST(Tangents, FollowUAndHandedness) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.normals.assign(4, glm::vec3(0, 0, 1));
  mesh.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  Mesh mirrored = mesh;
  for (glm::vec2& uv : mirrored.texcoords) uv.x = 1.0f - uv.x;  // u runs along -x
  compute_tangents(mesh);
  compute_tangents(mirrored);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(glm::distance(glm::vec3(mesh.tangents[i]), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(mesh.tangents[i].w, 1.0f);
    EXPECT_NEAR(glm::distance(glm::vec3(mirrored.tangents[i]), glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(mirrored.tangents[i].w, -1.0f);
  }
}

TEST(Tangents, WithoutUvArePerpendicularToTheNormal) {
  Mesh mesh = unit_cube_soup();
  compute_tangents(mesh);  // no normals either: smooth normals come first
  ASSERT_EQ(mesh.tangents.size(), mesh.positions.size());
  for (std::size_t i = 0; i < mesh.tangents.size(); ++i) {
    EXPECT_NEAR(glm::dot(glm::vec3(mesh.tangents[i]), mesh.normals[i]), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(mesh.tangents[i])), 1.0f, 1e-6f);
    EXPECT_EQ(mesh.tangents[i].w, 1.0f);
  }
}

}  // namespace
}  // namespace facet::test
