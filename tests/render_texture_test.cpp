// Render textures (facet/render_texture.hpp): a frame rendered offscreen is what later draws
// sample, its mip chain is filtered when asked for, a frame cannot sample its own target, and
// the image is the same for any thread count and tile size.
#include "facet/render_texture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/image_io.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 64, kHeight = 48;

// The shapes scene rendered into target (a RenderTexture or a Framebuffer), one sample a pixel,
// no tone mapping.
template <class Target>
void render_shapes_into(Target& target, RenderSettings settings = {}) {
  static const Scene scene = make_shapes_scene();
  Renderer renderer(settings);
  Camera camera = scene.camera;
  camera.aspect = static_cast<float>(target.width()) / target.height();
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(target);
}

// The same frame rendered into a plain framebuffer: what a render texture's textures must hold.
Framebuffer shapes_reference(RenderSettings settings = {},
                             ColorFormat format = ColorFormat::rgba8_srgb) {
  Framebuffer reference(kWidth, kHeight, format);
  render_shapes_into(reference, settings);
  return reference;
}

// A rectangle filling an orthographic view 2 units tall, its texture coordinates 0 to 1 (v up).
Mesh screen(float aspect) {
  Mesh mesh;
  mesh.positions = {{-aspect, -1, 0}, {aspect, -1, 0}, {aspect, 1, 0}, {-aspect, 1, 0}};
  mesh.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

// The screen drawn unlit with map, filling a width x height framebuffer.
Framebuffer show_on_screen(const TextureMap& map, int width, int height) {
  const float aspect = static_cast<float>(width) / height;
  const Mesh mesh = screen(aspect);
  Material material;
  material.shading = ShadingModel::unlit;
  material.base_color_map = map;
  Renderer renderer;
  renderer.begin_frame(
      Camera::orthographic({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 2.0f, aspect, 0.5f, 1.5f));
  renderer.draw(mesh, material);
  Framebuffer out(width, height);
  renderer.finish(out);
  return out;
}

TEST(RenderTexture, ADrawSamplingItShowsTheImageRenderedIntoIt) {
  RenderTexture target(kWidth, kHeight);
  render_shapes_into(target);
  EXPECT_EQ(target.texture()->level_count(), 1);
  Sampler nearest{Filter::nearest, Wrap::clamp_to_edge, Wrap::clamp_to_edge};
  const Framebuffer reference = shapes_reference();
  EXPECT_EQ(target.texture()->level(0).rgba8, reference.rgba8());
  const Framebuffer shown =
      show_on_screen({target.texture(), nearest, glm::mat3(1.0f)}, kWidth, kHeight);
  EXPECT_EQ(shown.rgba8(), reference.rgba8());

  // Rendered again into, the same texture object holds the new image.
  const std::shared_ptr<const Texture> before = target.texture();
  RenderSettings settings;
  settings.clear_color = {1.0f, 0.0f, 0.0f, 1.0f};
  render_shapes_into(target, settings);
  EXPECT_EQ(target.texture(), before);
  const Framebuffer red_reference = shapes_reference(settings);
  EXPECT_NE(red_reference.rgba8(), reference.rgba8());
  EXPECT_EQ(target.texture()->level(0).rgba8, red_reference.rgba8());
  EXPECT_EQ(show_on_screen({target.texture(), nearest, glm::mat3(1.0f)}, kWidth, kHeight).rgba8(),
            red_reference.rgba8());
  // And a third time, over the buffers the first image was rendered into.
  render_shapes_into(target);
  EXPECT_EQ(target.texture()->level(0).rgba8, reference.rgba8());
}

TEST(RenderTexture, MipmapsAreTheLevelsAverages) {
  for (ColorFormat format : {ColorFormat::rgba8_srgb, ColorFormat::rgba32f}) {
    RenderTexture target(kWidth, kHeight, {format, true, false});
    render_shapes_into(target);
    const Texture& texture = *target.texture();
    ASSERT_EQ(texture.level_count(), 7);  // 64x48 down to 1x1
    for (int level = 1; level < texture.level_count(); ++level) {
      const Texture::Level& above = texture.level(level - 1);
      const Texture::Level& here = texture.level(level);
      for (int y = 0; y < here.height; ++y) {
        for (int x = 0; x < here.width; ++x) {
          glm::vec4 sum(0.0f);
          int n = 0;
          for (int dy = 0; dy < (above.height > 1 ? 2 : 1); ++dy) {
            for (int dx = 0; dx < (above.width > 1 ? 2 : 1); ++dx, ++n) {
              sum += texture.texel(level - 1, 2 * x + dx, 2 * y + dy);
            }
          }
          const glm::vec4 texel = texture.texel(level, x, y);
          for (int k = 0; k < 4; ++k) {
            // An 8-bit level is rounded to its code: half a code step of sRGB at most.
            EXPECT_NEAR(texel[k], sum[k] / n, format == ColorFormat::rgba32f ? 1e-6f : 0.01f)
                << "level " << level << " (" << x << ", " << y << ")";
          }
        }
      }
    }
  }
}

TEST(RenderTexture, DepthTextureHoldsTheWindowDepth) {
  RenderTexture target(kWidth, kHeight, {ColorFormat::rgba8_srgb, false, true});
  render_shapes_into(target);
  ASSERT_NE(target.depth_texture(), nullptr);
  const Texture& depth = *target.depth_texture();
  EXPECT_EQ(depth.format(), Texture::Format::r32f);  // one float a texel
  EXPECT_EQ(depth.level(0).r32f.size(), static_cast<std::size_t>(kWidth) * kHeight);
  const Framebuffer reference = shapes_reference();
  int drawn = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float d = reference.depth_at(x, y);
      EXPECT_EQ(depth.texel(0, x, y), glm::vec4(d, d, d, 1.0f));
      drawn += d < 1.0f;
    }
  }
  EXPECT_GT(drawn, kWidth * kHeight / 4);
  EXPECT_EQ(RenderTexture(4, 4).depth_texture(), nullptr);
}

