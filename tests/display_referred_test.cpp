// Frames whose every color is a display value (the normals, depth and texcoords views, the
// glmark2 scenes' models) keep those values as code / 255 in their tiles and round them at
// resolve (at one sample, the codes themselves, which resolve copies), instead of storing
// decoded linear values that resolve sRGB-encodes back to the same codes
// (pipeline/frame_run.cpp's display_referred_frame).
// The bytes must not change: each frame here is also rendered to a float target, which never
// takes that path and holds a display value as the value itself (the normals view's
// n * 0.5 + 0.5, unrounded) and everything else as linear light; encoded as an 8-bit target
// stores each (display values rounded to their code, light sRGB-encoded), the 8-bit frame must be
// that, byte for byte, and must have taken the path.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/teapot.hpp"
#include "scenes/bench_scenes.hpp"
#include "support/golden.hpp"
#include "support/required_package.hpp"
#include "support/srgb_reference.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 320, kHeight = 180;

// Records one frame into a renderer (begin_frame and draws).
using Record = std::function<void(Renderer&)>;

// Frames whose draws show display values, but for the draws given this instance id, which are lit.
constexpr std::uint32_t kLitInstance = 99;

// The frame rendered to an 8-bit target; `referred` says whether it took the display path.
std::vector<std::uint8_t> render_8bit(const Record& record, const RenderSettings& settings,
                                      bool& referred) {
  Renderer renderer(settings);
  Framebuffer frame(kWidth, kHeight);
  record(renderer);
  renderer.finish(frame);
  referred = renderer.stats().display_referred;
  return frame.rgba8();
}

// The frame rendered to a float target, then encoded as an 8-bit target stores it: drawn pixels
// of display-valued draws as their codes (StoreDisplayCodes' rounding), the background and lit
// draws (kLitInstance) sRGB-encoded as encode_srgb_row promises; alpha rounded.
std::vector<std::uint8_t> render_float_encoded(const Record& record,
                                               const RenderSettings& settings) {
  Renderer renderer(settings);
  ExtraOutputs ids;
  ids.instance_ids = true;
  Framebuffer frame(kWidth, kHeight, ColorFormat::rgba32f, DepthImage::keep, ids);
  record(renderer);
  renderer.finish(frame);
  EXPECT_FALSE(renderer.stats().display_referred);
  std::vector<std::uint8_t> bytes(frame.rgba32f().size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const float v = frame.rgba32f()[i];
    const std::size_t pixel = i / 4;
    const bool display = frame.depth()[pixel] < 1.0f && frame.instance_ids()[pixel] != kLitInstance;
    if (i % 4 == 3 || display) {
      bytes[i] = static_cast<std::uint8_t>((v > 0.0f ? std::min(v, 1.0f) : 0.0f) * 255.0f + 0.5f);
    } else {
      bytes[i] = encode_srgb8(v);
    }
  }
  return bytes;
}

// Compares the two renders of `record`; returns whether the 8-bit one was display-referred.
bool expect_same_bytes(const Record& record, const RenderSettings& settings,
                       const std::string& what) {
  bool referred = false;
  const std::vector<std::uint8_t> fast = render_8bit(record, settings, referred);
  const std::vector<std::uint8_t> reference = render_float_encoded(record, settings);
  EXPECT_EQ(fast.size(), reference.size());
  std::size_t differing = 0, first = 0;
  for (std::size_t i = 0; i < std::min(fast.size(), reference.size()); ++i) {
    if (fast[i] != reference[i] && differing++ == 0) first = i;
  }
  EXPECT_EQ(differing, 0u) << what << ": first at byte " << first << " (pixel " << first / 4
                           << ", channel " << first % 4 << "): " << int{fast[first]} << " vs "
                           << int{reference[first]};
  return referred;
}

// A teapot and a box in a model's shading, in front of a clear color with an odd alpha.
Record debug_view_scene(ShadingModel model, Lighting lighting = {}) {
  return [model, lighting](Renderer& renderer) {
    static const Mesh pot = teapot(6), crate = box({1.0f, 0.6f, 0.8f});
    renderer.begin_frame(Camera::look_at({2.5f, 1.8f, 3.5f}, {0.0f, 0.3f, 0.0f}, {0, 1, 0}, 45.0f,
                                         static_cast<float>(kWidth) / kHeight, 0.1f, 20.0f),
                         lighting);
    Material material;
    material.shading = model;
    renderer.draw(pot, material);
    renderer.draw(crate, material, glm::translate(glm::mat4(1.0f), {-1.2f, 0.0f, -0.5f}));
  };
}

