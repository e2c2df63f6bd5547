// `facet render` with bad models and bad values, through the real binary: exit code 2, one
// "facet: error:" line that says what and where, and nothing written (an existing output file
// survives).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include "support/cli_content_inputs.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

struct BadCase {
  const char* name;
  const char* args;      // after `facet render`, before -o out.png; $IN/ is the inputs directory
  const char* mentions;  // the error line must contain this
};

// The inputs are written when a test runs, not when the cases are listed, so paths to them are
// spelled $IN/ here.
const BadCase kBadCases[] = {
    {"missing_model", "$IN/no_such_model.obj", "no_such_model.obj"},
    {"directory_as_model", "$IN/a_directory.obj", "a_directory.obj"},
    {"noise_obj", "$IN/noise.obj", "noise.obj"},
    {"noise_glb", "$IN/noise.glb", "noise.glb"},
    {"empty_glb", "$IN/empty.glb", "empty.glb"},
    {"d_index_out_of_range", "$IN/index_out_of_range.d", "index_out_of_range.d:5:"},
    {"model_and_scene", "$IN/ball.d --scene teapot", "--scene"},
    {"light_unknown_kind", "$IN/ball.d --light bogus,1,2", "--light"},
    {"light_dir_two_numbers", "$IN/ball.d --light dir,1,2", "--light"},
    {"light_point_words", "$IN/ball.d --light point,a,b,c", "--light"},
    {"light_trailing_comma", "$IN/ball.d --light dir,1,2,3,", "--light"},
    {"light_second_bad", "$IN/ball.d --light dir,0,-1,0 --light dir,1,2", "--light"},
    {"light_zero_direction", "$IN/ball.d --light dir,0,0,0", "--light"},
    {"light_spot_zero_direction", "$IN/ball.d --light spot,0,3,0,0,0,0", "--light"},
    {"light_negative_intensity", "$IN/ball.d --light point,0,3,3,1,1,1,-5", "--light"},
    {"light_negative_color", "$IN/ball.d --light dir,0,-1,0,-1,0,0", "--light"},
    {"light_spot_cones_reversed", "$IN/ball.d --light spot,0,3,0,0,-1,0,40,20", "--light"},
    {"light_spot_cone_too_wide", "$IN/ball.d --light spot,0,3,0,0,-1,0,20,120", "--light"},
    {"fog_no_kind", "$IN/ball.d --fog fog", "--fog"},
    {"fog_linear_one_number", "$IN/ball.d --fog linear,5", "--fog"},
    {"fog_linear_reversed", "$IN/ball.d --fog linear,10,5", "--fog"},
    {"fog_exp_negative", "$IN/ball.d --fog exp,-1", "--fog"},
    {"fog_exp_two_numbers", "$IN/ball.d --fog exp,1,2", "--fog"},
    {"fog_color_out_of_range", "$IN/ball.d --fog linear --fog-color 2,0,0", "--fog-color"},
    {"fog_color_without_fog", "$IN/ball.d --fog-color 2,0,0", "--fog-color"},
    {"env_missing_image", "$IN/ball.d --env missing.png", "missing.png"},
    {"env_unreadable_image", "$IN/ball.d --env $IN/not_an_image.png", "not_an_image.png"},
    {"env_projection_unknown", "$IN/ball.d --env sky --env-projection cube", "--env-projection"},
    {"env_projection_without_env", "$IN/ball.d --env-projection cube", "--env-projection"},
    {"texture_missing", "$IN/ball.d --texture missing.png", "missing.png"},
    {"texture_unreadable", "$IN/ball.d --texture $IN/not_an_image.png", "not_an_image.png"},
    {"projection_unknown", "$IN/ball.d --texture $IN/texture.png --projection weird",
     "--projection"},
    {"reflectivity_above_1", "$IN/ball.d --reflectivity 2", "--reflectivity"},
    {"reflectivity_negative", "$IN/ball.d --reflectivity -0.5", "--reflectivity"},
    {"exposure_100", "$IN/ball.d --exposure 100", "--exposure"},
    {"camera_in_a_file_without_cameras", "$IN/ball.d --camera 0", "--camera"},
    // Camera numbers that overflow a float or leave nothing for the depth buffer to draw: named
    // by flag (before: 0 pixels shaded with exit 0, "near plane must be positive, got inf", and
    // "up is parallel to the view direction").
    {"near_far_ratio_beyond_depth", "$IN/ball.d --near 1e-30 --far 1e30",
     "--near 1e-30 and --far 1e+30"},
    {"near_alone_beyond_depth", "$IN/ball.d --near 1e-9", "--near 1e-09 and the far plane"},
    {"eye_too_far", "$IN/ball.d --eye 1e38,0,0", "--eye: 1e38,0,0 is"},
    {"target_too_far", "$IN/ball.d --target 0,0,-1e30", "--target: the eye and the target"},
    // assimp's OpenGEX parser prints a line of its own to std::cerr before it fails.
    {"assimp_prints_its_own_line", "/usr/share/assimp/models/OpenGEX/empty_camera.ogex",
     "empty_camera.ogex"},
};