// Depth alone: no color texture, and the same depths as with color.
TEST(RenderTexture, DepthOnlyTargetsKeepTheSameDepths) {
  RenderTexture both(kWidth, kHeight, {.depth = true});
  RenderTexture depth_only(kWidth, kHeight, {.depth = true, .color = false});
  render_shapes_into(both);
  render_shapes_into(depth_only);
  EXPECT_EQ(depth_only.texture(), nullptr);
  EXPECT_EQ(depth_only.depth_texture()->level(0).r32f, both.depth_texture()->level(0).r32f);
  EXPECT_EQ(depth_only.depth_texture()->level(0).r32f, shapes_reference().depth());
  EXPECT_FALSE(depth_only.framebuffer().has_color());  // no color image allocated either
  EXPECT_THROW(RenderTexture(4, 4, {.color = false}), Error);
}

// Depth alone shades nothing, but what each draw leaves in the depth image stays: an opaque
// quad's depths, none from a cut-out whose texture's alpha removes it nor from a blended one.
TEST(RenderTexture, DepthOnlyTargetsKeepCutOutsAndBlendedDrawsOut) {
  const Mesh mesh = screen(1.0f);
  std::vector<std::uint8_t> clear_rgba(4 * 4 * 4, 0);  // alpha 0 everywhere: cut out
  Material opaque, cut_out, blended;
  cut_out.alpha_mode = AlphaMode::mask;
  cut_out.base_color_map.texture = Texture::from_rgba8(4, 4, clear_rgba, true, "clear");
  blended.alpha_mode = AlphaMode::blend;
  blended.base_color.a = 0.5f;
  auto depths = [&](bool color) {
    RenderTexture target(kWidth, kHeight, {.depth = true, .color = color});
    Renderer renderer;
    renderer.begin_frame(Camera::orthographic({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 2.0f,
                                              static_cast<float>(kWidth) / kHeight, 0.5f, 3.0f));
    renderer.draw(mesh, opaque, glm::translate(glm::mat4(1.0f), {-0.5f, 0.0f, -1.0f}));
    renderer.draw(mesh, cut_out, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, 0.0f}));
    renderer.draw(mesh, blended, glm::translate(glm::mat4(1.0f), {0.5f, 0.0f, 0.5f}));
    renderer.finish(target);
    return target.depth_texture()->level(0).r32f;
  };
  const std::vector<float> alone = depths(false);
  EXPECT_EQ(alone, depths(true));
  // The opaque quad is there and behind the other two everywhere it is seen.
  const float opaque_depth = alone[(kHeight / 2) * kWidth + kWidth / 4];
  EXPECT_LT(opaque_depth, 1.0f);
  for (const float d : alone) EXPECT_TRUE(d == 1.0f || d == opaque_depth) << d;
}

