// A sun's maps drawn only where their lookups read (pipeline/shadow/shadow_reach.hpp): the
// reach of a view seen straight down and of a slice of a perspective view where geometry puts
// them, with the lookup filter's margin, for casters' boxes and for the map's tiles; through
// the renderer, the same images as with the maps drawn whole (in a frame with a model that
// looks shadows up at its vertices): the built-in worlds, and scenes built so that a reach too
// small would change them (a caster just out of view, a mirror showing what is behind the
// camera, a blend band); and a Gouraud vertex out of view still shadowed.
#include "pipeline/shadow/shadow_reach.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>
#include <vector>

#include "facet/islands.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

using pipeline::box_outside_reach;
using pipeline::LookupDepths;
using pipeline::shadow_reach;
using pipeline::ShadowReach;
using pipeline::texels_outside_reach;

// A map under a sun straight down: texel x = 10 (world x + 50), texel y = 10 (world z + 50), so
// a world unit is 10 texels and the map covers [-50, 50] on both axes.
glm::mat4 map_from_above() {
  glm::mat4 m(0.0f);
  m[0][0] = 10.0f, m[3][0] = 500.0f;  // x
  m[2][1] = 10.0f, m[3][1] = 500.0f;  // y from world z
  m[1][2] = -0.01f, m[3][2] = 0.5f;   // depth (unused by the reach)
  m[3][3] = 1.0f;
  return m;
}

// Whether a box of unit height at world x in [x0, x1], z in [z0, z1] lies outside the reach.
bool outside(const ShadowReach& reach, float x0, float x1, float z0, float z1) {
  return box_outside_reach(reach, {x0, 0.0f, z0}, {x1, 1.0f, z1}, glm::mat4(1.0f));
}

// An orthographic view straight down over [-5, 5] x [-5, 5] reaches exactly that square: a
// box within it is kept, one 3 texels off its side too (the filter's reach, 4 texels), one 5
// texels off is dropped, and so is one across the map.
TEST(ShadowReach, ViewFromAboveReachesItsSquareAndTheFilterMargin) {
  const Camera above =
      Camera::orthographic({0, 50, 0}, {0, 0, 0}, {0, 0, -1}, 10.0f, 1.0f, 1.0f, 100.0f);
  const std::array views{above};
  const ShadowReach reach =
      shadow_reach(views, {above.eye, above.forward(), 1.0f, 100.0f}, map_from_above(), 1.0f);
  EXPECT_EQ(reach.corners, 4);
  EXPECT_FALSE(outside(reach, -1.0f, 1.0f, -1.0f, 1.0f));
  EXPECT_FALSE(outside(reach, 5.3f, 6.0f, -1.0f, 1.0f));
  EXPECT_TRUE(outside(reach, 5.5f, 6.0f, -1.0f, 1.0f));
  EXPECT_FALSE(outside(reach, -1.0f, 1.0f, -6.0f, -5.3f));
  EXPECT_TRUE(outside(reach, -1.0f, 1.0f, -6.0f, -5.5f));
  EXPECT_TRUE(outside(reach, 20.0f, 30.0f, 20.0f, 30.0f));
  // A box turned 45 degrees about y, its nearest corner 3 texels off the square's side.
  const glm::mat4 turned = glm::rotate(glm::translate(glm::mat4(1.0f), {5.3f + 0.5f, 0, 0}),
                                       glm::radians(45.0f), {0, 1, 0});
  EXPECT_FALSE(
      box_outside_reach(reach, {-0.35355f, 0, -0.35355f}, {0.35355f, 1, 0.35355f}, turned));

  // The map's tiles: texels 450 .. 549 hold the square (world -5 .. 5 at 10 texels a unit).
  EXPECT_FALSE(texels_outside_reach(reach, 448, 448, 512, 512));
  EXPECT_FALSE(texels_outside_reach(reach, 552, 448, 600, 512));  // 2 texels off the side
  EXPECT_TRUE(texels_outside_reach(reach, 555, 448, 600, 512));   // 5 texels off
  EXPECT_TRUE(texels_outside_reach(reach, 0, 0, 64, 64));
}

