// The extra outputs (ExtraOutputs): exact view depths and ray distances, normals, instance ids,
// triangle ids with barycentrics and albedo, checked against what the scene says each pixel
// must hold: distances against the geometry, barycentrics by projecting the point they name
// back to the pixel centre.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>
#include <vector>

#include "facet/camera.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 96, kHeight = 64;

ExtraOutputs everything(NormalSpace normals = NormalSpace::world) {
  ExtraOutputs all;
  all.view_depth = all.ray_distance = all.instance_ids = true;
  all.triangle_ids = all.barycentrics = all.albedo = true;
  all.normals = normals;
  return all;
}

Material unlit(glm::vec4 color = glm::vec4(1.0f)) {
  Material material;
  material.shading = ShadingModel::unlit;
  material.base_color = color;
  return material;
}

std::size_t index(int x, int y) { return static_cast<std::size_t>(y) * kWidth + x; }

// The view-space direction through pixel (x, y)'s centre, at view depth 1.
glm::vec3 pixel_ray(const Camera& camera, int x, int y) {
  const float tan_y = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
  const float ndc_x = (x + 0.5f) / kWidth * 2.0f - 1.0f;
  const float ndc_y = 1.0f - (y + 0.5f) / kHeight * 2.0f;
  return {ndc_x * tan_y * camera.aspect, ndc_y * tan_y, -1.0f};
}

TEST(ExtraOutputs, DepthsAreTheDistancesOfTheSurfaceDrawn) {
  const Camera camera = test_camera(kWidth, kHeight, 60.0f, 0.5f, 50.0f);
  for (float distance : {0.75f, 4.0f, 37.0f}) {
    // A wall facing the camera over the upper half of the frame, the lower half empty.
    const Mesh wall = quad({-100, 0, -distance}, {100, 0, -distance}, {100, 100, -distance},
                           {-100, 100, -distance});
    Renderer renderer;
    Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, everything());
    renderer.begin_frame(camera);
    renderer.draw(wall, unlit());
    renderer.finish(image);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const std::size_t i = index(x, y);
        if (image.depth()[i] == 1.0f) {  // nothing drawn
          EXPECT_EQ(image.view_depth()[i], 0.0f);
          EXPECT_EQ(image.ray_distance()[i], 0.0f);
          continue;
        }
        ASSERT_NEAR(image.view_depth()[i], distance, distance * 1e-5f) << x << ", " << y;
        const float ray = distance * glm::length(pixel_ray(camera, x, y));
        ASSERT_NEAR(image.ray_distance()[i], ray, ray * 1e-5f) << x << ", " << y;
        // The window depth says the same, less exactly.
        ASSERT_NEAR(camera.view_distance(image.depth()[i]), distance, distance * 1e-3f);
      }
    }
    EXPECT_GT(image.view_depth()[index(kWidth / 2, kHeight / 4)], 0.0f);
    EXPECT_EQ(image.view_depth()[index(kWidth / 2, kHeight * 3 / 4)], 0.0f);
  }
}

TEST(ExtraOutputs, UnderAnOrthographicCameraRaysStartOnTheImagePlane) {
  const Camera camera = Camera::orthographic({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 4.0f,
                                             float(kWidth) / kHeight, 0.5f, 50.0f);
  const Mesh wall = quad({-100, 0, -6}, {100, 0, -6}, {100, 100, -6}, {-100, 100, -6});
  Renderer renderer;
  Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, everything());
  renderer.begin_frame(camera);
  renderer.draw(wall, unlit());
  renderer.finish(image);
  int drawn = 0;
  for (std::size_t i = 0; i < image.depth().size(); ++i) {
    if (image.depth()[i] == 1.0f) continue;
    ++drawn;
    ASSERT_NEAR(image.view_depth()[i], 6.0f, 6e-5f);
    ASSERT_EQ(image.ray_distance()[i], image.view_depth()[i]);
  }
  EXPECT_EQ(drawn, kWidth * kHeight / 2);
}

