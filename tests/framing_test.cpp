// The automatic view (frame_scene, Framing, scene_camera in include/facet/scene.hpp): every
// sample model fits inside images of any aspect, the model's up axis turns the view as rotating
// the model would, the azimuth turns the eye about that axis, and the elevation reaches the
// poles without a degenerate camera.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/import.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

// The scene drawn through `camera` into a width x height image with a depth image.
Framebuffer render_depth(const Scene& scene, const Camera& camera, int width, int height) {
  Renderer renderer;
  Framebuffer target(width, height);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(target);
  return target;
}

// Pixels of the outermost ring where something was drawn (depth below 1).
int border_pixels_drawn(const Framebuffer& image) {
  int drawn = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const bool border = x == 0 || y == 0 || x == image.width() - 1 || y == image.height() - 1;
      if (border && image.depth_at(x, y) < 1.0f) ++drawn;
    }
  }
  return drawn;
}

int pixels_drawn(const Framebuffer& image) {
  int drawn = 0;
  for (float d : image.depth()) drawn += d < 1.0f;
  return drawn;
}

// The sizes of the report: a square thumbnail, a 4:3 and a tall image (at full size the test
// takes under 2 s, importing the models being most of it).
struct Size {
  int width, height;
};
constexpr Size kSizes[] = {{256, 256}, {800, 600}, {300, 600}};

// Regression: the import framed every model for 16:9 and a renderer of another aspect only
// widened or narrowed the view, cutting the model's ends (2CylinderEngine at 800x600, the bunny
// at 256x256 and 300x600). scene_camera frames it again for the image.
TEST(Framing, EveryGltfSampleFitsInsideImagesOfEveryAspect) {
  FACET_REQUIRE_PACKAGE(fs::exists(kSampleModels / "glTF2"), "assimp-testmodels is not installed");
  ImportOptions quiet;
  quiet.warn = [](const std::string&) {};
  int checked = 0;
  for (const fs::path& file : wellformed_model_files("glTF2")) {
    Scene scene;
    try {
      scene = import_scene(file.string(), quiet);
    } catch (const Error&) {
      continue;  // the files that must fail are import_test.cpp's business
    }
    SCOPED_TRACE(fs::relative(file, kSampleModels).string());
    ASSERT_TRUE(scene.framing.has_value());
    for (const Size& size : kSizes) {
      const float aspect = static_cast<float>(size.width) / size.height;
      Camera camera = scene_camera(scene, aspect);
      camera.aspect = aspect;  // as every caller sets it (it is already)
      Framebuffer image = render_depth(scene, camera, size.width, size.height);
      EXPECT_EQ(border_pixels_drawn(image), 0) << size.width << "x" << size.height;
      EXPECT_GT(pixels_drawn(image), 0) << size.width << "x" << size.height;
    }
    ++checked;
  }
  EXPECT_GE(checked, 25);
}

TEST(Framing, ACameraSetByHandIsKeptAtEveryAspect) {
  Scene scene;
  scene.add_object(cube(), Material{});
  scene.camera = Camera::look_at({0, 0, 3}, {0, 0, 0});
  EXPECT_EQ(scene_camera(scene, 0.5f).eye, glm::vec3(0, 0, 3));
  scene.framing = Framing{};
  EXPECT_NE(scene_camera(scene, 0.5f).eye, glm::vec3(0, 0, 3));
}

// A model without any symmetry: a long box along the right, a ball in front, a cone on top.
Scene lopsided_scene(const glm::mat4& transform = glm::mat4(1.0f)) {
  Scene scene;
  scene.add_object(box({2.0f, 0.4f, 0.6f}), Material{},
                   transform * glm::translate(glm::mat4(1.0f), {0.6f, 0.0f, 0.0f}));
  scene.add_object(uv_sphere(0.35f, 16, 8), Material{},
                   transform * glm::translate(glm::mat4(1.0f), {-0.2f, 0.1f, 0.5f}));
  scene.add_object(cone(0.3f, 0.9f, 12), Material{},
                   transform * glm::translate(glm::mat4(1.0f), {-0.3f, 0.2f, -0.1f}));
  return scene;
}

// Pixels whose depths differ by more than `tolerance`, or drawn in one image only.
int depth_differences(const Framebuffer& a, const Framebuffer& b, float tolerance = 1e-3f) {
  int different = 0;
  for (std::size_t i = 0; i < a.depth().size(); ++i) {
    const float da = a.depth()[i], db = b.depth()[i];
    if ((da < 1.0f) != (db < 1.0f) || std::abs(da - db) > tolerance) ++different;
  }
  return different;
}