RenderSettings with_clear(glm::vec4 clear) {
  RenderSettings settings;
  settings.clear_color = clear;
  return settings;
}

// At every tile size (the last row of tiles is partial at each, the last column at 128) and at
// one and three threads: one-sample frames keep their tiles as codes (TileContext::codes), which
// every size and thread count must clear, fill and copy out alike.
TEST(DisplayReferred, DebugViewsGiveTheEncodedBytes) {
  for (ShadingModel model : {ShadingModel::normals, ShadingModel::depth, ShadingModel::texcoords}) {
    for (int tile_size : {16, 32, 64, 128}) {
      for (int threads : {1, 3}) {
        const std::string name = std::string(to_string(model)) + ", tiles of " +
                                 std::to_string(tile_size) + ", " + std::to_string(threads) +
                                 " threads";
        RenderSettings settings = with_clear({0.3f, 0.55f, 0.07f, 0.6f});
        settings.tile_size = tile_size;
        settings.threads = threads;
        EXPECT_TRUE(expect_same_bytes(debug_view_scene(model), settings, name))
            << name << " did not take the display-referred path";
      }
    }
  }
}

TEST(DisplayReferred, Glmark2ScenesGiveTheEncodedBytes) {
  FACET_REQUIRE_PACKAGE(std::filesystem::is_directory("/usr/share/glmark2/models"),
                        "/usr/share/glmark2 missing (Debian package glmark2-data)");
  for (const std::string& name : bench::glmark2_scene_names()) {
    const auto scene = bench::make_glmark2_scene(name);
    ASSERT_NE(scene, nullptr) << name;
    const Record record = [&](Renderer& renderer) {
      scene->record(renderer, 0.7, kWidth, kHeight);
    };
    EXPECT_TRUE(expect_same_bytes(record, with_clear(scene->clear_color()), name))
        << name << " did not take the display-referred path";
  }
}

// Multisampled display-referred frames round each sample's value to its code, and the resolve
// averages the codes, as a multisampled 8-bit target does (glmark2's on llvmpipe); rounding the
// samples' average value instead (the one-sample frames' way, StoreDisplay) changes edge pixels
// by a code. Byte for byte against a golden made with the codes averaged.
TEST(DisplayReferred, MultisampledFramesAverageTheSamplesCodes) {
  RenderSettings settings = with_clear({0.3f, 0.55f, 0.07f, 0.6f});
  settings.msaa = 4;
  Renderer renderer(settings);
  Framebuffer frame(kWidth, kHeight);
  debug_view_scene(ShadingModel::normals)(renderer);
  renderer.finish(frame);
  ASSERT_TRUE(renderer.stats().display_referred);
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "display_referred_msaa4.png").string();
  write_image(frame, path);
  expect_matches_golden(path, "display_referred_msaa4", Tolerance{0, 0.0});
}

// What needs linear colors keeps them: a lit draw among display ones, fog, exposure. (Fog mixes
// light into the display values, which a float target keeps unmixed: no float reference.)
TEST(DisplayReferred, FramesThatNeedLinearColorsKeepThem) {
  const Record mixed = [](Renderer& renderer) {
    debug_view_scene(ShadingModel::normals)(renderer);
    static const Mesh ball = uv_sphere(0.4f);
    Material lit;
    lit.shading = ShadingModel::lambert;
    renderer.set_instance_id(kLitInstance);
    renderer.draw(ball, lit, glm::translate(glm::mat4(1.0f), {1.0f, 0.2f, 0.8f}));
  };
  EXPECT_FALSE(expect_same_bytes(mixed, with_clear({0.2f, 0.2f, 0.2f, 1.0f}), "mixed"));

  Lighting fogged;
  fogged.fog.mode = FogMode::linear;
  fogged.fog.start = 2.0f, fogged.fog.end = 8.0f;
  bool referred = true;
  render_8bit(debug_view_scene(ShadingModel::normals, fogged), with_clear({0.2f, 0.2f, 0.2f, 1.0f}),
              referred);
  EXPECT_FALSE(referred);

  RenderSettings brighter = with_clear({0.2f, 0.2f, 0.2f, 1.0f});
  brighter.exposure = 0.5f;
  referred = true;
  render_8bit(debug_view_scene(ShadingModel::normals), brighter, referred);
  EXPECT_FALSE(referred);
}

