// Golden images: `facet render --scene shapes` at 640x360 for every shading model, compared with
// tests/golden/shapes_<model>.png, and with its default shadows, shapes_shadows.png. Set
// FACET_UPDATE_GOLDENS=1 to overwrite the goldens with the current renders instead (do it on
// purpose, then look at every image before committing).
#include "support/golden.hpp"

#include <gtest/gtest.h>

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

class ShapesScene : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(ShapesScene, MatchesGolden) {
  const GoldenCase& golden_case = GetParam();
  const std::string model = golden_case.model;
  const fs::path output = fs::path(::testing::TempDir()) / (model + ".png");
  fs::remove(output);

  // One sample a pixel, no tone mapping and no shadows: these goldens hold the shading models,
  // not the anti-aliasing (msaa_test.cpp's golden does), the curves (tone_mapping_test.cpp) or
  // the shadows (ShapesSceneShadows's).
  const std::string command = std::string(FACET_CLI) +
                              " render --msaa 1 --tone-mapping none --shadows off --scene shapes "
                              "--size " +
                              std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                              " --shading " + model + golden_case.extra_args + " -o '" +
                              output.string() + "'";
  CommandResult result = run_command(command);
  ASSERT_EQ(result.exit_code, 0) << command << "\n" << result.stderr_text;
  expect_matches_golden(output.string(), "shapes_" + model);
}

INSTANTIATE_TEST_SUITE_P(Golden, ShapesScene, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<GoldenCase>& param_info) {
                           return std::string(param_info.param.model);
                         });

// The shapes scene as `facet render` draws it by default (4x MSAA, shadows from the key light).
TEST(ShapesSceneShadows, MatchesGolden) {
  const fs::path output = fs::path(::testing::TempDir()) / "shadows.png";
  fs::remove(output);
  const std::string command = std::string(FACET_CLI) + " render --scene shapes --size " +
                              std::to_string(kWidth) + "x" + std::to_string(kHeight) + " -o '" +
                              output.string() + "'";
  CommandResult result = run_command(command);
  ASSERT_EQ(result.exit_code, 0) << command << "\n" << result.stderr_text;
  expect_matches_golden(output.string(), "shapes_shadows");
}

}  // namespace
}  // namespace facet::test
