// The `facet` command line: help text, the success summary, PNG and PPM output, and the error
// contract for bad values (exit code 2, one "facet: error:" line, no file left behind).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kUsageError = 2;

std::vector<std::string> list_dir(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Runs `facet <args>` with dir as the working directory, so relative outputs land there.
CommandResult run_facet(const fs::path& dir, const std::string& args) {
  return run_command("cd '" + dir.string() + "' && " + FACET_CLI + " " + args);
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

long count_lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// --- help ---------------------------------------------------------------------------------

const char* const kRenderFlags[] = {
    "--scene",       "--output",    "--size",         "--eye",       "--target", "--up",
    "--fov",         "--near",      "--far",          "--shading",   "--cull",   "--background",
    "--threads",     "--tile-size", "--time",         "--frames",    "--fps",    "--shard",
    "--camera-path", "--outputs",   "--normal-space", "--overwrite", "--quiet",  "--orthographic"};

void expect_documents_every_flag(const std::string& args) {
  CommandResult r = run_facet(::testing::TempDir(), args);
  EXPECT_EQ(r.exit_code, 0) << "facet " << args << "\n" << r.stderr_text;
  for (const char* flag : kRenderFlags) {
    EXPECT_NE(r.stdout_text.find(flag), std::string::npos)
        << "facet " << args << " does not mention " << flag << ":\n"
        << r.stdout_text;
  }
}

TEST(CliHelp, RenderHelpDocumentsEveryFlag) { expect_documents_every_flag("render --help"); }

// --- successful renders -------------------------------------------------------------------

TEST(CliRender, PngSuccessPrintsOneSummaryLineAndWritesTheImage) {
  fs::path dir = fresh_test_dir("facet_cli_", "png");
  CommandResult r = run_facet(dir, "render --scene shapes --size 160x90 -o out.png");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stderr_text, "");
  EXPECT_EQ(count_lines(r.stdout_text), 1) << r.stdout_text;
  EXPECT_EQ(r.stdout_text.back(), '\n');
  for (const char* word : {"160x90", "triangles", "ms"}) {
    EXPECT_NE(r.stdout_text.find(word), std::string::npos) << word << " in: " << r.stdout_text;
  }
  Rgba8Image image = read_png((dir / "out.png").string());
  EXPECT_EQ(image.width, 160);
  EXPECT_EQ(image.height, 90);
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliRender, PpmOutputIsBinaryP6OfTheRightSize) {
  fs::path dir = fresh_test_dir("facet_cli_", "ppm");
  CommandResult r = run_facet(dir, "render --size 33x17 -o out.ppm");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(count_lines(r.stdout_text), 1) << r.stdout_text;

  // Netpbm P6: "P6", width, height, maxval separated by whitespace, then exactly one whitespace
  // byte, then width*height RGB triples.
  std::string data = read_file(dir / "out.ppm");
  std::istringstream header(data);
  std::string magic;
  int width = 0, height = 0, maxval = 0;
  header >> magic >> width >> height >> maxval;
  ASSERT_TRUE(header) << "unreadable PPM header";
  EXPECT_EQ(magic, "P6");
  EXPECT_EQ(width, 33);
  EXPECT_EQ(height, 17);
  EXPECT_EQ(maxval, 255);
  auto header_end = static_cast<std::size_t>(header.tellg());
  ASSERT_LT(header_end, data.size());
  EXPECT_TRUE(std::isspace(static_cast<unsigned char>(data[header_end])));
  EXPECT_EQ(data.size() - header_end - 1, std::size_t{33 * 17 * 3});
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"out.ppm"});
}

// --- bad values ---------------------------------------------------------------------------

struct BadCase {
  const char* name;
  const char* args;  // after `facet render`; outputs are relative to a fresh directory
};