// A perspective view looking level along -z from the origin (90 degrees, square), under a sun
// straight down: the points it sees at view depths [10, 20] lie across the sun within the
// trapezoid from (-10, -10)..(10, -10) to (-20, -20)..(20, -20) (x, z): nearer, farther, beside
// or behind it nothing is read.
TEST(ShadowReach, SliceOfAPerspectiveViewReachesItsTrapezoid) {
  const Camera level = Camera::look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0f, 1.0f, 0.5f, 40.0f);
  const std::array views{level};
  const ShadowReach slice =
      shadow_reach(views, {level.eye, level.forward(), 10.0f, 20.0f}, map_from_above(), 1.0f);
  EXPECT_FALSE(outside(slice, -1.0f, 1.0f, -15.0f, -14.0f));
  EXPECT_FALSE(outside(slice, 14.0f, 16.0f, -18.0f, -17.0f));  // by the widening side
  EXPECT_TRUE(outside(slice, -1.0f, 1.0f, -5.0f, -4.0f));      // nearer
  EXPECT_TRUE(outside(slice, -1.0f, 1.0f, -30.0f, -25.0f));    // farther
  EXPECT_TRUE(outside(slice, 14.0f, 16.0f, -12.0f, -11.0f));   // beside the narrow end
  EXPECT_TRUE(outside(slice, -1.0f, 1.0f, 5.0f, 6.0f));        // behind the camera
  // From the near plane on, the nearer box is read too.
  const ShadowReach from_near =
      shadow_reach(views, {level.eye, level.forward(), 0.5f, 20.0f}, map_from_above(), 1.0f);
  EXPECT_FALSE(outside(from_near, -1.0f, 1.0f, -5.0f, -4.0f));
  // Depths no view sees: nothing is read.
  const ShadowReach unseen =
      shadow_reach(views, {level.eye, level.forward(), 50.0f, 60.0f}, map_from_above(), 1.0f);
  EXPECT_EQ(unseen.corners, 0);
  EXPECT_TRUE(outside(unseen, -1.0f, 1.0f, -15.0f, -14.0f));
}

// A tiny triangle at the scene's centre (so the box the maps are fitted to stays the same), in
// a Gouraud material (which looks shadows up at its vertices) that is blended and fully
// transparent: it changes no pixel and casts nothing, but its frame draws every caster into
// every map.
void add_reach_off_switch(Scene& scene) {
  Material m;
  m.shading = ShadingModel::gouraud;
  m.alpha_mode = AlphaMode::blend;
  m.base_color = {1.0f, 1.0f, 1.0f, 0.0f};
  const glm::vec3 c = scene.bounds().centre();
  scene.add_object(triangle(c, c + glm::vec3(0.01f, 0, 0), c + glm::vec3(0, 0.01f, 0)), m);
}

constexpr int kWidth = 320, kHeight = 180;
constexpr float kAspect = static_cast<float>(kWidth) / kHeight;

RenderSettings reach_settings() {
  RenderSettings settings;
  settings.shadows = true;
  settings.reflections = true;
  settings.msaa = 1;
  settings.shadow_map_size = 512;
  return settings;
}

// Expects `scene` drawn the same with its maps drawn only within their reach as drawn whole.
void expect_as_drawn_whole(Scene scene, const Camera& camera, const RenderSettings& settings,
                           const char* what) {
  const Framebuffer reached = render_scene_image(scene, camera, kWidth, kHeight, settings);
  add_reach_off_switch(scene);
  const Framebuffer whole = render_scene_image(scene, camera, kWidth, kHeight, settings);
  EXPECT_TRUE(reached.rgba8() == whole.rgba8()) << what;
}

Material lit(glm::vec3 color) {
  Material m;
  m.shading = ShadingModel::lambert;
  m.base_color = glm::vec4(color, 1.0f);
  m.cull = CullMode::none;
  return m;
}

glm::mat4 at(glm::vec3 centre) { return glm::translate(glm::mat4(1.0f), centre); }

// The built-in worlds: the islands (three cascades, the sea reflecting them) and the shapes
// (one map), at one sample and at 4 (where the middle cascade's map is drawn within its reach).
TEST(ShadowReach, WorldsAreDrawnAsWithMapsDrawnWhole) {
  for (const bool islands : {true, false}) {
    for (const int msaa : {1, 4}) {
      Scene scene = islands ? make_islands_scene() : make_shapes_scene();
      Camera camera = scene_camera(scene, kAspect);
      camera.aspect = kAspect;
      RenderSettings settings = reach_settings();
      settings.msaa = msaa;
      expect_as_drawn_whole(std::move(scene), camera, settings, islands ? "islands" : "shapes");
    }
  }
}

