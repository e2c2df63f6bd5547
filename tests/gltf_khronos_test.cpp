// The glTF 2.0 reader on Khronos's own sample models (tests/data/khronos, listed with their
// sources and licenses in its README.md), each for the feature it was made to show: every
// primitive mode, morph targets and skins posed at a time, a sparse accessor, and a file's
// perspective and orthographic cameras. Expected values come from the models' data and READMEs,
// worked out in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "support/gltf_builder.hpp"
#include "support/render_helpers.hpp"
#include "support/world_positions.hpp"

namespace facet::test {
namespace {

std::filesystem::path khronos(const std::string& name) {
  return std::filesystem::path(FACET_KHRONOS_DIR) / (name + ".gltf");
}

ImportOptions at_time(double seconds) {
  ImportOptions options;
  options.time = seconds;
  return options;
}

// Whether some position is within 1e-4 of `want`.
bool has_position(const std::vector<glm::vec3>& positions, glm::vec3 want) {
  return std::any_of(positions.begin(), positions.end(),
                     [&](glm::vec3 p) { return glm::length(p - want) < 1e-4f; });
}

// MeshPrimitiveModes: seven nodes, each one mode over the same hexagon (centre 0, corners 1 to 6
// counter-clockwise from the lower right). Each node's primitive count, by where it is placed.
TEST(GltfKhronos, MeshPrimitiveModesDrawsEachModeWithItsCount) {
  const ImportedGltf got = import_gltf(khronos("MeshPrimitiveModes"));
  const Scene& scene = got.scene;
  // (x, y) of the node -> (topology, primitives): POINTS [0..6] 7 points; LINES 6 spokes;
  // LINE_LOOP [0..6] 7 segments (closed); LINE_STRIP [0..6] 6; TRIANGLES 6; TRIANGLE_STRIP
  // [2, 3, 1, 4, 6, 5] 4; TRIANGLE_FAN [0, 1, ..., 6, 1] 6.
  const std::map<std::pair<int, int>, std::pair<Topology, std::size_t>> want = {
      {{0, 3}, {Topology::points, 7}},      {{-2, 0}, {Topology::lines, 6}},
      {{0, 0}, {Topology::lines, 7}},       {{2, 0}, {Topology::lines, 6}},
      {{-2, -3}, {Topology::triangles, 6}}, {{0, -3}, {Topology::triangles, 4}},
      {{2, -3}, {Topology::triangles, 6}}};
  std::map<std::pair<int, int>, std::pair<Topology, std::size_t>> seen;
  for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
    if (scene.nodes[n].instances.empty()) continue;
    const glm::mat4 world = scene.world_transform(static_cast<int>(n));
    const std::pair<int, int> at = {static_cast<int>(world[3].x), static_cast<int>(world[3].y)};
    const Mesh& mesh = *scene.meshes.at(scene.nodes[n].instances[0].mesh);
    const std::size_t count = mesh.topology == Topology::points  ? mesh.positions.size()
                              : mesh.topology == Topology::lines ? mesh.indices.size() / 2
                                                                 : mesh.indices.size() / 3;
    seen[at] = {mesh.topology, count};
    // Every triangle of the three filled hexagons faces the viewer (+Z), as the file's
    // counter-clockwise corners do: strips alternate their order, fans turn about vertex 0.
    if (mesh.topology != Topology::triangles) continue;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                      c = mesh.positions[mesh.indices[i + 2]];
      EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f)
          << "triangle " << i / 3 << " of the node at " << at.first << ", " << at.second;
    }
  }
  EXPECT_EQ(seen, want);
}

// SimpleMorph: a triangle (0, 0), (1, 0), (0.5, 0.5) whose top vertex target 0 moves by (-1, 1)
// and target 1 by (1, 1). The mesh's weights are 0.5 and 0.5; the animation's keys at t = 0, 1,
// 2, 3, 4 are (0, 0), (0, 1), (1, 1), (1, 0), (0, 0).
TEST(GltfKhronos, SimpleMorphAtRestAndAtTimes) {
  const struct {
    std::optional<double> time;
    glm::vec3 top;
  } cases[] = {{std::nullopt, {0.5f, 1.5f, 0}},  // the mesh's weights 0.5, 0.5
               {0.5, {1.0f, 1.0f, 0}},           // halfway to (0, 1): weights 0, 0.5
               {1.0, {1.5f, 1.5f, 0}},           // (0, 1)
               {2.0, {0.5f, 2.5f, 0}},           // (1, 1)
               {3.0, {-0.5f, 1.5f, 0}}};         // (1, 0)
  for (const auto& c : cases) {
    ImportOptions options;
    options.time = c.time;
    const std::vector<glm::vec3> p =
        world_positions(import_gltf(khronos("SimpleMorph"), options).scene);
    ASSERT_EQ(p.size(), 3u);
    const std::string when = c.time ? "at t = " + std::to_string(*c.time) : "at rest";
    EXPECT_TRUE(has_position(p, c.top)) << when;
    EXPECT_TRUE(has_position(p, {0, 0, 0}) && has_position(p, {1, 0, 0})) << when;
  }
}