const BadCase kBadCases[] = {
    {"size_zero_width", "--size 0x5 -o out.png"},
    {"size_one_number", "--size 100 -o out.png"},
    {"size_too_wide", "--size 9000x10 -o out.png"},
    {"fov_too_wide", "--fov 200 -o out.png"},
    {"fov_zero", "--fov 0 -o out.png"},
    {"unknown_scene", "--scene nosuch -o out.png"},
    {"output_dir_missing", "-o /nonexistent-dir/x.png"},
    {"output_unknown_type", "-o out.bmp"},
    {"output_is_directory", "-o /tmp"},
    {"model_is_a_device", "/dev/null -o out.png"},
    {"threads_negative", "--threads -1 -o out.png"},
    {"threads_huge", "--threads 100000 -o out.png"},
    {"tile_size_48", "--tile-size 48 -o out.png"},
    {"msaa_3", "--msaa 3 -o out.png"},
    {"msaa_32", "--msaa 32 -o out.png"},
    {"msaa_zero", "--msaa 0 -o out.png"},
    {"shadows_maybe", "--shadows maybe -o out.png"},
    {"reflections_maybe", "--reflections maybe -o out.png"},
    {"shadow_map_zero", "--shadow-map-size 0 -o out.png"},
    {"shadow_map_huge", "--shadow-map-size 100000 -o out.png"},
    {"shadow_map_word", "--shadow-map-size big -o out.png"},
    {"shadow_cascades_5", "--shadow-cascades 5 -o out.png"},
    {"shadow_cascades_zero", "--shadow-cascades 0 -o out.png"},
    {"shadow_cascades_word", "--shadow-cascades many -o out.png"},
    {"near_zero", "--near 0 -o out.png"},
    {"far_behind_near", "--far 0.05 -o out.png"},
    {"orthographic_fov", "--orthographic --fov 30 -o out.png"},
    {"orthographic_near", "--orthographic --near 1 -o out.png"},
    {"eye_two_numbers", "--eye 1,2 -o out.png"},
    {"eye_nan", "--eye nan,0,0 -o out.png"},
    {"background_out_of_range", "--background 2,0,0 -o out.png"},
    {"shading_unknown", "--shading bogus -o out.png"},
    {"cull_unknown", "--cull sideways -o out.png"},
    {"unknown_flag", "--no-such-flag -o out.png"},
    {"missing_output", "--size 64x36"},
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << "facet render " << c.args; }

class BadValue : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadValue, ExitsWithOneErrorLineAndNoFile) {
  const BadCase& c = GetParam();
  fs::path dir = fresh_test_dir("facet_cli_", c.name);
  CommandResult r = run_facet(dir, std::string("render ") + c.args);
  EXPECT_EQ(r.exit_code, kUsageError) << "facet render " << c.args;
  EXPECT_EQ(count_lines(r.stderr_text), 1) << r.stderr_text;
  EXPECT_EQ(r.stderr_text.rfind("facet: error:", 0), 0u) << r.stderr_text;
  EXPECT_EQ(r.stdout_text, "");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{}) << "files left behind";
  EXPECT_FALSE(fs::exists("/nonexistent-dir"));
}