// The automatic tile size (RenderSettings::kAutoTileSize): 128 pixels where the tiles hold
// codes (one sample, display values alone), 64 wherever they hold floats, and what was asked
// for when a size is given. Lines, which geometry counts only after the size is chosen, are
// foreseen from their meshes. The image is the same as with 64-pixel tiles.
TEST(DisplayReferred, AutomaticTilesAre128PixelsWhereTheyHoldCodes) {
  const auto tile_size = [](const Record& record, RenderSettings settings,
                            ColorFormat format = ColorFormat::rgba8_srgb) {
    Renderer renderer(settings);
    Framebuffer frame(kWidth, kHeight, format);
    record(renderer);
    renderer.finish(frame);
    return renderer.stats().tile_size;
  };
  const RenderSettings automatic = with_clear({0.2f, 0.2f, 0.2f, 1.0f});
  const Record normals = debug_view_scene(ShadingModel::normals);
  EXPECT_EQ(tile_size(normals, automatic), 128);

  RenderSettings multisampled = automatic;
  multisampled.msaa = 4;
  EXPECT_EQ(tile_size(normals, multisampled), 64);
  EXPECT_EQ(tile_size(normals, automatic, ColorFormat::rgba32f), 64);
  RenderSettings given = automatic;
  given.tile_size = 32;
  EXPECT_EQ(tile_size(normals, given), 32);

  const Record with_lines = [&](Renderer& renderer) {
    normals(renderer);
    static const Mesh line = [] {
      Mesh mesh;
      mesh.topology = Topology::lines;
      mesh.positions = {{-1.0f, 0.0f, 0.0f}, {1.0f, 0.5f, 0.0f}};
      return mesh;
    }();
    Material material;
    material.shading = ShadingModel::normals;
    renderer.draw(line, material);
  };
  EXPECT_EQ(tile_size(with_lines, automatic), 64);
  Lighting fogged;
  fogged.fog.mode = FogMode::linear;
  EXPECT_EQ(tile_size(debug_view_scene(ShadingModel::normals, fogged), automatic), 64);
  const Record lit = [](Renderer& renderer) {
    static const Mesh ball = uv_sphere(0.4f);
    renderer.begin_frame(Camera::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, 1.0f, 0.1f, 10.0f),
                         {});
    renderer.draw(ball, Material{});
  };
  EXPECT_EQ(tile_size(lit, automatic), 64);

  bool referred = false;
  RenderSettings sixty_four = automatic;
  sixty_four.tile_size = 64;
  EXPECT_EQ(render_8bit(normals, automatic, referred), render_8bit(normals, sixty_four, referred));
}

// A float target holds the normals view's values themselves: a face turned to the camera (normal
// +Z) is (0.5, 0.5, 1) exactly, not the sRGB decode of the 8-bit code 128 (0.2158), and the 8-bit
// target holds that value's code.
TEST(DisplayReferred, FloatTargetsHoldTheNormalsViewsValues) {
  for (ColorFormat format : {ColorFormat::rgba32f, ColorFormat::rgba8_srgb}) {
    Renderer renderer;
    Framebuffer frame(32, 32, format);
    renderer.begin_frame(Camera::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45.0f, 1.0f, 0.1f, 10.0f),
                         {});
    Material material;
    material.shading = ShadingModel::normals;
    static const Mesh crate = box({1.0f, 1.0f, 1.0f});
    renderer.draw(crate, material);
    renderer.finish(frame);
    const std::size_t centre = (16 * 32 + 16) * 4;
    if (format == ColorFormat::rgba32f) {
      EXPECT_EQ(frame.rgba32f()[centre + 0], 0.5f);
      EXPECT_EQ(frame.rgba32f()[centre + 1], 0.5f);
      EXPECT_EQ(frame.rgba32f()[centre + 2], 1.0f);
    } else {
      EXPECT_EQ(int{frame.rgba8()[centre + 0]}, 128);
      EXPECT_EQ(int{frame.rgba8()[centre + 1]}, 128);
      EXPECT_EQ(int{frame.rgba8()[centre + 2]}, 255);
    }
  }
}

}  // namespace
}  // namespace facet::test
