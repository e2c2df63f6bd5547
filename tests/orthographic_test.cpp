// Orthographic cameras (Camera::orthographic): things are the same size at every distance, as
// many pixels as their size in scene units says; window depth is linear in distance, and what
// reads distance (view_distance, the depth view, fog, specular highlights, levels of detail,
// framing) reads it right.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 64, kHeight = 48;

// Looks down -Z from the origin; 4 units tall, so 12 pixels a unit.
Camera ortho_camera(float near_plane = 0.5f, float far_plane = 50.0f) {
  return Camera::orthographic({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 4.0f, float(kWidth) / kHeight,
                              near_plane, far_plane);
}

std::vector<bool> drawn(const Framebuffer& image) {
  std::vector<bool> out;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) out.push_back(image.depth_at(x, y) < 1.0f);
  }
  return out;
}

long count(const std::vector<bool>& pixels) {
  return std::count(pixels.begin(), pixels.end(), true);
}

TEST(Orthographic, ASquareCoversTheSamePixelsAtEveryDepth) {
  // 1 x 1, its edges at window x 32 + 12 (-0.48) = 26.24 and 38.24: pixel centres 26.5 .. 37.5.
  std::vector<bool> first;
  for (float distance : {1.0f, 5.0f, 20.0f, 49.0f}) {
    const Mesh square = soup_quad(-0.48f, -0.52f, 0.52f, 0.48f, -distance);
    const std::vector<bool> pixels =
        drawn(render_unlit({&square}, ortho_camera(), kWidth, kHeight));
    EXPECT_EQ(count(pixels), 12 * 12) << distance;
    if (first.empty()) first = pixels;
    EXPECT_EQ(pixels, first) << distance;
  }
}

TEST(Orthographic, SizeInSceneUnitsGivesTheSizeInPixels) {
  // 2 x 0.75 units at 12 pixels a unit: 24 x 9 pixels (edges off the pixel centres).
  const Mesh rectangle = soup_quad(-1.01f, -0.4f, 0.99f, 0.35f, -7.0f);
  EXPECT_EQ(count(drawn(render_unlit({&rectangle}, ortho_camera(), kWidth, kHeight))), 24 * 9);
  // Twice the view height: half the pixels each way.
  Camera wide = ortho_camera();
  wide.view_height = 8.0f;
  const Mesh big = soup_quad(-2.02f, -0.8f, 1.98f, 0.7f, -7.0f);
  EXPECT_EQ(count(drawn(render_unlit({&big}, wide, kWidth, kHeight))), 24 * 9);
}

TEST(Orthographic, ViewDistanceOfTheDepthIsTheDistanceDrawnAt) {
  const Camera camera = ortho_camera(0.5f, 50.0f);
  EXPECT_FLOAT_EQ(camera.view_distance(0.0f), 0.5f);
  EXPECT_FLOAT_EQ(camera.view_distance(1.0f), 50.0f);
  for (float distance : {0.75f, 4.0f, 37.0f}) {
    const Mesh wall = soup_quad(-10, -10, 10, 10, -distance);
    const Framebuffer image = render_unlit({&wall}, camera, kWidth, kHeight);
    const float depth = image.depth_at(kWidth / 2, kHeight / 2);
    EXPECT_NEAR(depth, (distance - 0.5f) / 49.5f, 1e-6f) << "linear in distance";
    EXPECT_NEAR(camera.view_distance(depth), distance, distance * 1e-5f) << distance;
  }
}

// A wall `distance` away drawn with `material` under `camera` into a framebuffer of `format`:
// the centre pixel.
Framebuffer wall_image(const Camera& camera, float distance, const Material& material,
                       const Lighting& lighting = {}, ColorFormat format = ColorFormat::rgba32f) {
  const Mesh wall = soup_quad(-10, -10, 10, 10, -distance);
  Renderer renderer;
  Framebuffer image(kWidth, kHeight, format);
  renderer.begin_frame(camera, lighting);
  renderer.draw(wall, material);
  renderer.finish(image);
  return image;
}

glm::vec4 wall_color(const Camera& camera, float distance, const Material& material,
                     const Lighting& lighting = {}) {
  return wall_image(camera, distance, material, lighting).pixel(kWidth / 2, kHeight / 2);
}

TEST(Orthographic, DepthViewShowsTheDistance) {
  // The depth view spans the frame's own depths, white to black, linear in distance: with
  // small cards at 5 and 45 beside the wall, 1 - (distance - 5) / 40 at the wall, as an 8-bit
  // code (the depth view writes display values).
  Material depth;
  depth.shading = ShadingModel::depth;
  const Mesh near_card = soup_quad(-0.1f, -0.1f, 0.0f, 0.0f, -5.0f);
  const Mesh far_card = soup_quad(-0.1f, -0.1f, 0.0f, 0.0f, -45.0f);
  for (Camera camera :
       {ortho_camera(0.5f, 50.5f), test_camera(kWidth, kHeight, 60.0f, 0.5f, 50.5f)}) {
    for (float distance : {10.0f, 30.0f}) {
      const Mesh wall = soup_quad(-10, -10, 10, 10, -distance);
      Renderer renderer;
      Framebuffer image(kWidth, kHeight);
      renderer.begin_frame(camera);
      for (const Mesh* mesh : {&wall, &near_card, &far_card}) renderer.draw(*mesh, depth);
      renderer.finish(image);
      const float expected = 255.0f * (1.0f - (distance - 5.0f) / 40.0f);
      const int code = image.rgba8()[4 * (kHeight / 2 * kWidth + kWidth * 5 / 8)];
      EXPECT_NEAR(code, expected, 1.0f)
          << (camera.projection_kind == Projection::orthographic ? "orthographic " : "perspective ")
          << distance;
    }
  }
}