INSTANTIATE_TEST_SUITE_P(Cli, BadValue, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

// Each --light takes its own value only: a model path after it is the model, and the order of
// options does not matter.
TEST(CliRender, LightOptionsLeaveTheModelPathToTheModel) {
  fs::path dir = fresh_test_dir("facet_cli_", "light_order");
  {
    std::ofstream obj(dir / "tri.obj");
    obj << "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\n";
  }
  const std::string size = " --size 32x24";
  CommandResult before =
      run_facet(dir, "render --light dir,0,0,-1 --light point,0,2,3,1,0,0 tri.obj -o a.png" + size);
  ASSERT_EQ(before.exit_code, 0) << before.stderr_text;
  CommandResult after =
      run_facet(dir, "render tri.obj --light dir,0,0,-1 -o b.png --light point,0,2,3,1,0,0" + size);
  ASSERT_EQ(after.exit_code, 0) << after.stderr_text;
  CommandResult one = run_facet(dir, "render --light dir,0,0,-1 tri.obj -o c.png" + size);
  ASSERT_EQ(one.exit_code, 0) << one.stderr_text;
  EXPECT_EQ(read_file(dir / "a.png"), read_file(dir / "b.png"));
  EXPECT_NE(read_file(dir / "a.png"), read_file(dir / "c.png")) << "the second light is lost";
}

// The default shadow map size, auto, is the power of two at least the image's longer edge,
// 256 .. 2048: the same image as that size asked for, and not the same as half of it.
TEST(CliRender, AutoShadowMapSizeFollowsTheImage) {
  fs::path dir = fresh_test_dir("facet_cli_", "shadow_map_auto");
  const struct {
    const char* size;
    int map;
  } cases[] = {{"64x48", 256}, {"600x300", 1024}, {"90x2100", 2048}};
  for (const auto& c : cases) {
    auto render = [&](const std::string& map_flag, const char* output) {
      const CommandResult r = run_facet(dir, std::string("render --scene shapes -q --size ") +
                                                 c.size + map_flag + " -o " + output);
      ASSERT_EQ(r.exit_code, 0) << c.size << map_flag << ": " << r.stderr_text;
    };
    render("", "auto.png");
    render(" --shadow-map-size " + std::to_string(c.map), "same.png");
    render(" --shadow-map-size " + std::to_string(c.map / 2), "half.png");
    EXPECT_EQ(read_file(dir / "auto.png"), read_file(dir / "same.png")) << c.size;
    EXPECT_NE(read_file(dir / "auto.png"), read_file(dir / "half.png")) << c.size;
  }
}

// The default shadow cascades, auto, are chosen from the view: one map for the shapes (the same
// image as --shadow-cascades 1), three for the islands seen from the ground (as 3, not as 1).
TEST(CliRender, AutoShadowCascadesFollowTheView) {
  fs::path dir = fresh_test_dir("facet_cli_", "shadow_cascades_auto");
  auto render = [&](const char* scene, const std::string& cascades, const char* output) {
    const CommandResult r = run_facet(dir, std::string("render --scene ") + scene +
                                               " -q --size 320x180" + cascades + " -o " + output);
    ASSERT_EQ(r.exit_code, 0) << scene << cascades << ": " << r.stderr_text;
  };
  auto same = [&](const char* a, const char* b) {
    return read_file(dir / a) == read_file(dir / b);
  };
  render("shapes", "", "shapes_default.png");
  render("shapes", " --shadow-cascades auto", "shapes_auto.png");
  render("shapes", " --shadow-cascades 1", "shapes_1.png");
  EXPECT_TRUE(same("shapes_default.png", "shapes_auto.png"));
  EXPECT_TRUE(same("shapes_auto.png", "shapes_1.png"));
  render("islands", "", "islands_auto.png");
  render("islands", " --shadow-cascades 3", "islands_3.png");
  render("islands", " --shadow-cascades 1", "islands_1.png");
  EXPECT_TRUE(same("islands_auto.png", "islands_3.png"));
  EXPECT_FALSE(same("islands_auto.png", "islands_1.png"));
}

// Reflections are on by default in render: the islands' sea mirrors them (--reflections on
// draws the same), and --reflections off leaves it showing its water alone.
TEST(CliRender, ReflectionsAreOnByDefault) {
  fs::path dir = fresh_test_dir("facet_cli_", "reflections");
  auto render = [&](const std::string& flag, const char* output) {
    const CommandResult r =
        run_facet(dir, "render --scene islands -q --size 160x90 --msaa 1" + flag + " -o " + output);
    ASSERT_EQ(r.exit_code, 0) << flag << ": " << r.stderr_text;
  };
  render("", "default.png");
  render(" --reflections on", "on.png");
  render(" --reflections off", "off.png");
  EXPECT_EQ(read_file(dir / "default.png"), read_file(dir / "on.png"));
  EXPECT_NE(read_file(dir / "default.png"), read_file(dir / "off.png"));
}

// The error says what is wrong with the path: an output that is a directory, a model that is a
// device.
TEST(CliRender, PathErrorsSayWhatThePathIs) {
  fs::path dir = fresh_test_dir("facet_cli_", "path_errors");
  CommandResult out_dir = run_facet(dir, "render -o /tmp --size 8x8");
  EXPECT_EQ(out_dir.stderr_text, "facet: error: /tmp: is a directory\n");
  CommandResult device = run_facet(dir, "render /dev/null -o out.png --size 8x8");
  EXPECT_EQ(device.stderr_text,
            "facet: error: /dev/null: is a character device, not a model file\n");
}

// --orthographic: two equal squares, one 3 units behind the other, come out the same size (in
// perspective the far one is smaller), and the view is fitted to them.
TEST(CliRender, OrthographicDrawsEqualThingsEquallyLarge) {
  fs::path dir = fresh_test_dir("facet_cli_", "orthographic");
  {
    std::ofstream obj(dir / "squares.obj");
    obj << "v -2 -0.5 0\nv -1 -0.5 0\nv -1 0.5 0\nv -2 0.5 0\n"
           "v 1 -0.5 -3\nv 2 -0.5 -3\nv 2 0.5 -3\nv 1 0.5 -3\n"
           "f 1 2 3 4\nf 5 6 7 8\n";
  }
  const std::string view =
      " --eye 0,0,6 --target 0,0,-1.5 --size 120x60 --shading unlit --background 0,0,0";
  // Pixels drawn (not background) in the left and right halves.
  auto halves = [&](const std::string& name) {
    Rgba8Image image = read_png((dir / name).string());
    int left = 0, right = 0, top = image.height, bottom = -1;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        if (image.pixels[4 * (y * image.width + x)] == 0) continue;
        (x < image.width / 2 ? left : right) += 1;
        top = std::min(top, y), bottom = std::max(bottom, y);
      }
    }
    return std::vector<int>{left, right, top, bottom};
  };
  CommandResult ortho = run_facet(dir, "render squares.obj --orthographic -o o.png" + view);
  ASSERT_EQ(ortho.exit_code, 0) << ortho.stderr_text;
  const std::vector<int> o = halves("o.png");
  // 2 units a side in a view 1.08 x 4 units wide, 120 pixels: 27.8 x 27.8 pixels each.
  EXPECT_NEAR(o[0], 772, 60);
  EXPECT_NEAR(o[0], o[1], o[0] / 20) << "left " << o[0] << ", right " << o[1];
  // Fitted: the squares reach the sides but for a small margin, which the image's top and
  // bottom (a 4 x 1 row of squares in a 2:1 image) do not.
  EXPECT_GT(o[2], 5);
  EXPECT_LT(o[3], 60 - 5);
  CommandResult perspective = run_facet(dir, "render squares.obj -o p.png" + view);
  ASSERT_EQ(perspective.exit_code, 0) << perspective.stderr_text;
  const std::vector<int> p = halves("p.png");
  EXPECT_LT(p[1], p[0] * 3 / 4) << "left " << p[0] << ", right " << p[1];
}