// A half turn of the eye shows what a half turn of the model about the vertical axis through
// its centre shows (a half turn keeps the bounding box, so the framing distance): the other
// side. Any azimuth turns the eye's direction by that angle about the up axis.
TEST(Framing, AzimuthTurnsTheEyeAboutTheUpAxis) {
  constexpr int kW = 160, kH = 120;
  const float aspect = static_cast<float>(kW) / kH;
  const Scene model = lopsided_scene();
  const glm::vec3 centre = model.bounds().centre();
  Framing half_turn;
  half_turn.azimuth_degrees = 180.0f;
  Framebuffer seen = render_depth(model, frame_scene(model, aspect, half_turn), kW, kH);
  const glm::mat4 turn = glm::translate(glm::mat4(1.0f), centre) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(180.0f), {0, 1, 0}) *
                         glm::translate(glm::mat4(1.0f), -centre);
  const Scene turned = lopsided_scene(turn);
  Framebuffer expected = render_depth(turned, frame_scene(turned, aspect), kW, kH);
  EXPECT_LT(depth_differences(seen, expected), kW * kH / 500);
  Framebuffer front = render_depth(model, frame_scene(model, aspect), kW, kH);
  EXPECT_GT(depth_differences(seen, front), kW * kH / 20) << "the other side looks the same";

  auto heading_degrees = [](const Camera& c) {
    const glm::vec3 back = c.eye - c.target;
    return glm::degrees(std::atan2(back.x, back.z));  // from +Z toward +X
  };
  const float start = heading_degrees(frame_scene(model, aspect));
  for (float azimuth : {90.0f, -40.0f, 10.0f}) {
    Framing framing;
    framing.azimuth_degrees = azimuth;
    const Camera camera = frame_scene(model, aspect, framing);
    EXPECT_NEAR(std::remainder(heading_degrees(camera) - start - azimuth, 360.0f), 0.0f, 1e-3f);
    EXPECT_EQ(border_pixels_drawn(render_depth(model, camera, kW, kH)), 0);
  }
}

// Each up axis, with the right and front the documentation gives it: the view frames the model
// as the default (+Y up) view frames the model turned so that (right, up, front) become
// (+X, +Y, +Z).
TEST(Framing, UpAxisTurnsTheViewAsTurningTheModelWould) {
  struct Axes {
    const char* name;
    glm::vec3 right, up, front;
  };
  const Axes kAxes[] = {
      {"+X", {0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, {"-X", {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}},
      {"+Y", {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {"-Y", {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}},
      {"+Z", {1, 0, 0}, {0, 0, 1}, {0, -1, 0}}, {"-Z", {1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
  };
  constexpr int kW = 160, kH = 120;
  const float aspect = static_cast<float>(kW) / kH;
  const Scene model = lopsided_scene();
  for (const Axes& axes : kAxes) {
    SCOPED_TRACE(axes.name);
    Framing framing;
    framing.up = axes.up;
    Camera camera = frame_scene(model, aspect, framing);
    EXPECT_NO_THROW(camera.validate());
    Framebuffer seen = render_depth(model, camera, kW, kH);
    // The rotation taking right, up and front to x, y and z: those vectors are its rows.
    glm::mat4 to_y_up(1.0f);
    for (int column = 0; column < 3; ++column) {
      to_y_up[column] = glm::vec4(axes.right[column], axes.up[column], axes.front[column], 0.0f);
    }
    const Scene turned = lopsided_scene(to_y_up);
    Framebuffer expected = render_depth(turned, frame_scene(turned, aspect), kW, kH);
    EXPECT_GT(pixels_drawn(seen), kW * kH / 20);
    EXPECT_LT(depth_differences(seen, expected), kW * kH / 500);
  }
}

TEST(Framing, ElevationNinetyLooksStraightDownWithAValidCamera) {
  const Scene model = lopsided_scene();
  for (glm::vec3 up : {glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(-1, 0, 0)}) {
    for (float elevation : {90.0f, -90.0f}) {
      SCOPED_TRACE(elevation);
      Framing framing;
      framing.up = up;
      framing.elevation_degrees = elevation;
      framing.azimuth_degrees = 30.0f;
      Camera camera = frame_scene(model, 1.0f, framing);
      EXPECT_NO_THROW(camera.validate());
      EXPECT_LT(glm::length(camera.forward() + up * (elevation > 0 ? 1.0f : -1.0f)), 1e-5f);
      EXPECT_NEAR(glm::dot(camera.up, up), 0.0f, 1e-5f);  // perpendicular: never degenerate
      Framebuffer image = render_depth(model, camera, 64, 64);
      EXPECT_EQ(border_pixels_drawn(image), 0);
      EXPECT_GT(pixels_drawn(image), 64 * 64 / 10);
      // Orthographic framing keeps the line of sight, and so the top view.
      Camera parallel = fit_orthographic(model, camera, 1.0f);
      EXPECT_NO_THROW(parallel.validate());
      EXPECT_LT(glm::length(parallel.forward() - camera.forward()), 1e-5f);
      EXPECT_EQ(border_pixels_drawn(render_depth(model, parallel, 64, 64)), 0);
    }
  }
  // Level: the eye at the height of the model's centre.
  Framing level;
  level.elevation_degrees = 0.0f;
  Camera camera = frame_scene(model, 1.0f, level);
  EXPECT_NEAR(camera.eye.y, camera.target.y, 1e-5f);
}

TEST(Framing, BadFramingsNameTheField) {
  const Scene model = lopsided_scene();
  Framing framing;
  framing.up = glm::normalize(glm::vec3(1, 1, 0));
  EXPECT_THROW(frame_scene(model, 1.0f, framing), Error);
  framing = Framing{};
  framing.elevation_degrees = 91.0f;
  EXPECT_THROW(frame_scene(model, 1.0f, framing), Error);
  framing = Framing{};
  framing.azimuth_degrees = NAN;
  EXPECT_THROW(frame_scene(model, 1.0f, framing), Error);
}

}  // namespace
}  // namespace facet::test