// Straight down over a ground, a sun straight down, and a bar just past the right edge of the
// view, its shadow a texel or two past it: the lookups at the edge reach under it.
TEST(ShadowReach, CasterJustOutOfViewStillShadowsTheEdge) {
  Scene scene;
  scene.add_object(plane(40.0f, 40.0f), lit({0.8f, 0.8f, 0.8f}));
  scene.add_object(box({0.3f, 0.2f, 6.0f}), lit({0.8f, 0.2f, 0.2f}),
                   at({8.0f + 0.25f, 1.0f, 0.0f}));
  scene.lighting.lights = {Light::directional({0.0f, -1.0f, 0.0f})};
  scene.lighting.ambient = glm::vec3(0.1f);
  // 16 units wide (x in [-8, 8]) and 9 deep.
  const Camera above =
      Camera::orthographic({0, 10, 0}, {0, 0, 0}, {0, 0, -1}, 9.0f, kAspect, 1.0f, 20.0f);
  RenderSettings settings = reach_settings();
  settings.shadow_map_size = 128;  // a texel of about 1/8 unit: the bar 0.1 past the edge
  expect_as_drawn_whole(std::move(scene), above, settings, "bar past the edge");
}

// Gouraud looks shadows up at the vertices, wherever they lie: straight down on a ground of
// two triangles whose corner lies out of view (but within the map, squared from the wide view),
// under a block, the corner's shadow darkens what the view sees of its triangle.
TEST(ShadowReach, GouraudVertexOutOfViewIsShadowed) {
  Material ground;
  ground.shading = ShadingModel::gouraud;
  ground.base_color = {0.8f, 0.8f, 0.8f, 1.0f};
  ground.cull = CullMode::none;
  const auto scene_with_block = [&](bool block) {
    Scene scene;
    scene.add_object(plane(14.0f, 15.0f), ground);
    if (block)
      scene.add_object(box({2.0f, 0.2f, 2.0f}), lit({0.2f, 0.2f, 0.8f}), at({7.0f, 1.0f, 7.5f}));
    scene.lighting.lights = {Light::directional({0.0f, -1.0f, 0.0f})};
    scene.lighting.ambient = glm::vec3(0.1f);
    return scene;
  };
  // 16 units wide (x in [-8, 8]) and 9 deep (z in [-4.5, 4.5]): the ground's corners at
  // z = +-7.5 are out of view.
  const Camera above =
      Camera::orthographic({0, 10, 0}, {0, 0, 0}, {0, 0, -1}, 9.0f, kAspect, 1.0f, 20.0f);
  EXPECT_FALSE(render_scene_image(scene_with_block(true), above, kWidth, kHeight, reach_settings())
                   .rgba8() ==
               render_scene_image(scene_with_block(false), above, kWidth, kHeight, reach_settings())
                   .rgba8());
}

// A wide view of a mirror wall close ahead, a sun straight down, and behind the camera a block
// above the floor: the map, squared from the wide view, reaches behind the camera, where only
// the mirror shows the floor and the block's shadow on it. The mirror pass's lookups read
// casters the camera's own view does not, and at view depths behind the camera.
TEST(ShadowReach, MirrorShowsShadowsCastOutsideTheView) {
  Scene scene;
  Material mirror = phong_mirror();
  mirror.cull = CullMode::none;
  scene.add_object(rectangle(20.0f, 6.0f), mirror, at({0.0f, 3.0f, -5.0f}));
  scene.add_object(plane(20.0f, 11.0f), lit({0.8f, 0.8f, 0.8f}), at({0.0f, 0.0f, 0.5f}));
  scene.add_object(box({1.0f, 0.2f, 1.0f}), lit({0.2f, 0.2f, 0.8f}), at({0.0f, 1.0f, 3.0f}));
  scene.lighting.lights = {Light::directional({0.0f, -1.0f, 0.0f})};
  scene.lighting.ambient = glm::vec3(0.1f);
  const Camera camera = Camera::look_at({0.0f, 2.0f, 0.0f}, {0.0f, 1.5f, -5.0f}, {0, 1, 0}, 70.0f,
                                        kAspect, 0.5f, 100.0f);
  expect_as_drawn_whole(std::move(scene), camera, reach_settings(), "mirror");
}