// A quad a quarter of the view wide at x in an orthographic view (none when x is NaN), over
// settings' clear color, into target; returns the target's depth image.
std::vector<float> render_quad(RenderTexture& target, float x, RenderSettings settings) {
  const float aspect = static_cast<float>(target.width()) / target.height();
  settings.tile_size = 16;
  Renderer renderer(settings);
  renderer.begin_frame(
      Camera::orthographic({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 2.0f, aspect, 0.5f, 1.5f));
  static const Mesh quad = screen(1.0f);
  if (!std::isnan(x)) {
    glm::mat4 transform = glm::translate(glm::mat4(1.0f), {x, 0.1f * x, 0.2f * x});
    renderer.draw(quad, Material{}, glm::scale(transform, {0.25f, 0.5f, 1.0f}));
  }
  renderer.finish(target);
  return target.depth_texture()->level(0).r32f;
}

std::vector<float> render_quad_depth(RenderTexture& target, float x, int threads) {
  RenderSettings settings;
  settings.threads = threads;
  return render_quad(target, x, settings);
}

// A target's renders skip the tiles its buffers' earlier render left cleared: each image is
// still the one a new target gets, as the quad moves over and off the tiles, and as the clear
// color and the exposure change; depth alone, and color with depth, 8-bit and float.
TEST(RenderTexture, TargetsRenderedAgainHoldEachNewImage) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const RenderTextureOptions kinds[] = {{.depth = true, .color = false},
                                        {.depth = true},
                                        {.format = ColorFormat::rgba32f, .depth = true}};
  const float xs[] = {-0.8f, 0.7f, nan, -0.2f, 0.8f, nan, nan, -0.5f, -0.5f, 0.3f, nan, nan};
  for (const RenderTextureOptions& options : kinds) {
    for (int threads : {1, 2}) {
      RenderTexture target(kWidth, kHeight, options);
      for (int frame = 0; frame < static_cast<int>(std::size(xs)); ++frame) {
        RenderSettings settings;
        settings.threads = threads;
        if (frame >= 8) settings.clear_color = {0.2f, 0.4f, 0.6f, 1.0f};
        if (frame >= 10) settings.exposure = 1.0f;
        RenderTexture fresh(kWidth, kHeight, options);
        const std::vector<float> expected = render_quad(fresh, xs[frame], settings);
        const std::string where = "frame " + std::to_string(frame) + ", " +
                                  std::to_string(threads) + " threads, color " +
                                  std::to_string(options.color);
        EXPECT_EQ(render_quad(target, xs[frame], settings), expected) << where;
        if (!options.color) continue;
        EXPECT_EQ(target.texture()->level(0).rgba8, fresh.texture()->level(0).rgba8) << where;
        EXPECT_EQ(target.texture()->level(0).rgba32f, fresh.texture()->level(0).rgba32f) << where;
      }
    }
  }
}

