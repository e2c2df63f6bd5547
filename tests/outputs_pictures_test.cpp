// The pictures of docs/outputs.md: the shapes scene at 400x225 and each of its extra outputs
// (ExtraOutputs), turned into colors the way the page says. Each is a golden in docs/outputs/,
// compared as tests/golden's are; after an intended change regenerate them with
// FACET_UPDATE_GOLDENS=1 --gtest_filter='OutputsPictures*' and look at them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "facet/color.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/golden.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 400;
constexpr int kHeight = 225;

const Framebuffer& frame() {
  static const Framebuffer framebuffer = [] {
    Scene scene = make_shapes_scene();
    Camera camera = scene.camera;
    camera.aspect = static_cast<float>(kWidth) / kHeight;
    ExtraOutputs all;
    all.view_depth = all.instance_ids = all.triangle_ids = all.barycentrics = all.albedo = true;
    all.normals = NormalSpace::camera;
    RenderSettings settings;
    settings.clear_color = glm::vec4(srgb_to_linear({0.53f, 0.66f, 0.82f}), 1.0f);
    Renderer renderer(settings);
    Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::none, all);
    renderer.begin_frame(camera, scene.lighting);
    draw_scene(renderer, scene);
    renderer.finish(image);
    return image;
  }();
  return framebuffer;
}

// A color for an id: hues spread by the golden ratio, black for 0 (the background).
glm::vec3 id_color(std::uint32_t id) {
  if (id == 0) return glm::vec3(0.0f);
  const float hue = static_cast<float>(id) * 0.618034f;
  const float h = (hue - static_cast<float>(static_cast<int>(hue))) * 6.0f;
  const auto channel = [h](float offset) {
    float k = h + offset;
    k -= 6.0f * static_cast<float>(static_cast<int>(k / 6.0f));
    return std::clamp(std::abs(k - 3.0f) - 1.0f, 0.0f, 1.0f);
  };
  return {0.25f + 0.7f * channel(0.0f), 0.25f + 0.7f * channel(4.0f), 0.25f + 0.7f * channel(2.0f)};
}

// An 8-bit image whose pixel i shows `shown(i)`, a display value in [0, 1] (not light).
Framebuffer picture(const std::function<glm::vec3(std::size_t)>& shown) {
  Framebuffer image(kWidth, kHeight, ColorFormat::rgba8_srgb, DepthImage::none);
  for (std::size_t i = 0; i < static_cast<std::size_t>(kWidth) * kHeight; ++i) {
    const glm::vec3 v = glm::clamp(shown(i), 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c)
      image.rgba8()[4 * i + c] = static_cast<std::uint8_t>(v[c] * 255.0f + 0.5f);
    image.rgba8()[4 * i + 3] = 255;
  }
  return image;
}

struct Output {
  const char* name;  // docs/outputs/<name>.png
  std::function<Framebuffer()> draw;
};

const Output kOutputs[] = {
    {"color", [] { return frame(); }},
    // Near white, 20 units and beyond black; nothing drawn black.
    {"view_depth",
     [] {
       return picture([](std::size_t i) {
         const float d = frame().view_depth()[i];
         return glm::vec3(d == 0.0f ? 0.0f : std::clamp(1.0f - d / 20.0f, 0.0f, 1.0f));
       });
     }},
    {"normals_camera",
     [] {
       return picture([](std::size_t i) {
         const float* n = &frame().normals()[3 * i];
         return glm::vec3(n[0], n[1], n[2]) * 0.5f + 0.5f;
       });
     }},
    {"instance_ids",
     [] { return picture([](std::size_t i) { return id_color(frame().instance_ids()[i]); }); }},
    {"triangle_ids",
     [] { return picture([](std::size_t i) { return id_color(frame().triangle_ids()[i]); }); }},
    {"barycentrics",
     [] {
       return picture([](std::size_t i) {
         const float* b = &frame().barycentrics()[3 * i];
         return glm::vec3(b[0], b[1], b[2]);
       });
     }},
    {"albedo",
     [] {
       return picture([](std::size_t i) {
         const float* a = &frame().albedo()[4 * i];
         return linear_to_srgb(glm::vec3(a[0], a[1], a[2]));
       });
     }},
};

void PrintTo(const Output& output, std::ostream* os) { *os << output.name; }

class OutputPicture : public ::testing::TestWithParam<Output> {};

TEST_P(OutputPicture, MatchesGolden) {
  const Output& output = GetParam();
  const std::string path = (std::filesystem::path(::testing::TempDir()) /
                            (std::string("outputs_") + output.name + ".png"))
                               .string();
  write_image(output.draw(), path);
  expect_matches_golden_in(FACET_OUTPUTS_PICTURE_DIR, path, output.name);
}

INSTANTIATE_TEST_SUITE_P(OutputsPictures, OutputPicture, ::testing::ValuesIn(kOutputs),
                         [](const ::testing::TestParamInfo<Output>& param_info) {
                           return std::string(param_info.param.name);
                         });

}  // namespace
}  // namespace facet::test