// One renderer's frames, as the viewer draws them, each the image a fresh renderer draws: its
// maps keep what earlier frames left in the tiles a pass skips (outside the reach, and the
// empty tiles it cleared before and leaves cleared), which no lookup may see. The camera
// walks, turns, and comes back.
TEST(ShadowReach, FramesOfOneRendererAreThoseOfFreshOnes) {
  const Scene scene = make_islands_scene();
  Camera start = scene_camera(scene, kAspect);
  start.aspect = kAspect;
  const glm::vec3 along = start.forward();
  const glm::vec3 side = glm::normalize(glm::cross(along, glm::vec3(0, 1, 0)));
  std::vector<Camera> path;
  for (const glm::vec3 step :
       {glm::vec3(0.0f), along * 20.0f, side * 30.0f, -along * 15.0f, glm::vec3(0.0f)}) {
    Camera camera = start;
    camera.eye += step, camera.target += step + side * 10.0f * glm::length(step) / 30.0f;
    path.push_back(camera);
  }
  for (const int msaa : {1, 4}) {
    RenderSettings settings = reach_settings();
    settings.msaa = msaa;
    Renderer renderer(settings);
    Framebuffer frame(kWidth, kHeight);
    for (std::size_t i = 0; i < path.size(); ++i) {
      renderer.begin_frame(path[i], scene.lighting);
      draw_scene(renderer, scene);
      renderer.finish(frame);
      const Framebuffer fresh = render_scene_image(scene, path[i], kWidth, kHeight, settings);
      EXPECT_TRUE(frame.rgba8() == fresh.rgba8()) << "msaa " << msaa << ", frame " << i;
    }
  }
}

// A block moving over a ground that casts no shadow, under a sun straight down, seen from
// above: the maps' tiles it leaves are empty again, and must be cleared again, or its old
// shadows stay. Each frame as a fresh renderer draws it.
TEST(ShadowReach, ACasterThatMovesLeavesNoShadowBehind) {
  Scene scene;
  Material ground = lit({0.8f, 0.8f, 0.8f});
  ground.casts_shadows = false;
  scene.add_object(plane(16.0f, 9.0f), ground);
  const int block =
      scene.add_object(box({1.0f, 0.2f, 1.0f}), lit({0.2f, 0.2f, 0.8f}), at({-4.0f, 1.0f, 0.0f}));
  scene.lighting.lights = {Light::directional({0.0f, -1.0f, 0.0f})};
  scene.lighting.ambient = glm::vec3(0.1f);
  const Camera above =
      Camera::orthographic({0, 10, 0}, {0, 0, 0}, {0, 0, -1}, 9.0f, kAspect, 1.0f, 20.0f);
  Renderer renderer(reach_settings());
  Framebuffer frame(kWidth, kHeight);
  for (int i = 0; i < 4; ++i) {
    scene.nodes[block].transform = at({i % 2 == 0 ? -4.0f : 4.0f, 1.0f, 0.0f});
    renderer.begin_frame(above, scene.lighting);
    draw_scene(renderer, scene);
    renderer.finish(frame);
    const Framebuffer fresh = render_scene_image(scene, above, kWidth, kHeight, reach_settings());
    EXPECT_TRUE(frame.rgba8() == fresh.rgba8()) << "frame " << i;
  }
}

// Two cascades over a ground seen from low down, a sun low behind, and a row of posts along
// the view: where a post's long shadow lies in a blend band, the band's points read the next
// map too, which must hold the post.
TEST(ShadowReach, BlendBandsReadTheNextMapsCasters) {
  Scene scene;
  scene.add_object(plane(200.0f, 200.0f), lit({0.8f, 0.8f, 0.8f}));
  for (int i = 0; i < 40; ++i) {
    const float z = -8.0f - 0.25f * static_cast<float>(i);
    scene.add_object(box({0.1f, 1.5f, 0.1f}), lit({0.2f, 0.6f, 0.2f}), at({-1.0f, 0.75f, z}));
  }
  scene.lighting.lights = {Light::directional({1.0f, -1.0f, 0.0f})};
  scene.lighting.ambient = glm::vec3(0.1f);
  const Camera low = Camera::look_at({0.0f, 2.0f, 2.0f}, {0.0f, 0.0f, -20.0f}, {0, 1, 0}, 50.0f,
                                     kAspect, 0.5f, 120.0f);
  RenderSettings settings = reach_settings();
  settings.shadow_cascades = 2;
  settings.shadow_map_size = 2048;
  expect_as_drawn_whole(std::move(scene), low, settings, "blend bands");
}

}  // namespace
}  // namespace facet::test