TEST(ExtraOutputs, NormalsAreTheSurfacesInWorldOrCameraSpace) {
  const Camera camera =
      Camera::look_at({0.5f, 1.0f, 2.5f}, {0, 0, 0}, {0, 1, 0}, 60.0f, float(kWidth) / kHeight);
  // A tilted rectangle, its normals from the mesh, and a pyramid without normals, whose faces
  // get their face normals.
  const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), 0.6f, glm::vec3(1, 0.3f, 0));
  const glm::vec3 tilted_normal = glm::normalize(glm::mat3(tilt) * glm::vec3(0, 0, 1));
  const Mesh card = rectangle(1.5f, 1.0f);
  Mesh faceted = pyramid(1.0f, 1.0f, 1.0f);
  faceted.normals.clear();
  for (NormalSpace space : {NormalSpace::world, NormalSpace::camera}) {
    ExtraOutputs want;
    want.normals = space;
    want.instance_ids = true;
    Renderer renderer;
    Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, want);
    renderer.begin_frame(camera);
    renderer.set_instance_id(1);
    renderer.draw(card, unlit(), glm::translate(glm::mat4(1.0f), {-1.0f, 0, 0}) * tilt);
    renderer.set_instance_id(2);
    renderer.draw(faceted, unlit(), glm::translate(glm::mat4(1.0f), {1.0f, 0, 0}));
    renderer.finish(image);
    const glm::mat3 to_space =
        space == NormalSpace::camera ? glm::mat3(camera.view()) : glm::mat3(1.0f);
    int card_pixels = 0, pyramid_pixels = 0;
    for (std::size_t i = 0; i < image.instance_ids().size(); ++i) {
      const glm::vec3 n(image.normals()[3 * i], image.normals()[3 * i + 1],
                        image.normals()[3 * i + 2]);
      switch (image.instance_ids()[i]) {
        case 0:
          ASSERT_EQ(n, glm::vec3(0.0f));
          break;
        case 1:
          ++card_pixels;
          ASSERT_LT(glm::length(n - to_space * tilted_normal), 1e-5f);
          break;
        default: {
          ++pyramid_pixels;
          ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
          // A face normal of the pyramid: its sides lean out by atan(0.5) from the vertical.
          const glm::vec3 world = glm::transpose(to_space) * n;
          ASSERT_TRUE(std::abs(world.y - 1.0f / std::sqrt(5.0f)) < 1e-4f ||
                      std::abs(world.y + 1.0f) < 1e-4f)
              << world.x << " " << world.y << " " << world.z;
        }
      }
    }
    EXPECT_GT(card_pixels, 200);
    EXPECT_GT(pyramid_pixels, 200);
  }
}

TEST(ExtraOutputs, InstanceIdsAreTheDrawsNumbersUnlessSet) {
  const Camera camera = test_camera(kWidth, kHeight);
  const Mesh left = soup_quad(-2.0f, -1.0f, -0.5f, 1.0f, -3.0f);
  const Mesh right = soup_quad(0.5f, -1.0f, 2.0f, 1.0f, -3.0f);
  const Mesh far_right = soup_quad(0.0f, -1.0f, 2.5f, 1.0f, -4.0f);  // behind `right`
  ExtraOutputs want;
  want.instance_ids = true;
  for (bool numbered : {true, false}) {
    Renderer renderer;
    Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, want);
    renderer.begin_frame(camera);
    if (!numbered) renderer.set_instance_id(70000);
    renderer.draw(left, unlit());
    if (!numbered) renderer.set_instance_id(9);
    renderer.draw(right, unlit());
    renderer.draw(far_right, unlit());
    renderer.finish(image);
    const auto id = [&](int x, int y) { return image.instance_ids()[index(x, y)]; };
    EXPECT_EQ(id(2, kHeight / 2), 0u);
    EXPECT_EQ(id(kWidth / 4, kHeight / 2), numbered ? 1u : 70000u);
    EXPECT_EQ(id(kWidth * 3 / 4, kHeight / 2), numbered ? 2u : 9u);
    EXPECT_EQ(id(kWidth / 2 + 2, kHeight / 2), numbered ? 3u : 9u);  // only far_right here
  }
}

// Projects a world point to window coordinates (pixels, y down).
glm::vec2 window_position(const Camera& camera, glm::vec3 p) {
  const glm::vec4 clip = camera.view_projection() * glm::vec4(p, 1.0f);
  return {(clip.x / clip.w * 0.5f + 0.5f) * kWidth, (0.5f - clip.y / clip.w * 0.5f) * kHeight};
}

