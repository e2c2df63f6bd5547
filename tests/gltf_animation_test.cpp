// The glTF 2.0 reader's poses on models the tests write (support/gltf_builder.hpp): morph
// targets at their default weights, skins, nested skeletons, and animations sampled at a time
// with each interpolation (ImportOptions::time and ::animation). Expected values are worked out
// by hand in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "support/gltf_builder.hpp"
#include "support/world_positions.hpp"

namespace facet::test {
namespace {

using nlohmann::json;

ImportOptions at_time(double seconds, int animation = 0) {
  ImportOptions options;
  options.time = seconds;
  options.animation = animation;
  return options;
}

void expect_near(glm::vec3 got, glm::vec3 want, const std::string& what) {
  EXPECT_NEAR(glm::length(got - want), 0.0f, 1e-4f)
      << what << ": got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x
      << ", " << want.y << ", " << want.z << ")";
}

// --- morph targets ------------------------------------------------------------------------

// The unit quad with one target lifting its top edge (vertices 2 and 3) by 1 in y and tilting
// their normals toward +Y.
json morph_quad(GltfBuilder& b) {
  json primitive = unit_quad(b);
  const int lift = b.vec3s({{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}});
  const int tilt = b.vec3s({{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}});
  primitive["targets"] = {{{"POSITION", lift}, {"NORMAL", tilt}}};
  return primitive;
}

TEST(GltfPose, MorphTargetAtTheMeshDefaultWeights) {
  for (float weight : {0.0f, 0.5f, 1.0f}) {
    GltfBuilder b;
    b.add_mesh_node(morph_quad(b));
    b.json["meshes"][0]["weights"] = {weight};
    const std::string name = "morph_" + std::to_string(static_cast<int>(weight * 10));
    const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir(name) / "m.gltf"));
    const Mesh& mesh = mesh_of(got.scene);
    ASSERT_EQ(mesh.positions.size(), 4u);
    // Vertex 2 is (1, 1, 0) plus weight x (0, 1, 0); vertex 0 does not move.
    expect_near(mesh.positions[2], {1, 1 + weight, 0}, "vertex 2 at weight " + name);
    expect_near(mesh.positions[0], {0, 0, 0}, "vertex 0");
    // Its normal (0, 0, 1) + weight (0, 1, 0), renormalized.
    expect_near(mesh.normals[2], glm::normalize(glm::vec3(0, weight, 1)), "normal 2 " + name);
  }
}

TEST(GltfPose, NodeWeightsOverrideTheMeshAndEachNodeGetsItsOwnMesh) {
  GltfBuilder b;
  b.add_mesh_node(morph_quad(b));
  b.json["meshes"][0]["weights"] = {1.0};
  b.json["nodes"].push_back({{"mesh", 0}, {"weights", {0.25}}, {"translation", {3, 0, 0}}});
  b.json["scenes"][0]["nodes"].push_back(1);
  const ImportedGltf got = import_gltf(b.write_gltf(gltf_test_dir("morph_nodes") / "m.gltf"));
  ASSERT_EQ(got.scene.meshes.size(), 2u);
  const Mesh& first = *got.scene.meshes[got.scene.nodes[0].instances.at(0).mesh];
  const Mesh& second = *got.scene.meshes[got.scene.nodes[1].instances.at(0).mesh];
  EXPECT_NEAR(first.positions[3].y, 2.0f, 1e-6f);
  EXPECT_NEAR(second.positions[3].y, 1.25f, 1e-6f);
}

TEST(GltfPose, WeightsAnimatedLinearlyAndAtRestWithoutATime) {
  GltfBuilder b;
  const int node = b.add_mesh_node(morph_quad(b));
  b.animate(node, "weights", {0, 2}, {0, 1});
  const auto path = b.write_gltf(gltf_test_dir("morph_animated") / "m.gltf");
  // t = 0.5 of keys 0 .. 2: weight 0.25, vertex 2 at y 1.25.
  EXPECT_NEAR(mesh_of(import_gltf(path, at_time(0.5)).scene).positions[2].y, 1.25f, 1e-6f);
  // No time: the default weights (none given: 0), not the animation's first key.
  EXPECT_NEAR(mesh_of(import_gltf(path).scene).positions[2].y, 1.0f, 1e-6f);
}