// What is written through framebuffer() is shown by update(), and the renders after it clear it
// wherever they draw nothing: writing it forgets which of its tiles were cleared.
TEST(RenderTexture, DepthOnlyTargetsWrittenByHandAreClearedAgain) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> cleared(kWidth * kHeight, 1.0f);
  RenderTexture target(kWidth, kHeight, {.depth = true, .color = false});
  // Both buffers rendered empty: every tile of each known to be cleared.
  for (int i = 0; i < 3; ++i) ASSERT_EQ(render_quad_depth(target, nan, 1), cleared);
  Framebuffer& mine = target.framebuffer();
  std::fill(mine.depth().begin(), mine.depth().end(), 0.5f);
  target.update();
  EXPECT_EQ(target.depth_texture()->level(0).r32f, std::vector<float>(kWidth * kHeight, 0.5f));
  EXPECT_EQ(render_quad_depth(target, nan, 1), cleared);
  EXPECT_EQ(render_quad_depth(target, nan, 1), cleared);  // into the buffer written by hand
}

// A framebuffer of depth alone: no color image, the clear depth, and one error from what would
// read or write its color.
TEST(RenderTexture, DepthOnlyFramebuffersRefuseColor) {
  Framebuffer depth = Framebuffer::depth_only(kWidth, kHeight);
  EXPECT_FALSE(depth.has_color());
  EXPECT_TRUE(depth.rgba8().empty() && depth.rgba32f().empty());
  EXPECT_EQ(depth.depth(), std::vector<float>(kWidth * kHeight, 1.0f));
  EXPECT_TRUE(Framebuffer(4, 4).has_color());
  EXPECT_TRUE(Framebuffer(4, 4, ColorFormat::rgba32f).has_color());
  EXPECT_THROW(depth.pixel(0, 0), Error);
  const std::string png = testing::TempDir() + "/depth_only.png";
  EXPECT_THROW(write_image(depth, png), Error);
  EXPECT_FALSE(std::filesystem::exists(png));  // nothing half-written
  EXPECT_THROW(render_shapes_into(depth), Error);
  EXPECT_THROW(Framebuffer::depth_only(0, 4), Error);
}

// A draw that samples the target it is rendered into, or an environment that is that target:
// one error, and nothing rendered.
TEST(RenderTexture, AFrameCannotSampleItsOwnTarget) {
  RenderTexture target(kWidth, kHeight, {ColorFormat::rgba8_srgb, false, true});
  render_shapes_into(target);
  const std::vector<std::uint8_t> before = target.texture()->level(0).rgba8;
  const Mesh mesh = screen(1.0f);
  for (int way = 0; way < 3; ++way) {
    Material material;
    Lighting lighting;
    if (way == 0) material.base_color_map.texture = target.texture();
    if (way == 1) material.normal_map.texture = target.depth_texture();
    if (way == 2) lighting.environment.image = target.texture();
    Renderer renderer;
    renderer.begin_frame(test_camera(kWidth, kHeight), lighting);
    renderer.draw(mesh, material, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -3.0f}));
    try {
      renderer.finish(target);
      ADD_FAILURE() << "way " << way << ": no error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("samples the render texture"), std::string::npos)
          << e.what();
    }
    EXPECT_EQ(target.texture()->level(0).rgba8, before) << "way " << way;
    // Into another target the same draws are fine.
    RenderTexture other(kWidth, kHeight);
    EXPECT_NO_THROW(renderer.finish(other)) << "way " << way;
  }
  EXPECT_THROW(RenderTexture(0, 4), Error);
  EXPECT_THROW(RenderTexture(4, Framebuffer::kMaxSize + 1), Error);
}

TEST(RenderTexture, TheSameImageForAnyThreadsAndTiles) {
  RenderTexture reference(kWidth, kHeight, {ColorFormat::rgba8_srgb, true, false});
  RenderSettings one;
  one.threads = 1;
  render_shapes_into(reference, one);
  for (int threads : {2, 3}) {
    for (int tile : {16, 64}) {
      RenderSettings settings;
      settings.threads = threads;
      settings.tile_size = tile;
      RenderTexture target(kWidth, kHeight, {ColorFormat::rgba8_srgb, true, false});
      render_shapes_into(target, settings);
      for (int level = 0; level < reference.texture()->level_count(); ++level) {
        EXPECT_EQ(target.texture()->level(level).rgba8, reference.texture()->level(level).rgba8)
            << threads << " threads, tile " << tile << ", level " << level;
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