// Every covered pixel names a triangle of the mesh and barycentrics whose point projects to
// the pixel's centre; every uncovered one names none.
void expect_barycentrics_name_the_pixel(const Framebuffer& image, const Mesh& mesh,
                                        const Camera& camera, float tolerance_pixels) {
  int covered = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = index(x, y);
      const std::uint32_t id = image.triangle_ids()[i];
      const float* b = &image.barycentrics()[3 * i];
      if (image.depth()[i] == 1.0f) {
        ASSERT_EQ(id, 0u) << x << ", " << y;
        ASSERT_EQ(b[0] + b[1] + b[2], 0.0f);
        continue;
      }
      ++covered;
      ASSERT_GE(id, 1u) << x << ", " << y;
      ASSERT_LE(id, mesh.primitive_count());
      ASSERT_NEAR(b[0] + b[1] + b[2], 1.0f, 1e-5f);
      for (int k = 0; k < 3; ++k) ASSERT_GE(b[k], -1e-3f) << x << ", " << y;
      const std::uint32_t* corner = &mesh.indices[3 * (id - 1)];
      const glm::vec3 p = b[0] * mesh.positions[corner[0]] + b[1] * mesh.positions[corner[1]] +
                          b[2] * mesh.positions[corner[2]];
      const glm::vec2 at = window_position(camera, p);
      ASSERT_NEAR(at.x, x + 0.5f, tolerance_pixels) << x << ", " << y << " triangle " << id;
      ASSERT_NEAR(at.y, y + 0.5f, tolerance_pixels) << x << ", " << y << " triangle " << id;
    }
  }
  EXPECT_GT(covered, kWidth * kHeight / 4);
}

TEST(ExtraOutputs, BarycentricsProjectToThePixelCentre) {
  // A ground grid of 20,000 triangles seen at a slant (ids past 4096 need the id's high half),
  // running through the near plane (clipped triangles keep the barycentrics of the whole).
  const Mesh ground = plane(40.0f, 40.0f, 100, 100);
  ASSERT_EQ(ground.primitive_count(), 20000u);
  const Camera camera = Camera::look_at({0.3f, 0.3f, 1.0f}, {0, 0, -1.0f}, {0, 1, 0}, 60.0f,
                                        float(kWidth) / kHeight, 0.5f, 100.0f);
  Renderer renderer;
  Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, everything());
  renderer.begin_frame(camera);
  renderer.draw(ground, unlit());
  renderer.finish(image);
  EXPECT_GT(renderer.stats().clipped, 0u);
  expect_barycentrics_name_the_pixel(image, ground, camera, 0.02f);
  std::uint32_t largest = 0;
  for (std::uint32_t id : image.triangle_ids()) largest = std::max(largest, id);
  EXPECT_GT(largest, 4096u);
}

TEST(ExtraOutputs, AlbedoIsTheUnlitSurfaceColor) {
  const Camera camera = test_camera(kWidth, kHeight);
  Mesh card = soup_quad(-1.0f, -1.0f, 1.0f, 1.0f, -3.0f);
  card.colors.assign(card.positions.size(), glm::vec4(0.5f, 1.0f, 0.25f, 1.0f));
  card.normals.assign(card.positions.size(), glm::vec3(0, 0, 1));
  Material lit;
  lit.shading = ShadingModel::lambert;
  lit.base_color = {0.8f, 0.4f, 1.0f, 1.0f};
  lit.use_vertex_colors = true;
  ExtraOutputs want;
  want.albedo = true;
  Renderer renderer;
  Framebuffer image(kWidth, kHeight, ColorFormat::rgba32f, DepthImage::keep, want);
  renderer.begin_frame(camera);
  renderer.draw(card, lit);
  renderer.finish(image);
  const std::size_t centre = index(kWidth / 2, kHeight / 2);
  const glm::vec4 albedo(image.albedo()[4 * centre], image.albedo()[4 * centre + 1],
                         image.albedo()[4 * centre + 2], image.albedo()[4 * centre + 3]);
  EXPECT_LT(glm::length(albedo - glm::vec4(0.4f, 0.4f, 0.25f, 1.0f)), 1e-6f);
  EXPECT_NE(image.pixel(kWidth / 2, kHeight / 2), albedo);  // the color is lit
  EXPECT_EQ(image.albedo()[0], 0.0f);                       // a corner: background
}