// SimpleSkin: a strip 1 wide from y = 0 to 2 on joints 1 (at y = 0, the root) and 2 (at y = 1);
// the top row (y = 2) follows joint 2 alone, the bottom row joint 1 alone. At t = 1 the
// animation has turned joint 2 by 90 degrees about +Z, so the top row, turned about (0, 1),
// lies at x = -1: (-0.5, 2) goes to (-1, 0.5) and (0.5, 2) to (-1, 1.5).
TEST(GltfKhronos, SimpleSkinBendsAtItsUpperJoint) {
  const std::vector<glm::vec3> rest = world_positions(import_gltf(khronos("SimpleSkin")).scene);
  ASSERT_EQ(rest.size(), 10u);
  EXPECT_TRUE(has_position(rest, {-0.5f, 2, 0}) && has_position(rest, {0.5f, 2, 0}));
  const std::vector<glm::vec3> bent =
      world_positions(import_gltf(khronos("SimpleSkin"), at_time(1.0)).scene);
  ASSERT_EQ(bent.size(), 10u);
  EXPECT_TRUE(has_position(bent, {-1, 0.5f, 0}));
  EXPECT_TRUE(has_position(bent, {-1, 1.5f, 0}));
  EXPECT_TRUE(has_position(bent, {-0.5f, 0, 0}) && has_position(bent, {0.5f, 0, 0}));  // still
}

// RiggedSimple (COLLADA2GLTF): a tube along the bind space's Z, 1 wide at the foot and 0.45 at
// the top, on two joints under a Z-up-to-Y-up root matrix, the skeleton beside the mesh node. At
// rest it stands along Y from -4.575 to 4.575. At the animation's second key (t = 1.0417) the
// upper joint leans back: the highest vertex, bind (0, -0.45, 4.575), is at (0, 4.048, -2.211)
// and the tube reaches z = -2.955 (worked out from the file's matrices and keys with a
// script of its own).
TEST(GltfKhronos, RiggedSimpleLeansAtItsSecondKey) {
  const Bounds rest = import_gltf(khronos("RiggedSimple")).scene.bounds();
  EXPECT_NEAR(glm::length(rest.min - glm::vec3(-1, -4.575f, -1)), 0.0f, 2e-3f);
  EXPECT_NEAR(glm::length(rest.max - glm::vec3(1, 4.575f, 1)), 0.0f, 2e-3f);
  const Scene leaning = import_gltf(khronos("RiggedSimple"), at_time(1.0416669845581055)).scene;
  const Bounds bounds = leaning.bounds();
  EXPECT_NEAR(glm::length(bounds.min - glm::vec3(-1, -4.5751f, -2.9545f)), 0.0f, 2e-3f);
  EXPECT_NEAR(glm::length(bounds.max - glm::vec3(1, 4.0479f, 1)), 0.0f, 2e-3f);
  const std::vector<glm::vec3> p = world_positions(leaning);
  EXPECT_TRUE(std::any_of(p.begin(), p.end(), [](glm::vec3 q) {
    return glm::length(q - glm::vec3(0, 4.0479f, -2.2114f)) < 2e-3f;
  }));
}

// AnimatedModel poses from the file read once: the same world positions as importing the file
// again at each time, its length that of the animation's keys, and no reading of the file after
// it is made (the test moves the file away before posing).
TEST(GltfKhronos, AnimatedModelPosesAsImportAtEveryTimeWithoutTheFile) {
  const std::filesystem::path dir = fresh_test_dir("facet_animated_", "posing");
  for (const char* name : {"SimpleSkin", "RiggedSimple", "SimpleMorph"}) {
    SCOPED_TRACE(name);
    const std::filesystem::path copy = dir / (std::string(name) + ".gltf");
    std::filesystem::copy_file(khronos(name), copy);
    const AnimatedModel model(copy.string());
    EXPECT_EQ(model.animation_count(), 1);
    std::vector<std::vector<glm::vec3>> imported;
    const double times[] = {0.0, 0.37, 1.0, 2.5};
    for (double t : times)
      imported.push_back(world_positions(import_scene(copy.string(), at_time(t))));
    std::filesystem::remove(copy);
    for (std::size_t i = 0; i < std::size(times); ++i) {
      EXPECT_EQ(world_positions(model.pose(times[i])), imported[i]) << "t = " << times[i];
    }
    EXPECT_NE(imported[0], imported[2]) << "the pose moves";
  }
  // SimpleSkin's keys run from 0 to 5.5 s.
  std::filesystem::copy_file(khronos("SimpleSkin"), dir / "skin.gltf");
  EXPECT_DOUBLE_EQ(AnimatedModel((dir / "skin.gltf").string()).duration(), 5.5);
}

