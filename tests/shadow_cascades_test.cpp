// A sun's cascades chosen from the view (pipeline/shadow/cascades.hpp): the depths the camera
// sees of a box where geometry puts them, one map for a model seen whole and for the shapes
// scene, three for the islands seen from the ground, one for any orthographic view; and the
// renderer's automatic count (RenderSettings::kAutoShadowCascades, the default) drawing the
// image the explicit count draws.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "facet/islands.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/teapot.hpp"
#include "facet/worlds.hpp"
#include "pipeline/shadow/cascades.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

using pipeline::automatic_cascade_count;
using pipeline::ViewDepths;
using pipeline::WorldBox;

WorldBox box_of(const Scene& scene) {
  const Bounds bounds = scene.bounds();
  WorldBox box;
  box.add(bounds.min), box.add(bounds.max);
  return box;
}

// The scene's default view for an image of this aspect, as `facet render` sets it up.
Camera view_of(const Scene& scene, float aspect) {
  Camera camera = scene_camera(scene, aspect);
  camera.aspect = aspect;
  return camera;
}

WorldBox box_between(glm::vec3 low, glm::vec3 high) {
  WorldBox box;
  box.add(low), box.add(high);
  return box;
}

// From 5 above the ground, looking 30 degrees down, at a slab [-20, 20] x [0, 1] x [-20, 20]:
// the frustum's lower edge (20 degrees below the line of sight: 50 below the horizon) meets the
// slab's top at view depth 4 / (sin 30 + tan 20 cos 30), everywhere along that edge, and the
// farthest point seen is the middle of the far side's foot, (0, 0, -20): depth
// 20 cos 30 + 5 sin 30. The box's own corners span from behind the camera (so scene_depths
// starts at the near plane).
TEST(ShadowCascades, SeenDepthsAreThoseOfTheBoxWithinTheFrustum) {
  const float pitch = glm::radians(30.0f), half_fov = glm::radians(20.0f);
  const glm::vec3 eye(0.0f, 5.0f, 0.0f);
  const Camera camera =
      Camera::look_at(eye, eye + glm::vec3(0.0f, -std::sin(pitch), -std::cos(pitch)), {0, 1, 0},
                      40.0f, 1.0f, 0.1f, 100.0f);
  const WorldBox slab = box_between({-20.0f, 0.0f, -20.0f}, {20.0f, 1.0f, 20.0f});
  const ViewDepths seen = pipeline::seen_depths(camera, slab);
  const float nearest = 4.0f / (std::sin(pitch) + std::tan(half_fov) * std::cos(pitch));
  const float farthest = 20.0f * std::cos(pitch) + 5.0f * std::sin(pitch);
  EXPECT_NEAR(seen.nearest, nearest, 1e-3f);
  EXPECT_NEAR(seen.farthest, farthest, 1e-3f);
  EXPECT_EQ(pipeline::scene_depths(camera, slab).nearest, camera.near_plane);

  // The camera inside the box: from the near plane to the far. Looking away from it: nothing.
  const WorldBox around = box_between(glm::vec3(-200.0f), glm::vec3(200.0f));
  const ViewDepths inside = pipeline::seen_depths(camera, around);
  EXPECT_NEAR(inside.nearest, camera.near_plane, 1e-4f);
  EXPECT_NEAR(inside.farthest, camera.far_plane, 1e-2f);
  const WorldBox behind = box_between({-1.0f, 4.0f, 2.0f}, {1.0f, 6.0f, 4.0f});
  const ViewDepths none = pipeline::seen_depths(camera, behind);
  EXPECT_GT(none.nearest, none.farthest);
  EXPECT_EQ(automatic_cascade_count(camera, behind), 1);
}

// A model framed whole keeps one map (its depths span a few times their nearest), as do the
// teapot and the shapes scene (a ground plane 40 wide seen from above it: about 24 times); the
// islands from the ground see from the near plane (0.5) to the far (3000), 6000 times, between
// kCascadeDepthRatio^2 and ^3: three maps.
TEST(ShadowCascades, AutomaticCountIsOneForAModelAndMoreForTheIslands) {
  Scene model;
  model.add_object(uv_sphere(1.0f), Material{});
  model.add_object(box(glm::vec3(3.0f, 0.5f, 2.0f)), Material{});
  for (const float aspect : {16.0f / 9.0f, 1.0f, 0.5f}) {
    EXPECT_EQ(automatic_cascade_count(frame_scene(model, aspect), box_of(model)), 1) << aspect;
  }
  const Scene teapot = make_teapot_scene();
  EXPECT_EQ(automatic_cascade_count(view_of(teapot, 4.0f / 3.0f), box_of(teapot)), 1);
  const Scene shapes = make_shapes_scene();
  EXPECT_EQ(automatic_cascade_count(view_of(shapes, 4.0f / 3.0f), box_of(shapes)), 1);

  const Scene islands = make_islands_scene();
  const Camera ground = view_of(islands, 4.0f / 3.0f);
  const ViewDepths seen = pipeline::seen_depths(ground, box_of(islands));
  const float r = pipeline::kCascadeDepthRatio;
  EXPECT_GT(seen.farthest, seen.nearest * r * r);
  EXPECT_EQ(automatic_cascade_count(ground, box_of(islands)), 3);
  // Seen in parallel projection, a texel is the same size on screen at every depth.
  const Camera parallel = fit_orthographic(islands, ground, 4.0f / 3.0f);
  EXPECT_EQ(automatic_cascade_count(parallel, box_of(islands)), 1);
}

// Through the renderer: the default settings draw the shapes as one map does, and the islands as
// three maps do (not as one).
TEST(ShadowCascades, RendererDefaultDrawsTheAutomaticCount) {
  RenderSettings automatic;
  automatic.shadows = true;
  automatic.shadow_map_size = 256;
  ASSERT_EQ(automatic.shadow_cascades, RenderSettings::kAutoShadowCascades);
  const auto with_cascades = [&](int cascades) {
    RenderSettings s = automatic;
    s.shadow_cascades = cascades;
    return s;
  };
  constexpr int kWidth = 160, kHeight = 90;
  Scene shapes = make_shapes_scene();
  shapes.camera.aspect = static_cast<float>(kWidth) / kHeight;
  EXPECT_TRUE(render_scene_image(shapes, shapes.camera, kWidth, kHeight, automatic).rgba8() ==
              render_scene_image(shapes, shapes.camera, kWidth, kHeight, with_cascades(1)).rgba8());

  const Scene islands = make_islands_scene();
  const Camera ground = view_of(islands, static_cast<float>(kWidth) / kHeight);
  const Framebuffer chosen = render_scene_image(islands, ground, kWidth, kHeight, automatic);
  EXPECT_TRUE(chosen.rgba8() ==
              render_scene_image(islands, ground, kWidth, kHeight, with_cascades(3)).rgba8());
  EXPECT_FALSE(chosen.rgba8() ==
               render_scene_image(islands, ground, kWidth, kHeight, with_cascades(1)).rgba8());
}

}  // namespace
}  // namespace facet::test
