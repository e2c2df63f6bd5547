// Levels of detail (SceneNode::coarser): a node draws the level of the eye's distance from its
// detail bounds, measured as at a 60 degree field of view, and draw_scene draws that level for
// the renderer's camera.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"

namespace facet::test {
namespace {

// Instances 0 near, 1 from 10 away, 2 from 20 away, around the unit box at the origin.
SceneNode node_with_levels() {
  SceneNode node;
  node.instances = {{0, 0}};
  node.coarser = {{10.0f, {{1, 0}}}, {20.0f, {{2, 0}}}};
  node.detail_bounds.add(glm::vec3(-1.0f));
  node.detail_bounds.add(glm::vec3(1.0f));
  return node;
}

int drawn_mesh(const SceneNode& node, const glm::mat4& world, glm::vec3 eye, float fov = 60.0f) {
  Camera camera;
  camera.eye = eye;
  camera.fov_y_degrees = fov;
  return node.instances_seen_from(world, camera).at(0).mesh;
}

TEST(DetailLevels, FollowTheDistanceToTheNearestPointOfTheBounds) {
  const SceneNode node = node_with_levels();
  const glm::mat4 identity(1.0f);
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0, 5}), 0);      // 4 from the box
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0, 10.9f}), 0);  // 9.9
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0, 11.1f}), 1);  // 10.1
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0, 30}), 2);
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0.5f, 0}), 0);  // inside
  // Measured from the nearest point, not the centre: 15 along x past a box 4 wide there.
  const glm::mat4 wide = glm::scale(identity, {4.0f, 1.0f, 1.0f});
  EXPECT_EQ(drawn_mesh(node, wide, {15, 0, 0}), 1);
  EXPECT_EQ(drawn_mesh(node, identity, {15, 0, 0}), 1);
  EXPECT_EQ(drawn_mesh(node, glm::translate(identity, {10, 0, 0}), {15, 0, 0}), 0);
}

TEST(DetailLevels, ANarrowFieldOfViewCountsAsNearer) {
  const SceneNode node = node_with_levels();
  const glm::mat4 identity(1.0f);
  // 14 away: level 1 at 60 degrees; 14 tan(15) / tan(30) = 6.5 at 30 degrees; 31.6 at 100.
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0, 15}, 60.0f), 1);
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0, 15}, 30.0f), 0);
  EXPECT_EQ(drawn_mesh(node, identity, {0, 0, 15}, 100.0f), 2);
}

TEST(DetailLevels, WithoutLevelsOrBoundsTheInstancesAreDrawn) {
  SceneNode node = node_with_levels();
  node.detail_bounds = Bounds{};
  EXPECT_EQ(drawn_mesh(node, glm::mat4(1.0f), {0, 0, 100}), 0);
  node = node_with_levels();
  node.coarser.clear();
  EXPECT_EQ(drawn_mesh(node, glm::mat4(1.0f), {0, 0, 100}), 0);
}

// The detail bounds hold every level's meshes; nodes without levels keep theirs.
TEST(DetailLevels, BoundsAreSetAroundEveryLevel) {
  Scene scene;
  scene.meshes = {std::make_shared<const Mesh>(cube(2.0f)),
                  std::make_shared<const Mesh>(box({6.0f, 1.0f, 1.0f}))};
  SceneNode levelled, plain;
  levelled.instances = {{0, 0}};
  levelled.coarser = {{10.0f, {{1, 0}}}};
  plain.instances = {{1, 0}};
  scene.nodes = {levelled, plain};
  scene.bound_detail_levels();
  EXPECT_EQ(scene.nodes[0].detail_bounds.min, glm::vec3(-3.0f, -1.0f, -1.0f));
  EXPECT_EQ(scene.nodes[0].detail_bounds.max, glm::vec3(3.0f, 1.0f, 1.0f));
  EXPECT_TRUE(scene.nodes[1].detail_bounds.empty());
}

// A red cube near, a green one from 10 away: draw_scene draws the one for the frame's camera.
TEST(DetailLevels, DrawSceneDrawsTheLevelOfTheFramesCamera) {
  Scene scene;
  scene.meshes = {std::make_shared<const Mesh>(cube(2.0f))};
  Material red, green;
  red.base_color = {1, 0, 0, 1}, red.shading = ShadingModel::unlit;
  green.base_color = {0, 1, 0, 1}, green.shading = ShadingModel::unlit;
  scene.materials = {red, green};
  SceneNode node;
  node.instances = {{0, 0}};
  node.coarser = {{10.0f, {{0, 1}}}};
  scene.nodes = {node};
  scene.bound_detail_levels();
  auto centre_pixel = [&](float distance) {
    Renderer renderer;
    Framebuffer frame(32, 32);
    renderer.begin_frame(Camera::look_at({0, 0, distance}, {0, 0, 0}, {0, 1, 0}, 60.0f, 1.0f));
    draw_scene(renderer, scene);
    renderer.finish(frame);
    const std::uint8_t* p = frame.rgba8().data() + 4 * (16 * 32 + 16);
    return glm::ivec3(p[0], p[1], p[2]);
  };
  EXPECT_EQ(centre_pixel(5.0f), glm::ivec3(255, 0, 0));
  EXPECT_EQ(centre_pixel(15.0f), glm::ivec3(0, 255, 0));
}

}  // namespace
}  // namespace facet::test
