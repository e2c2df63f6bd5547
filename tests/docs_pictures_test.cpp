// The pictures of docs/pipeline.md: the shapes scene at 400x225 as each stage of the pipeline
// leaves it, drawn through the views that show that stage. Each is a golden in docs/pipeline/,
// compared as tests/golden's are, so the docs show what the code draws; after an intended change
// regenerate them with FACET_UPDATE_GOLDENS=1 --gtest_filter='DocsPictures*' and look at them.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <utility>

#include "facet/color.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/render_texture.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/golden.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 400;
constexpr int kHeight = 225;

struct Picture {
  const char* name;  // docs/pipeline/<name>.png
  ShadingModel shading = ShadingModel::lambert;
  DebugView debug_view = DebugView::none;
  int tile_size = 64;
  float far_plane = 0.0f;         // 0: the scene camera's
  float ground_uv_repeat = 1.0f;  // the ground's texture coordinates times this
  bool sky = false;               // the procedural sky behind the scene, drawn at resolve
};

// The view each stage's section of docs/pipeline.md shows (1, recording, has none).
const Picture kPictures[] = {
    // 2. Vertex transform: a varying the vertex stage writes (the world normal), interpolated.
    {.name = "vertex_normals", .shading = ShadingModel::normals},
    // 3. Assembly, culling and clipping: the edges of the triangles culling kept, clipped.
    {.name = "assembly_wireframe", .shading = ShadingModel::wireframe},
    // 4. Setup: texture coordinates through the varying planes, divided by 1/w per pixel. The
    // ground's run 0..1 over its whole 40 units; repeated, they show the perspective.
    {.name = "setup_texcoords", .shading = ShadingModel::texcoords, .ground_uv_repeat = 10.0f},
    // 5. Binning: each tile tinted by how many primitives its bin holds; 32-pixel tiles, so the
    // 400x225 image has 13x8 of them.
    {.name = "bin_tile_bins", .debug_view = DebugView::tile_bins, .tile_size = 32},
    // 6. Raster: how many triangles covered each pixel, with no depth test.
    {.name = "raster_overdraw", .debug_view = DebugView::overdraw},
    // 6. Raster: the view depth of the surface the depth test kept. The default far plane (100)
    // would put the whole scene in the lightest quarter; 20 gives contrast, as tests/golden's.
    {.name = "raster_depth", .shading = ShadingModel::depth, .far_plane = 20.0f},
    // 7. Resolve: the shaded frame, the sky in the pixels nothing covered, encoded to sRGB.
    {.name = "resolve_shaded", .sky = true},
};

void PrintTo(const Picture& picture, std::ostream* os) { *os << picture.name; }

Framebuffer render(const Picture& picture) {
  Scene scene = make_shapes_scene();
  for (Material& material : scene.materials) material.shading = picture.shading;
  if (picture.ground_uv_repeat != 1.0f) {
    Mesh ground = *scene.meshes[0];  // the first object make_shapes_scene adds
    for (glm::vec2& uv : ground.texcoords) uv *= picture.ground_uv_repeat;
    scene.meshes[0] = std::make_shared<const Mesh>(std::move(ground));
  }
  scene.lighting.environment.show_as_background = picture.sky;
  Camera camera = scene.camera;
  camera.aspect = static_cast<float>(kWidth) / kHeight;
  if (picture.far_plane > 0.0f) camera.far_plane = picture.far_plane;

  RenderSettings settings;
  settings.tile_size = picture.tile_size;
  settings.debug_view = picture.debug_view;
  // `facet render`'s default background, sRGB sky blue.
  settings.clear_color = glm::vec4(srgb_to_linear({0.53f, 0.66f, 0.82f}), 1.0f);
  Renderer renderer(settings);
  Framebuffer framebuffer(kWidth, kHeight);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(framebuffer);
  return framebuffer;
}

class PipelineStage : public ::testing::TestWithParam<Picture> {};

TEST_P(PipelineStage, MatchesGolden) {
  const Picture& picture = GetParam();
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / (std::string("docs_") + picture.name + ".png"))
          .string();
  write_image(render(picture), path);
  expect_matches_golden_in(FACET_DOCS_PICTURE_DIR, path, picture.name);
}