TEST(Orthographic, FogFollowsTheDistance) {
  Material white;
  white.shading = ShadingModel::unlit;
  Lighting lighting;
  lighting.fog.mode = FogMode::linear;
  lighting.fog.start = 0.0f;
  lighting.fog.end = 20.0f;
  lighting.fog.color = glm::vec3(0.0f);
  for (float distance : {5.0f, 15.0f}) {
    EXPECT_NEAR(wall_color(ortho_camera(), distance, white, lighting).r, 1.0f - distance / 20.0f,
                1e-5f)
        << distance;
  }
}

TEST(Orthographic, ViewDirectionIsTheAxisEverywhere) {
  // Parallel rays see a flat mirror-like wall the same everywhere: a highlight straight along
  // the axis is as bright at the corners as at the centre (a perspective eye sees it fade).
  const Camera camera = ortho_camera();
  const glm::vec3 eye = camera.shading_eye();
  EXPECT_LT(glm::length(glm::normalize(camera.eye - eye) - glm::vec3(0, 0, -1)), 1e-6f);
  EXPECT_GT(glm::length(camera.eye - eye), 1e4f * 50.0f);

  Material shiny;
  shiny.shading = ShadingModel::blinn_phong;
  shiny.shininess = 200.0f;
  shiny.specular_color = glm::vec3(1.0f);
  shiny.base_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Lighting lighting;
  lighting.ambient = glm::vec3(0.0f);
  lighting.lights = {Light::directional({0, 0, -1})};
  const Mesh wall = quad({-10, -10, -5}, {10, -10, -5}, {10, 10, -5}, {-10, 10, -5});
  for (bool orthographic : {true, false}) {
    const Camera c = orthographic ? camera : test_camera(kWidth, kHeight, 60.0f, 0.5f, 50.0f);
    Renderer renderer;
    Framebuffer image(kWidth, kHeight, ColorFormat::rgba32f);
    renderer.begin_frame(c, lighting);
    renderer.draw(wall, shiny);
    renderer.finish(image);
    const float centre = image.pixel(kWidth / 2, kHeight / 2).g;
    const float corner = image.pixel(0, 0).g;
    EXPECT_GT(centre, 0.5f);
    if (orthographic) {
      EXPECT_NEAR(corner, centre, 1e-3f);
    } else {
      EXPECT_LT(corner, centre * 0.5f);  // the test can tell the two apart
    }
  }
}

TEST(Orthographic, LevelOfDetailFollowsTheViewHeight) {
  SceneNode node;
  node.instances = {{0, 0}};
  node.coarser = {{10.0f, {{1, 0}}}};
  node.detail_bounds.add(glm::vec3(-1.0f));
  node.detail_bounds.add(glm::vec3(1.0f));
  // A 60 degree view 10 away is 2 tan(30) 10 = 11.5 units tall.
  Camera camera = ortho_camera();
  camera.view_height = 11.0f;
  EXPECT_EQ(node.instances_seen_from(glm::mat4(1.0f), camera).at(0).mesh, 0);
  camera.view_height = 12.0f;
  EXPECT_EQ(node.instances_seen_from(glm::mat4(1.0f), camera).at(0).mesh, 1);
}

TEST(Orthographic, FramingFitsTheWholeScene) {
  Scene scene;
  scene.add_object(
      uv_sphere(1.0f, 24, 16), Material{},
      glm::scale(glm::translate(glm::mat4(1.0f), {3.0f, -1.0f, 2.0f}), {2.0f, 1.0f, 1.0f}));
  const Camera camera = frame_scene_orthographic(scene, float(kWidth) / kHeight);
  ASSERT_EQ(camera.projection_kind, Projection::orthographic);
  camera.validate();
  // The same direction as the perspective framing.
  const Camera perspective = frame_scene(scene, float(kWidth) / kHeight);
  EXPECT_LT(glm::length(camera.forward() - perspective.forward()), 1e-5f);
  Renderer renderer;
  Framebuffer image(kWidth, kHeight);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(image);
  // Nothing cut off, by the sides or the clip planes, and the model fills the view one way.
  int left = kWidth, right = -1, top = kHeight, bottom = -1;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (image.depth_at(x, y) == 1.0f) continue;
      left = std::min(left, x), right = std::max(right, x);
      top = std::min(top, y), bottom = std::max(bottom, y);
      EXPECT_GT(image.depth_at(x, y), 0.0f);
    }
  }
  EXPECT_GT(left, 0);
  EXPECT_LT(right, kWidth - 1);
  EXPECT_GT(top, 0);
  EXPECT_LT(bottom, kHeight - 1);
  const float filled =
      std::max(float(right - left + 1) / kWidth, float(bottom - top + 1) / kHeight);
  EXPECT_GT(filled, 0.85f);
}

std::string error_of(const Camera& camera) {
  try {
    camera.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Orthographic, BadValuesAreNamed) {
  EXPECT_EQ(error_of(ortho_camera(0.0f, 10.0f)), "");  // near may be 0 in a parallel projection
  Camera flat = ortho_camera();
  flat.view_height = 0.0f;
  EXPECT_NE(error_of(flat).find("view_height must be positive"), std::string::npos);
  flat.view_height = std::nanf("");
  EXPECT_NE(error_of(flat).find("view_height must be positive"), std::string::npos);
  EXPECT_NE(error_of(ortho_camera(-1.0f, 10.0f)).find("near plane must not be negative"),
            std::string::npos);
  EXPECT_NE(error_of(ortho_camera(2.0f, 1.0f)).find("must be beyond the near plane"),
            std::string::npos);
}

}  // namespace
}  // namespace facet::test