TEST(ExtraOutputs, CutOutPixelsAreCutOutOfEveryOutputAndBlendedDrawsAreOpaque) {
  const Camera camera = test_camera(kWidth, kHeight);
  // Left: a card whose alpha runs from 0 to 1 across it, cut out at 0.5. Right: a half
  // transparent card.
  Mesh ramp = quad({-2.0f, -1.0f, -3.0f}, {-0.2f, -1.0f, -3.0f}, {-0.2f, 1.0f, -3.0f},
                   {-2.0f, 1.0f, -3.0f});
  ramp.colors = {{1, 1, 1, 0}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 0}};
  Material cut = unlit();
  cut.use_vertex_colors = true;
  cut.alpha_mode = AlphaMode::mask;
  cut.alpha_cutoff = 0.5f;
  Material glass = unlit({0.2f, 0.5f, 1.0f, 0.5f});
  glass.alpha_mode = AlphaMode::blend;
  const Mesh pane = soup_quad(0.2f, -1.0f, 2.0f, 1.0f, -3.0f);
  Renderer renderer;
  Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, everything());
  renderer.begin_frame(camera);
  renderer.draw(ramp, cut);
  renderer.draw(pane, glass);
  renderer.finish(image);
  // Across the ramp: the pixels the color pass cut out, and those it drew.
  int cut_pixels = 0, kept_pixels = 0;
  const int y = kHeight / 2;
  const int ramp_begin = static_cast<int>(window_position(camera, {-2.0f, 0, -3.0f}).x) + 1;
  const int ramp_end = static_cast<int>(window_position(camera, {-0.2f, 0, -3.0f}).x);
  for (int x = ramp_begin; x < ramp_end; ++x) {
    const std::size_t i = index(x, y);
    const bool drawn = image.depth()[i] < 1.0f;
    EXPECT_EQ(image.instance_ids()[i] != 0, drawn) << x;
    EXPECT_EQ(image.triangle_ids()[i] != 0, drawn) << x;
    EXPECT_EQ(image.albedo()[4 * i + 3] != 0.0f, drawn) << x;
    ++(drawn ? kept_pixels : cut_pixels);
  }
  EXPECT_GT(cut_pixels, 5);
  EXPECT_GT(kept_pixels, 5);
  const std::size_t glass_pixel = index(kWidth * 3 / 4, y);
  EXPECT_EQ(image.instance_ids()[glass_pixel], 2u);
  EXPECT_NEAR(image.view_depth()[glass_pixel], 3.0f, 1e-5f);
  EXPECT_NEAR(image.albedo()[4 * glass_pixel + 3], 0.5f, 1e-6f);
}

TEST(ExtraOutputs, LeaveTheColorImageAsItWasAndAreTheSameForAnyThreadsAndTiles) {
  const Camera camera =
      Camera::look_at({1.5f, 1.2f, 2.5f}, {0, 0, 0}, {0, 1, 0}, 60.0f, float(kWidth) / kHeight);
  const Mesh ball = uv_sphere(0.8f, 24, 12);
  const Mesh floor = plane(6.0f, 6.0f, 4, 4);
  Material lit;
  lit.shading = ShadingModel::blinn_phong;
  const auto render = [&](const ExtraOutputs& want, int threads, int tile_size) {
    RenderSettings settings;
    settings.threads = threads;
    settings.tile_size = tile_size;
    Renderer renderer(settings);
    Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, want);
    renderer.begin_frame(camera);
    renderer.draw(ball, lit);
    renderer.draw(floor, lit, glm::translate(glm::mat4(1.0f), {0, -0.8f, 0}));
    renderer.finish(image);
    return image;
  };
  const Framebuffer plain = render({}, 1, 64);
  const Framebuffer first = render(everything(NormalSpace::camera), 1, 64);
  EXPECT_EQ(first.rgba8(), plain.rgba8());
  EXPECT_EQ(first.depth(), plain.depth());
  for (auto [threads, tile_size] : {std::pair{3, 16}, std::pair{2, 128}}) {
    const Framebuffer other = render(everything(NormalSpace::camera), threads, tile_size);
    EXPECT_EQ(other.view_depth(), first.view_depth());
    EXPECT_EQ(other.ray_distance(), first.ray_distance());
    EXPECT_EQ(other.normals(), first.normals());
    EXPECT_EQ(other.instance_ids(), first.instance_ids());
    EXPECT_EQ(other.triangle_ids(), first.triangle_ids());
    EXPECT_EQ(other.barycentrics(), first.barycentrics());
    EXPECT_EQ(other.albedo(), first.albedo());
  }
}

TEST(ExtraOutputs, IdsTooLargeForTheOutputAreRefusedBeforeDrawing) {
  const Camera camera = test_camera(kWidth, kHeight);
  const Mesh card = soup_quad(-1.0f, -1.0f, 1.0f, 1.0f, -3.0f);
  ExtraOutputs want;
  want.instance_ids = true;
  Renderer renderer;
  Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::keep, want);
  renderer.begin_frame(camera);
  renderer.set_instance_id(1u << 24);
  renderer.draw(card, unlit());
  try {
    renderer.finish(image);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("instance id 16777216"), std::string::npos) << e.what();
  }
  for (std::uint8_t byte : image.rgba8()) ASSERT_EQ(byte, 0);  // nothing drawn
}

}  // namespace
}  // namespace facet::test