// Three and four morph targets: a weights channel's keys are that many scalars each, not one
// VEC3 or VEC4 (AnimatedMorphSphere-like files with several targets were refused). Target t
// lifts vertex 2 by t + 1 in y; the weights go from all 0 at t = 0 to all 1 at t = 2.
TEST(GltfPose, WeightsChannelOfThreeAndFourTargets) {
  for (int targets : {2, 3, 4, 5}) {
    GltfBuilder b;
    json primitive = unit_quad(b);
    float lift = 0.0f;
    for (int t = 0; t < targets; ++t) {
      const float dy = static_cast<float>(t + 1);
      primitive["targets"].push_back(
          {{"POSITION", b.vec3s({{0, 0, 0}, {0, 0, 0}, {0, dy, 0}, {0, 0, 0}})}});
      lift += dy;
    }
    const int node = b.add_mesh_node(primitive);
    std::vector<float> keys(static_cast<std::size_t>(targets), 0.0f);
    keys.resize(static_cast<std::size_t>(2 * targets), 1.0f);
    b.animate(node, "weights", {0, 2}, keys);
    const auto path = b.write_gltf(gltf_test_dir("morph_" + std::to_string(targets)) / "m.gltf");
    // t = 0.5: every weight 0.25, vertex 2 at y = 1 + 0.25 x (1 + 2 + ... + targets).
    EXPECT_NEAR(mesh_of(import_gltf(path, at_time(0.5)).scene).positions[2].y, 1 + 0.25f * lift,
                1e-5f)
        << targets << " targets";
  }
}

// --- animation sampling -------------------------------------------------------------------

// A quad whose node's x translation is keyed 0 at t = 1, 10 at t = 2, 30 at t = 4.
std::filesystem::path translated_quad(const std::string& name, const std::string& interpolation,
                                      std::vector<float> values = {0, 0, 0, 10, 0, 0, 30, 0, 0}) {
  GltfBuilder b;
  const int node = b.add_mesh_node(unit_quad(b));
  b.animate(node, "translation", {1, 2, 4}, values, interpolation);
  return b.write_gltf(gltf_test_dir(name) / "t.gltf");
}

float x_at(const std::filesystem::path& path, double t) {
  return import_gltf(path, at_time(t)).scene.nodes.at(0).transform[3].x;
}

TEST(GltfPose, TranslationLinearBetweenKeysClampedOutside) {
  const auto path = translated_quad("linear", "LINEAR");
  EXPECT_NEAR(x_at(path, 0.0), 0.0f, 1e-5f);     // before the first key: the first value
  EXPECT_NEAR(x_at(path, 1.5), 5.0f, 1e-5f);     // halfway from 0 to 10
  EXPECT_NEAR(x_at(path, 3.0), 20.0f, 1e-5f);    // halfway from 10 to 30
  EXPECT_NEAR(x_at(path, 100.0), 30.0f, 1e-5f);  // after the last: the last value
}

TEST(GltfPose, TranslationStepHoldsUntilTheNextKey) {
  const auto path = translated_quad("step", "STEP");
  EXPECT_NEAR(x_at(path, 1.999), 0.0f, 1e-6f);  // still key 0's value
  EXPECT_NEAR(x_at(path, 2.0), 10.0f, 1e-6f);   // at a key: that key's value
  EXPECT_NEAR(x_at(path, 3.9), 10.0f, 1e-6f);
  EXPECT_NEAR(x_at(path, 4.0), 30.0f, 1e-6f);
}

TEST(GltfPose, TranslationCubicSplineUsesTheTangents) {
  // Keys (in-tangent, value, out-tangent): t = 1 (_, 0, 4); t = 2 (8, 10, _); t = 4 (_, 30, _)
  // (only x shown; y and z 0). At t = 1.5, u = 0.5, dt = 1:
  //   p = (2/8 - 3/4 + 1) 0 + (1/8 - 2/4 + 1/2) 1 * 4 + (-2/8 + 3/4) 10 + (1/8 - 1/4) 1 * 8
  //     = 0.5 + 5 - 1 = 4.5   (LINEAR would give 5)
  const std::vector<float> keys = {0, 0, 0, 0,  0, 0, 4, 0, 0,  //
                                   8, 0, 0, 10, 0, 0, 0, 0, 0,  //
                                   0, 0, 0, 30, 0, 0, 0, 0, 0};
  const auto path = translated_quad("cubic", "CUBICSPLINE", keys);
  EXPECT_NEAR(x_at(path, 1.5), 4.5f, 1e-5f);
  EXPECT_NEAR(x_at(path, 2.0), 10.0f, 1e-5f);  // at a key: its value
  EXPECT_NEAR(x_at(path, 0.0), 0.0f, 1e-5f);   // clamped: the value, not a tangent
  EXPECT_NEAR(x_at(path, 5.0), 30.0f, 1e-5f);
}

