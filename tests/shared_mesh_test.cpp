// Meshes drawn through shared pointers to const (Renderer::draw's second form, which draw_scene
// uses) are checked and bounded once, then remembered: the frames they draw must be those of
// the same meshes drawn by reference, a bad mesh must be refused every time, and the renderer
// must let go of a mesh once it is no longer drawn.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/trigonometric.hpp>
#include <memory>

#include "facet/error.hpp"
#include "facet/procedural.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 64, kHeight = 48;

std::shared_ptr<const Mesh> sphere_at(glm::vec3 centre) {
  Mesh mesh = uv_sphere(1.0f, 12, 12);
  for (glm::vec3& p : mesh.positions) p += centre;
  return std::make_shared<const Mesh>(std::move(mesh));
}

// Draws `mesh` into fb seen from the test camera turned by `yaw` degrees, through the given
// form of draw().
void draw_frame(Renderer& renderer, Framebuffer& fb, const std::shared_ptr<const Mesh>& mesh,
                bool shared, float yaw) {
  Camera camera = test_camera(kWidth, kHeight);
  const float radians = glm::radians(yaw);
  camera.target = camera.eye + glm::vec3(-std::sin(radians), 0.0f, -std::cos(radians));
  renderer.begin_frame(camera);
  Material material;
  material.shading = ShadingModel::lambert;
  if (shared) {
    renderer.draw(mesh, material);
  } else {
    renderer.draw(*mesh, material);
  }
  renderer.finish(fb);
}

TEST(SharedMesh, FramesAreThoseOfTheMeshDrawnByReference) {
  const std::shared_ptr<const Mesh> mesh = sphere_at({0.0f, 0.0f, -5.0f});
  Renderer by_reference, by_pointer;
  Framebuffer expected(kWidth, kHeight), got(kWidth, kHeight);
  // In view, then out of view (the remembered bounds cull it), then in view again.
  for (float yaw : {0.0f, 150.0f, 10.0f}) {
    draw_frame(by_reference, expected, mesh, false, yaw);
    draw_frame(by_pointer, got, mesh, true, yaw);
    EXPECT_EQ(got.rgba8(), expected.rgba8()) << yaw;
    EXPECT_EQ(got.depth(), expected.depth()) << yaw;
    EXPECT_EQ(by_pointer.stats().drawn, by_reference.stats().drawn) << yaw;
    EXPECT_EQ(by_pointer.stats().culled, by_reference.stats().culled) << yaw;
  }
  EXPECT_EQ(by_pointer.stats().drawn, by_reference.stats().drawn);
  EXPECT_GT(by_reference.stats().drawn, 0u);
}

TEST(SharedMesh, ABadMeshIsRefusedEveryTimeAndANewOneInItsPlaceIsChecked) {
  Mesh bad = uv_sphere(1.0f, 6, 6);
  bad.indices[4] = static_cast<std::uint32_t>(bad.positions.size());
  const auto bad_mesh = std::make_shared<const Mesh>(bad);
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  EXPECT_THROW(renderer.draw(bad_mesh, Material{}), Error);  // before begin_frame()
  for (int frame = 0; frame < 2; ++frame) {
    renderer.begin_frame(test_camera(kWidth, kHeight));
    try {
      renderer.draw(bad_mesh, Material{});
      FAIL() << "an out-of-range index must throw, frame " << frame;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("index 4"), std::string::npos) << e.what();
    }
    renderer.finish(fb);
  }
  EXPECT_EQ(renderer.stats().triangles_in, 0u);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  EXPECT_THROW(renderer.draw(std::shared_ptr<const Mesh>(), Material{}), Error);
  const auto mended = std::make_shared<const Mesh>(uv_sphere(1.0f, 6, 6));
  EXPECT_NO_THROW(renderer.draw(mended, Material{}));
}

TEST(SharedMesh, TheRendererLetsGoOfAMeshAFrameAfterTheLastThatDrewIt) {
  const std::shared_ptr<const Mesh> mesh = sphere_at({0.0f, 0.0f, -5.0f});
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  draw_frame(renderer, fb, mesh, true, 0.0f);
  EXPECT_EQ(mesh.use_count(), 2);  // the renderer remembers it
  renderer.begin_frame(test_camera(kWidth, kHeight));
  renderer.finish(fb);
  EXPECT_EQ(mesh.use_count(), 2);  // drawn in the last frame: still remembered
  renderer.begin_frame(test_camera(kWidth, kHeight));
  EXPECT_EQ(mesh.use_count(), 1);
  renderer.finish(fb);
}

}  // namespace
}  // namespace facet::test