// A wireframe draws its edges as lines: the summary counts them rather than saying "0 drawn"
// alone.
TEST(CliRender, WireframeSummaryCountsLines) {
  fs::path dir = fresh_test_dir("facet_cli_", "wire_lines");
  CommandResult r =
      run_facet(dir, "render --scene shapes --shading wireframe -o w.png --size 64x36");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find(" lines drawn"), std::string::npos) << r.stdout_text;
  EXPECT_NE(r.stdout_text.find(" primitives in"), std::string::npos) << r.stdout_text;
  CommandResult shaded = run_facet(dir, "render --scene shapes -o s.png --size 64x36");
  ASSERT_EQ(shaded.exit_code, 0) << shaded.stderr_text;
  EXPECT_EQ(shaded.stdout_text.find(" lines drawn"), std::string::npos) << shaded.stdout_text;
  EXPECT_NE(shaded.stdout_text.find(" triangles in"), std::string::npos) << shaded.stdout_text;
}

TEST(CliOutput, FailedRenderKeepsAnExistingFile) {
  fs::path dir = fresh_test_dir("facet_cli_", "keep");
  const std::string contents = "an earlier image that must survive";
  std::ofstream(dir / "keep.png", std::ios::binary) << contents;
  // Failures at different points of the command: material overrides, camera validation, and
  // renderer creation (which comes after the output path has been checked).
  for (const char* args : {"--shading bogus", "--fov 200", "--tile-size 48"}) {
    CommandResult r = run_facet(dir, std::string("render ") + args + " -o keep.png");
    EXPECT_EQ(r.exit_code, kUsageError) << args;
    EXPECT_EQ(read_file(dir / "keep.png"), contents) << args << " clobbered the file";
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{"keep.png"}) << args;
  }
}

}  // namespace
}  // namespace facet::test
