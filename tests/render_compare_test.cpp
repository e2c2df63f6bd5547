// `facet render --compare`: the variants side by side, each panel the image its variant renders
// alone, labelled; and one error line for lists and options it cannot draw.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 96, kHeight = 54;
// The label's box lies within this corner of each panel.
constexpr int kLabelWidth = 72, kLabelHeight = 28;

std::string render_command(const fs::path& out, const std::string& args,
                           const std::string& size = "96x54") {
  return std::string(FACET_CLI) + " render --scene shapes --size " + size + " --msaa 1 " + args +
         " -o " + out.string();
}

// Pixels of `picture`'s panel `panel` that differ from `alone`, outside the label's corner; and
// those inside it.
struct PanelDifference {
  int outside_label = 0, inside_label = 0;
};
PanelDifference compare_panel(const Rgba8Image& picture, int panel, const Rgba8Image& alone) {
  PanelDifference d;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::uint8_t* a = &picture.pixels[(y * picture.width + panel * kWidth + x) * 4];
      const std::uint8_t* b = &alone.pixels[(y * kWidth + x) * 4];
      if (std::equal(a, a + 4, b)) continue;
      (x < kLabelWidth && y < kLabelHeight ? d.inside_label : d.outside_label) += 1;
    }
  }
  return d;
}

TEST(RenderCompare, PanelsAreTheVariantsRenderedAloneEachLabelled) {
  const fs::path dir = fresh_test_dir("facet_compare_", "models");
  const CommandResult r =
      run_command(render_command(dir / "compare.png", "--compare flat,phong,normals"));
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("3 panels of 96x54 side by side"), std::string::npos)
      << r.stdout_text;
  const Rgba8Image picture = read_png((dir / "compare.png").string());
  ASSERT_EQ(picture.width, 3 * kWidth);
  ASSERT_EQ(picture.height, kHeight);
  const char* models[] = {"flat", "phong", "normals"};
  for (int panel = 0; panel < 3; ++panel) {
    const fs::path alone = dir / (std::string(models[panel]) + ".png");
    ASSERT_EQ(
        run_command(render_command(alone, std::string("--shading ") + models[panel])).exit_code, 0);
    const PanelDifference d = compare_panel(picture, panel, read_png(alone.string()));
    EXPECT_EQ(d.outside_label, 0) << models[panel];
    EXPECT_GT(d.inside_label, 40) << models[panel] << ": no label drawn";
  }
  // The variants differ: the normals view is no Phong-lit image.
  const fs::path phong = dir / "phong.png", normals = dir / "normals.png";
  EXPECT_GT(compare_panel(read_png(phong.string()), 0, read_png(normals.string())).outside_label,
            500);
}

TEST(RenderCompare, BadListsAndOptionsGiveOneErrorLine) {
  const fs::path dir = fresh_test_dir("facet_compare_", "errors");
  const fs::path out = dir / "out.png";
  const struct {
    const char* args;
    const char* message;
  } cases[] = {
      {"--compare flat", "name at least two variants"},
      {"--compare flat,glossy",
       "'glossy' is neither a shading model, a backend nor a tone mapping"},
      {"--compare flat,phong,flat", "flat is named twice"},
      {"--compare flat,phong --background none", "opaque background"},
      {"--compare flat,phong --debug-view overdraw", "not with --debug-view"},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_command(render_command(out, c.args));
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_EQ(r.stderr_text.rfind("facet: error: --compare: ", 0), 0u)
        << c.args << ": " << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(c.message), std::string::npos) << c.args << ": " << r.stderr_text;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  const CommandResult wide = run_command(render_command(out, "--compare flat,phong", "4100x10"));
  EXPECT_NE(wide.stderr_text.find("--compare: 2 panels of 4100 pixels are wider than 8192"),
            std::string::npos)
      << wide.stderr_text;
  const CommandResult frames =
      run_command(render_command(dir / "f_%04d.png", "--compare flat,phong --frames 0:2"));
  EXPECT_NE(frames.stderr_text.find("--compare: makes one picture, not a sequence"),
            std::string::npos)
      << frames.stderr_text;
  const CommandResult exr = run_command(render_command(dir / "out.exr", "--compare flat,phong"));
  EXPECT_NE(exr.stderr_text.find("--compare: writes one color image"), std::string::npos)
      << exr.stderr_text;
}

}  // namespace
}  // namespace facet::test