TEST(GltfPose, RotationLinearIsSphericalAndAnimationNPicksTheAnimation) {
  GltfBuilder b;
  const int node = b.add_mesh_node(unit_quad(b));
  const float h = std::sqrt(0.5f);  // 90 degrees about +Z: (0, 0, sin 45, cos 45)
  b.animate(node, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, h, h});
  b.animate(node, "scale", {0, 1}, {1, 1, 1, 3, 3, 3}, "LINEAR", 1);
  const auto path = b.write_gltf(gltf_test_dir("rotation") / "r.gltf");
  // A quarter of the way: 22.5 degrees, the x axis at (cos 22.5, sin 22.5, 0). (Blending the
  // quaternions component-wise and normalizing would give 21.6 degrees: off by 0.015.)
  const glm::mat4 m = import_gltf(path, at_time(0.25)).scene.nodes[0].transform;
  const float a = glm::radians(22.5f);
  expect_near(glm::vec3(m[0]), {std::cos(a), std::sin(a), 0}, "x axis at 22.5 degrees");
  // Animation 1 scales instead; animation 0's rotation is not applied.
  const glm::mat4 s = import_gltf(path, at_time(0.5, 1)).scene.nodes[0].transform;
  expect_near(glm::vec3(s[0]), {2, 0, 0}, "x axis scaled by 2");
}

TEST(GltfPose, AnimationOutOfRangeOrTimeNotFiniteIsRefused) {
  const auto path = translated_quad("bad_animation", "LINEAR");
  try {
    import_gltf(path, at_time(1.0, 3));
    FAIL() << "animation 3 imported";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("animation 3 does not exist; the file has 1 (0 to 0)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(import_gltf(path, at_time(std::nan(""))), Error);
  // A file without animations is at rest whatever the time.
  GltfBuilder still;
  still.add_mesh_node(unit_quad(still));
  const auto still_path = still.write_gltf(gltf_test_dir("no_animation") / "s.gltf");
  EXPECT_NO_THROW(import_gltf(still_path, at_time(2.0)));
  EXPECT_THROW(import_gltf(still_path, at_time(2.0, 1)), Error);
}

// --- skins --------------------------------------------------------------------------------

std::filesystem::path skinned_bar(const std::string& name) {
  GltfBuilder b;
  add_skinned_bar(b);
  return b.write_gltf(gltf_test_dir(name) / "bar.gltf");
}

// The bar's vertices, in any order (finish_mesh makes normals for it, which may renumber them):
// one of them within 1e-4 of `want`.
void expect_vertex(const std::vector<glm::vec3>& got, glm::vec3 want, const std::string& what) {
  float nearest = 1e30f;
  for (const glm::vec3& p : got) nearest = std::min(nearest, glm::length(p - want));
  EXPECT_LT(nearest, 1e-4f) << what << ": no vertex at (" << want.x << ", " << want.y << ", "
                            << want.z << ")";
}

TEST(GltfPose, SkinnedBarAtRestFollowsItsNestedSkeleton) {
  // At rest each joint's world times its inverse bind matrix is translate(10, 0, 0): the bar
  // moves with the skeleton's parent, and the mesh node's own (0, 0, 5) is ignored.
  const std::vector<glm::vec3> got = world_positions(import_gltf(skinned_bar("bar_rest")).scene);
  ASSERT_FALSE(got.empty());
  for (float y : {0.0f, 1.0f, 2.0f}) {
    expect_vertex(got, {9.9f, y, 0}, "left at rest");
    expect_vertex(got, {10.1f, y, 0}, "right at rest");
  }
}

TEST(GltfPose, SkinnedBarBentNinetyDegreesAtTimeOne) {
  const std::vector<glm::vec3> got =
      world_positions(import_gltf(skinned_bar("bar_bent"), at_time(1.0)).scene);
  ASSERT_FALSE(got.empty());
  // Bottom row: joint 0 only, unmoved.
  expect_vertex(got, {9.9f, 0, 0}, "foot left");
  expect_vertex(got, {10.1f, 0, 0}, "foot right");
  // Top row: translate(10, 1, 0) rotateZ(90) translate(0, -1, 0), rotateZ(90) taking (x, y) to
  // (-y, x): (0.1, 2) -> (0.1, 1) -> (-1, 0.1) -> (9, 1.1); (-0.1, 2) -> (-0.1, 1) ->
  // (-1, -0.1) -> (9, 0.9).
  expect_vertex(got, {9.0f, 1.1f, 0}, "top right");
  expect_vertex(got, {9.0f, 0.9f, 0}, "top left");
  // Middle row (0.1, 1): joint 0 puts it at (10.1, 1), joint 1 at (10, 1.1); blended by
  // 128/255 and 127/255. (-0.1, 1): (9.9, 1) and (10, 0.9).
  expect_vertex(got, (128.0f * glm::vec3(10.1f, 1, 0) + 127.0f * glm::vec3(10, 1.1f, 0)) / 255.0f,
                "middle right");
  expect_vertex(got, (128.0f * glm::vec3(9.9f, 1, 0) + 127.0f * glm::vec3(10, 0.9f, 0)) / 255.0f,
                "middle left");
  EXPECT_EQ(got.size(), 6u);
}

}  // namespace
}  // namespace facet::test
