// Golden images: `facet render --scene shapes` at 640x360 for every shading model, compared with
// tests/golden/shapes_<model>.png. Set FACET_UPDATE_GOLDENS=1 to overwrite the goldens with the
// current renders instead (do it on purpose, then look at every image before committing).
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

// A channel may differ from the golden by at most 2 levels (of 255), and at most 0.1% of pixels
// (230 of 640x360) may differ by more. That absorbs a reordered float operation or a different
// rounding in a later optimisation (which moves a shade by one level, or an edge pixel or two),
// while any visible change - a moved edge, a changed light, a missing object - fails.
struct Tolerance {
  int max_channel_delta;
  double max_outlier_fraction;
};
constexpr Tolerance kGoldenTolerance{2, 0.001};

constexpr int kWidth = 640;
constexpr int kHeight = 360;

struct GoldenCase {
  const char* model;
  const char* extra_args;
};

// `depth` maps near..far to white..black; with the default far of 100 the whole scene (3 to 30
// units away) is in the lightest quarter of that range, so the golden uses --far 20 for contrast.
const GoldenCase kCases[] = {
    {"unlit", ""},          {"vertex_color", ""}, {"flat", ""},      {"lambert", ""},
    {"depth", " --far 20"}, {"normals", ""},      {"wireframe", ""}, {"wire_overlay", ""},
};

void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.model << c.extra_args; }

struct Comparison {
  long outliers = 0;  // pixels with a channel beyond the tolerance
  int max_delta = 0;  // largest channel difference anywhere
  Rgba8Image diff;    // outliers red, small differences yellow, the rest the golden dimmed
};

Comparison compare(const Rgba8Image& actual, const Rgba8Image& golden) {
  Comparison c;
  c.diff = golden;
  for (std::size_t i = 0; i < golden.pixels.size(); i += 4) {
    int delta = 0;
    for (int ch = 0; ch < 4; ++ch) {
      delta = std::max(delta, std::abs(int(actual.pixels[i + ch]) - int(golden.pixels[i + ch])));
    }
    c.max_delta = std::max(c.max_delta, delta);
    std::uint8_t* d = &c.diff.pixels[i];
    if (delta > kGoldenTolerance.max_channel_delta) {
      ++c.outliers;
      d[0] = 255, d[1] = 0, d[2] = 0;
    } else if (delta > 0) {
      d[0] = 255, d[1] = 255, d[2] = 0;
    } else {
      int grey = (d[0] + d[1] + d[2]) / 12;
      d[0] = d[1] = d[2] = static_cast<std::uint8_t>(grey);
    }
    d[3] = 255;
  }
  return c;
}

bool write_png(const Rgba8Image& image, const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGBA;
  return png_image_write_to_file(&png, path.c_str(), 0, image.pixels.data(), 0, nullptr) != 0;
}

bool updating_goldens() {
  const char* value = std::getenv("FACET_UPDATE_GOLDENS");
  return value && std::string(value) == "1";
}

class ShapesScene : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(ShapesScene, MatchesGolden) {
  const GoldenCase& golden_case = GetParam();
  const std::string model = golden_case.model;
  const fs::path output = fs::path(::testing::TempDir()) / (model + ".png");
  const fs::path golden_path = fs::path(FACET_GOLDEN_DIR) / ("shapes_" + model + ".png");
  fs::remove(output);

  const std::string command = std::string(FACET_CLI) + " render --scene shapes --size " +
                              std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                              " --shading " + model + golden_case.extra_args + " -o '" +
                              output.string() + "'";
  CommandResult result = run_command(command);
  ASSERT_EQ(result.exit_code, 0) << command << "\n" << result.stderr_text;

  if (updating_goldens()) {
    fs::copy_file(output, golden_path, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "FACET_UPDATE_GOLDENS=1: wrote " << golden_path.string()
                 << " (look at it before committing)";
  }

  ASSERT_TRUE(fs::exists(golden_path))
      << golden_path.string() << " is missing; create it with FACET_UPDATE_GOLDENS=1";
  Rgba8Image actual = read_png(output.string());
  Rgba8Image golden = read_png(golden_path.string());
  ASSERT_EQ(actual.width, golden.width) << output.string();
  ASSERT_EQ(actual.height, golden.height) << output.string();

  Comparison c = compare(actual, golden);
  const long allowed =
      static_cast<long>(kGoldenTolerance.max_outlier_fraction * golden.width * golden.height);
  if (c.outliers > allowed) {
    const fs::path diff_path = fs::path(::testing::TempDir()) / (model + ".diff.png");
    bool wrote = write_png(c.diff, diff_path.string());
    ADD_FAILURE() << model << ": " << c.outliers << " pixels differ by more than "
                  << kGoldenTolerance.max_channel_delta << " levels (allowed " << allowed
                  << "), max difference " << c.max_delta << "\n  render: " << output.string()
                  << "\n  golden: " << golden_path.string()
                  << "\n  diff:   " << (wrote ? diff_path.string() : "(could not write diff image)")
                  << "\n  (red: beyond tolerance, yellow: within it)";
  }
}

INSTANTIATE_TEST_SUITE_P(Golden, ShapesScene, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<GoldenCase>& param_info) {
                           return std::string(param_info.param.model);
                         });

}  // namespace
}  // namespace facet::test
