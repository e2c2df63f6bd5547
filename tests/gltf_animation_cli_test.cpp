// `facet render MODEL --time T --animation N` on a glTF model the test writes: the skinned bar of
// support/gltf_builder.hpp, drawn white (unlit) on black from straight in front, so that where
// the bar is can be read off the image.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_content_inputs.hpp"
#include "support/gltf_builder.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

// The bar stands from (10, 0) to (10, 2) at rest; at t = 1 its top half lies along y = 1 from
// x = 10 to x = 9. The camera looks at (10, 1, 0) from 10 units away with a 40 degree vertical
// field of view: half the image's height is 10 tan 20° = 3.64 units, so in a 320x180 image a
// point (x, y) is at pixel (160 + (x - 10) 160 / 6.47, 90 - (y - 1) 90 / 3.64).
const std::string kView =
    " --size 320x180 --eye 10,1,10 --target 10,1,0 --fov 40 --background 0,0,0";

std::filesystem::path write_bar(const std::filesystem::path& dir) {
  GltfBuilder b;
  add_skinned_bar(b);
  b.json["materials"] = {
      {{"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}, {"doubleSided", true}}};
  b.json["meshes"][0]["primitives"][0]["material"] = 0;
  return b.write_glb(dir / "bar.glb");
}

int red_at(const Rgba8Image& image, int x, int y) {
  return image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
}

// (10, 1.8): on the standing bar only, pixel (160, 70); (9.4, 1): on the bent bar only, pixel
// (145, 90).
void expect_bar(const Rgba8Image& image, bool bent) {
  ASSERT_EQ(image.width, 320);
  EXPECT_EQ(red_at(image, 160, 70) > 128, !bent) << "the bar's standing top";
  EXPECT_EQ(red_at(image, 145, 90) > 128, bent) << "the bar's bent top";
  EXPECT_GT(red_at(image, 160, 110), 128) << "the bar's foot, where it always is";
}

TEST(CliGltfAnimation, TimePosesTheModelAndWithoutItTheModelRests) {
  const auto dir = gltf_test_dir("cli_time");
  const std::string bar = write_bar(dir).string();
  CommandResult rest = run_facet(dir, "render " + bar + kView + " -o rest.png -q");
  ASSERT_EQ(rest.exit_code, 0) << rest.stderr_text;
  expect_bar(read_png((dir / "rest.png").string()), false);
  CommandResult bent = run_facet(dir, "render " + bar + kView + " --time 1 -o bent.png -q");
  ASSERT_EQ(bent.exit_code, 0) << bent.stderr_text;
  expect_bar(read_png((dir / "bent.png").string()), true);
}

TEST(CliGltfAnimation, EachFrameOfASequenceIsPosedAtItsTime) {
  const auto dir = gltf_test_dir("cli_frames");
  const std::string bar = write_bar(dir).string();
  CommandResult run =
      run_facet(dir, "render " + bar + kView + " --frames 0:2 --fps 1 -o f_%d.png -q");
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  expect_bar(read_png((dir / "f_0.png").string()), false);  // t = 0: the animation's first key
  expect_bar(read_png((dir / "f_1.png").string()), true);   // t = 1: bent
}

TEST(CliGltfAnimation, AnAnimationTheFileDoesNotHaveIsOneErrorLine) {
  const auto dir = gltf_test_dir("cli_bad_animation");
  const std::string bar = write_bar(dir).string();
  CommandResult run = run_facet(dir, "render " + bar + " --time 1 --animation 3 -o x.png");
  EXPECT_EQ(run.exit_code, kUsageError);
  EXPECT_EQ(lines_of(run.stderr_text).size(), 1u) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("animation 3 does not exist"), std::string::npos)
      << run.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  CommandResult builtin = run_facet(dir, "render --scene teapot --animation 1 -o y.png");
  EXPECT_EQ(builtin.exit_code, kUsageError);
  EXPECT_NE(builtin.stderr_text.find("--animation"), std::string::npos) << builtin.stderr_text;
}

}  // namespace
}  // namespace facet::test