TEST(GltfKhronos, AnimatedModelRefusesOtherFormatsAndMissingAnimations) {
  const std::filesystem::path dir = fresh_test_dir("facet_animated_", "refused");
  std::filesystem::copy_file(khronos("SimpleSkin"), dir / "skin.gltf");
  ImportOptions second;
  second.animation = 1;
  try {
    AnimatedModel((dir / "skin.gltf").string(), second);
    ADD_FAILURE() << "animation 1 of a file with one";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("animation 1 does not exist"), std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "tetra.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_THROW(AnimatedModel((dir / "tetra.obj").string()), Error);
}

// SimpleSparseAccessor: a strip of 12 triangles along y = 0 .. 1, x = 0 .. 6, whose sparse
// accessor lifts vertices 8, 10 and 12 to (1, 2), (3, 3) and (5, 4): without it the strip would
// stay 1 high.
TEST(GltfKhronos, SimpleSparseAccessorLiftsThreeVertices) {
  const Scene scene = import_gltf(khronos("SimpleSparseAccessor")).scene;
  EXPECT_EQ(scene.triangle_count(), 12u);
  const Bounds bounds = scene.bounds();
  EXPECT_NEAR(glm::length(bounds.min - glm::vec3(0, 0, 0)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(bounds.max - glm::vec3(6, 4, 0)), 0.0f, 1e-5f);
  const std::vector<glm::vec3> p = world_positions(scene);
  for (glm::vec3 lifted : {glm::vec3(1, 2, 0), glm::vec3(3, 3, 0), glm::vec3(5, 4, 0)})
    EXPECT_TRUE(has_position(p, lifted)) << lifted.x;
  EXPECT_FALSE(has_position(p, {1, 1, 0}));  // vertex 8's place before the substitution
}

// Cameras: a unit quad turned -45 degrees about X (y' = 0.707 y, z' = -0.707 y), seen by
// a perspective camera (yfov 0.7 rad, aspect 1) and an orthographic one (xmag = ymag = 1), both
// at (0.5, 0.5, 3) looking down -Z.
TEST(GltfKhronos, CamerasAreReadAndDrawnThrough) {
  const Scene scene = import_gltf(khronos("Cameras")).scene;
  EXPECT_EQ(scene.triangle_count(), 2u);
  const Bounds bounds = scene.bounds();
  EXPECT_NEAR(glm::length(bounds.min - glm::vec3(0, 0, -0.7071f)), 0.0f, 2e-3f);
  EXPECT_NEAR(glm::length(bounds.max - glm::vec3(1, 0.7071f, 0)), 0.0f, 2e-3f);
  ASSERT_EQ(scene.cameras.size(), 2u);
  const Camera& perspective = scene.cameras[0];
  EXPECT_EQ(perspective.projection_kind, Projection::perspective);
  EXPECT_NEAR(perspective.fov_y_degrees, glm::degrees(0.7f), 1e-3f);
  EXPECT_NEAR(perspective.aspect, 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(perspective.eye - glm::vec3(0.5f, 0.5f, 3)), 0.0f, 1e-5f);
  const Camera& orthographic = scene.cameras[1];
  EXPECT_EQ(orthographic.projection_kind, Projection::orthographic);
  EXPECT_NEAR(orthographic.view_height, 2.0f, 1e-6f);
  EXPECT_NEAR(glm::length(orthographic.eye - glm::vec3(0.5f, 0.5f, 3)), 0.0f, 1e-5f);

  // Through the orthographic camera, 96x54: 27 pixels a unit, the image's centre row at y = 0.5.
  // The quad's top edge (y = 0.707) is at row 27 - 0.207 x 27 = 21.4 and its bottom (y = 0) at
  // row 27 + 0.5 x 27 = 40.5: rows 10 and 48 show the blue background, rows 25 to 38 at the
  // centre the grey quad.
  const std::filesystem::path dir = fresh_test_dir("gltf_khronos_", "cameras");
  const std::string png = (dir / "ortho.png").string();
  const CommandResult run =
      run_command(std::string(FACET_CLI) + " render '" + khronos("Cameras").string() +
                  "' --camera 1 --size 96x54 -q -o '" + png + "'");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const Rgba8Image image = read_png(png);
  ASSERT_EQ(image.width, 96);
  auto rgb = [&](int x, int y) {
    const std::uint8_t* p = &image.pixels[static_cast<std::size_t>(y * image.width + x) * 4];
    return glm::ivec3(p[0], p[1], p[2]);
  };
  for (int y : {10, 48}) {
    const glm::ivec3 sky = rgb(48, y);
    EXPECT_GT(sky.b - sky.r, 50) << "row " << y << " should be the background";
  }
  for (int y : {25, 30, 38}) {
    const glm::ivec3 quad = rgb(48, y);
    EXPECT_LT(std::abs(quad.b - quad.r), 20) << "row " << y << " should be the grey quad";
  }
  // 27 pixels a unit across too: the quad's x = 0 .. 1 is columns 34.5 .. 61.5.
  EXPECT_GT(rgb(30, 30).b - rgb(30, 30).r, 50);
  EXPECT_GT(rgb(66, 30).b - rgb(66, 30).r, 50);
}

}  // namespace
}  // namespace facet::test
