// `facet render --tone-mapping`: its default keeps the highlights of every sample model's default
// image, which clipping loses; its values are checked; --compare draws the curves side by side.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_content_inputs.hpp"
#include "support/text.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

// The share of an image's fully covered pixels with a channel at 255 (clipped), and how many
// such pixels it has.
struct Clipping {
  double share = 0.0;
  int covered = 0;
};
Clipping clipping(const fs::path& png) {
  const Rgba8Image image = read_png(png.string());
  Clipping c;
  int clipped = 0;
  for (std::size_t p = 0; p < image.pixels.size(); p += 4) {
    const std::uint8_t* px = &image.pixels[p];
    if (px[3] != 255) continue;  // the background, or an edge
    ++c.covered;
    if (px[0] == 255 || px[1] == 255 || px[2] == 255) ++clipped;
  }
  c.share = c.covered > 0 ? static_cast<double>(clipped) / c.covered : 0.0;
  return c;
}

// Models whose lights are past what any curve can show: animation_with_skeleton.fbx has a point
// light of intensity 4.5e9 (irradiance in the tens of thousands on the model).
bool blown_out(const std::string& relative) {
  return relative == "FBX/animation_with_skeleton.png";
}

TEST(CliToneMappingSampleModels, TheDefaultKeepsTheHighlightsOfEveryOne) {
  REQUIRE_INSTALLED(kModels);
  const fs::path dir = fresh_test_dir("facet_tone_", "samples");
  // Some sample models fail on purpose (exit code 1): every one that renders is looked at. One
  // sample a pixel and no shadows: the curve is what is tested.
  run_facet(dir, "render " + kModels.string() +
                     " --size 64x64 --msaa 1 --shadows off --background none -q -o all/");
  int looked_at = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir / "all")) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = fs::relative(entry.path(), dir / "all").string();
    const Clipping c = clipping(entry.path());
    if (c.covered < 50 || blown_out(relative)) continue;
    ++looked_at;
    EXPECT_LE(c.share, 0.05) << relative << ": " << c.covered << " covered pixels";
  }
  EXPECT_GT(looked_at, 150);
  // Lit brighter than white: clipped without tone mapping.
  const std::string bright[] = {"Collada/lights.dae", "FBX/global_settings.fbx",
                                "MS3D/twospheres_withmats.ms3d"};
  for (const std::string& model : bright) {
    const CommandResult r =
        run_facet(dir, "render " + (kModels / model).string() +
                           " --size 64x64 --msaa 1 --shadows off --background none "
                           "--tone-mapping none -q -o none.png");
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    EXPECT_GT(clipping(dir / "none.png").share, 0.1) << model;
  }
}

TEST(CliToneMapping, AnUnknownCurveIsOneLineAndExitCodeTwo) {
  const fs::path dir = fresh_test_dir("facet_tone_", "unknown");
  const CommandResult r = run_facet(dir, "render --tone-mapping filmic --size 8x8 -o out.png");
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_EQ(lines_of(r.stderr_text).size(), 1u) << r.stderr_text;
  EXPECT_TRUE(contains(r.stderr_text, "--tone-mapping: expected none, pbr-neutral or aces"))
      << r.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(CliToneMapping, CompareDrawsTheCurvesSideBySide) {
  const fs::path dir = fresh_test_dir("facet_tone_", "compare");
  const CommandResult r =
      run_facet(dir, "render --size 40x30 --exposure 2 --compare none,pbr-neutral,aces -o c.png");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const Rgba8Image image = read_png((dir / "c.png").string());
  ASSERT_EQ(image.width, 120);
  // The panels differ: the shapes' middle row, one panel against the next.
  auto panel_row = [&](int panel) {
    const auto begin = image.pixels.begin() + (15 * 120 + panel * 40) * 4;
    return std::vector<std::uint8_t>(begin, begin + 40 * 4);
  };
  EXPECT_NE(panel_row(0), panel_row(1));
  EXPECT_NE(panel_row(1), panel_row(2));
}

}  // namespace
}  // namespace facet::test