std::string with_inputs(std::string args) {
  for (std::size_t at; (at = args.find("$IN/")) != std::string::npos;)
    args.replace(at, 4, cli_inputs().string() + "/");
  return args;
}

void PrintTo(const BadCase& c, std::ostream* os) { *os << "facet render " << c.args; }

// Exit code 2, nothing on stdout, stderr is `warnings` warning lines then one error line.
void expect_one_error(const CommandResult& r, const std::string& mentions, std::size_t warnings) {
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_EQ(r.stdout_text, "");
  std::vector<std::string> lines = lines_of(r.stderr_text);
  ASSERT_EQ(lines.size(), warnings + 1) << r.stderr_text;
  EXPECT_EQ(r.stderr_text.back(), '\n');
  for (std::size_t i = 0; i < warnings; ++i)
    EXPECT_EQ(lines[i].rfind("facet: warning:", 0), 0u) << lines[i];
  EXPECT_EQ(lines.back().rfind("facet: error: ", 0), 0u) << lines.back();
  EXPECT_NE(lines.back().find(mentions), std::string::npos)
      << "'" << lines.back() << "' does not mention " << mentions;
}

class CliContentBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(CliContentBadInput, ExitsWithOneErrorLineAndWritesNothing) {
  const BadCase& c = GetParam();
  fs::path dir = fresh_test_dir("facet_cli_content_", std::string("bad_") + c.name);
  CommandResult r = run_facet(dir, "render " + with_inputs(c.args) + " -o out.png" + kCliSize);
  expect_one_error(r, c.mentions, 0);
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{}) << "files left behind";
}

INSTANTIATE_TEST_SUITE_P(CliContent, CliContentBadInput, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

TEST(CliContentErrors, DPolygonOutOfRangeNamesFileAndLine) {
  fs::path dir = fresh_test_dir("facet_cli_content_", "d_line");
  std::string model = input("index_out_of_range.d");
  CommandResult r = run_facet(dir, "render " + model + " -o out.png" + kCliSize);
  EXPECT_EQ(r.stderr_text,
            "facet: error: " + model + ":5: polygon index 7 is out of range (1..3)\n");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{});
}

TEST(CliContentErrors, FileCameraOutOfRange) {
  REQUIRE_INSTALLED(kCamerasGltf);
  for (const char* n : {"2", "5", "-1"}) {
    SCOPED_TRACE(std::string("--camera ") + n);
    fs::path dir = fresh_test_dir("facet_cli_content_", std::string("camera_bad_") + n);
    CommandResult r =
        run_facet(dir, "render " + kCamerasGltf + " --camera " + n + " -o out.png" + kCliSize);
    // The file has two cameras, 0 and 1 (perspective and orthographic).
    expect_one_error(r, "--camera", 0);
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{});
  }
}

TEST(CliContentErrors, FailedRenderKeepsAnExistingFile) {
  fs::path dir = fresh_test_dir("facet_cli_content_", "keep");
  const std::string contents = "an earlier image that must survive";
  std::ofstream(dir / "keep.png", std::ios::binary) << contents;
  // Failures while importing, while applying the flags, and while loading a texture.
  for (std::string args : {input("noise.obj"), input("ball.d") + " --fog linear,10,5",
                           input("ball.d") + " --texture missing.png"}) {
    CommandResult r = run_facet(dir, "render " + args + " -o keep.png" + kCliSize);
    EXPECT_EQ(r.exit_code, kUsageError) << args;
    std::ifstream in(dir / "keep.png", std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), contents) << args;
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"keep.png"}) << args;
  }
}

}  // namespace
}  // namespace facet::test