INSTANTIATE_TEST_SUITE_P(DocsPictures, PipelineStage, ::testing::ValuesIn(kPictures),
                         [](const ::testing::TestParamInfo<Picture>& param_info) {
                           return std::string(param_info.param.name);
                         });

// "Tone mapping": the scene 1.5 stops brighter through each curve, side by side, as the
// command under the picture draws it.
TEST(DocsPictures, ToneMappingCurvesSideBySide) {
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "docs_tone_mapping.png").string();
  const CommandResult r = run_command(std::string(FACET_CLI) +
                                      " render --scene shapes --size 240x135 --exposure 1.5 "
                                      "--compare none,pbr-neutral,aces -q -o '" +
                                      path + "'");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  expect_matches_golden_in(FACET_DOCS_PICTURE_DIR, path, "tone_mapping");
}

// "Render textures": the shapes seen from behind, rendered into a RenderTexture with its mip
// chain, shown on a screen in a dark frame standing behind them in the same scene.
TEST(DocsPictures, RenderTextureOnAScreenInTheScene) {
  const Scene scene = make_shapes_scene();
  RenderSettings settings;
  settings.clear_color = glm::vec4(srgb_to_linear({0.53f, 0.66f, 0.82f}), 1.0f);
  Renderer renderer(settings);

  RenderTexture behind(256, 144, {.mipmaps = true});
  renderer.begin_frame(
      Camera::look_at({-2.0f, 2.5f, -7.0f}, {0.0f, 0.5f, 0.0f}, {0, 1, 0}, 50.0f, 256.0f / 144.0f),
      scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(behind);

  // An upright rectangle at depth z, its texture coordinates 0 to 1 (v up).
  auto rectangle = [](glm::vec2 low, glm::vec2 high, float z) {
    Mesh mesh;
    mesh.positions = {
        {low.x, low.y, z}, {high.x, low.y, z}, {high.x, high.y, z}, {low.x, high.y, z}};
    mesh.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
  };
  const Mesh screen = rectangle({-0.4f, 1.6f}, {2.8f, 3.4f}, -2.5f);
  const Mesh frame = rectangle({-0.5f, 1.5f}, {2.9f, 3.5f}, -2.51f);
  Material shown;
  shown.shading = ShadingModel::unlit;
  shown.base_color_map.texture = behind.texture();
  shown.base_color_map.sampler.wrap_u = shown.base_color_map.sampler.wrap_v = Wrap::clamp_to_edge;
  Material dark;
  dark.shading = ShadingModel::unlit;
  dark.base_color = {0.02f, 0.02f, 0.02f, 1.0f};

  Camera camera = scene.camera;
  camera.aspect = static_cast<float>(kWidth) / kHeight;
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.draw(frame, dark);
  renderer.draw(screen, shown);
  Framebuffer framebuffer(kWidth, kHeight);
  renderer.finish(framebuffer);
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "docs_render_texture.png").string();
  write_image(framebuffer, path);
  expect_matches_golden_in(FACET_DOCS_PICTURE_DIR, path, "render_texture");
}

// docs/pipeline.md's "Reflections": the islands' sea mirroring the second island, as `facet
// render --scene islands --eye 150,6,80 --target 330,5,10` draws it (4 samples, shadows, PBR
// Neutral), at 400x225.
TEST(DocsPictures, Reflections) {
  Scene scene = make_builtin_scene("islands");
  const float aspect = static_cast<float>(kWidth) / kHeight;
  const Camera camera = Camera::look_at({150.0f, 6.0f, 80.0f}, {330.0f, 5.0f, 10.0f}, {0, 1, 0},
                                        scene.camera.fov_y_degrees, aspect, scene.camera.near_plane,
                                        scene.camera.far_plane);
  RenderSettings settings;
  settings.msaa = 4;
  settings.shadows = true;
  settings.tone_mapping = ToneMapping::pbr_neutral;
  const Framebuffer framebuffer = render_scene_image(scene, camera, kWidth, kHeight, settings);
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "docs_reflections.png").string();
  write_image(framebuffer, path);
  expect_matches_golden_in(FACET_DOCS_PICTURE_DIR, path, "reflections");
}

}  // namespace
}  // namespace facet::test
