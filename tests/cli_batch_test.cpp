// `facet render` on several models or folders (a batch), `facet thumbnail`, and the command
// line's help and parse errors: the program's help fits a screen, and a mistake is one line in
// facet's words that points to the right command's --help.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "support/text.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kUsageError = 2;
constexpr int kSomeFailed = 1;

// A tetrahedron as OBJ and a square pyramid's faces as ASCII STL: tiny, so each draws in
// milliseconds, and written here so the tests need no sample package.
const char* const kObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const char* const kStl =
    "solid pyramid\n"
    "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
    "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\n"
    "facet normal 0 -1 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex .5 .5 "
    "1\nendloop\nendfacet\n"
    "facet normal 1 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex .5 .5 "
    "1\nendloop\nendfacet\n"
    "facet normal 0 1 1\nouter loop\nvertex 1 1 0\nvertex 0 1 0\nvertex .5 .5 "
    "1\nendloop\nendfacet\n"
    "facet normal -1 0 1\nouter loop\nvertex 0 1 0\nvertex 0 0 0\nvertex .5 .5 "
    "1\nendloop\nendfacet\n"
    "endsolid pyramid\n";

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Every file under dir, as paths relative to it, sorted.
std::vector<std::string> files_under(const fs::path& dir) {
  std::vector<std::string> names;
  if (!fs::exists(dir)) return names;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) names.push_back(fs::relative(entry.path(), dir).string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

long count_lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

CommandResult run_facet(const fs::path& dir, const std::string& args) {
  return run_command("cd '" + dir.string() + "' && " + FACET_CLI + " " + args);
}

// in/a.obj, in/sub/a.stl (the same name one folder down), in/broken.obj, in/notes.txt (not a
// model), more/a.obj (the same name in another folder).
fs::path batch_inputs(const std::string& name) {
  fs::path dir = fresh_test_dir("facet_batch_", name);
  write_text(dir / "in/a.obj", kObj);
  write_text(dir / "in/sub/a.stl", kStl);
  write_text(dir / "in/broken.obj", "this is not an OBJ file\n");
  write_text(dir / "in/notes.txt", "not a model\n");
  write_text(dir / "more/a.obj", kObj);
  return dir;
}

// --- batches ------------------------------------------------------------------------------

TEST(CliBatch, FoldersAndFilesGiveOneImageEachAndTheBadFileIsReported) {
  fs::path dir = batch_inputs("mixed");
  CommandResult r = run_facet(dir, "render in more --size 40x30 -o thumbs/");
  EXPECT_EQ(r.exit_code, kSomeFailed) << r.stderr_text;
  // One line naming the bad file, and the others drawn past it.
  EXPECT_EQ(count_lines(r.stderr_text), 1) << r.stderr_text;
  EXPECT_EQ(r.stderr_text.rfind("facet: error: in/broken.obj", 0), 0u) << r.stderr_text;
  EXPECT_TRUE(contains(r.stdout_text, "4 models")) << r.stdout_text;
  EXPECT_TRUE(contains(r.stdout_text, "3 rendered, 1 failed")) << r.stdout_text;
  // The folder's layout is kept; the second a.obj at the top gets -2; no temporary is left.
  EXPECT_EQ(files_under(dir / "thumbs"),
            (std::vector<std::string>{"a-2.png", "a.png", "sub/a.png"}));
  for (const char* name : {"a.png", "a-2.png", "sub/a.png"}) {
    Rgba8Image image = read_png((dir / "thumbs" / name).string());
    EXPECT_EQ(image.width, 40) << name;  // every render option applies to every model
    EXPECT_EQ(image.height, 30) << name;
  }
  // The STL is drawn, not a copy of the OBJ.
  EXPECT_NE(read_file(dir / "thumbs/a.png"), read_file(dir / "thumbs/sub/a.png"));
  EXPECT_EQ(read_file(dir / "thumbs/a.png"), read_file(dir / "thumbs/a-2.png"));
}

TEST(CliBatch, QuietWritesEverythingAndPrintsNothing) {
  fs::path dir = batch_inputs("quiet");
  CommandResult r =
      // A file and a folder whose a.obj would take the same name, however the folder is spelt.
      run_facet(dir, "render in/a.obj ./more/ --size 16x16 --format ppm -q -o ./out");
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stdout_text, "");
  EXPECT_EQ(r.stderr_text, "");
  EXPECT_EQ(files_under(dir / "out"), (std::vector<std::string>{"a-2.ppm", "a.ppm"}));
}

TEST(CliBatch, OneModelIntoAFolderIsABatchOfOne) {
  fs::path dir = batch_inputs("one");
  CommandResult r = run_facet(dir, "render in/sub/a.stl --size 16x16 -o out/");
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(files_under(dir / "out"), std::vector<std::string>{"a.png"});
}

// On a terminal (here a pseudo-terminal from util-linux's `script`) a batch redraws one bar in
// place instead of a summary line per model.
TEST(CliBatch, ProgressBarOnATerminal) {
  FACET_REQUIRE_PACKAGE(run_command("command -v script").exit_code == 0,
                        "script(1) is missing (Debian package bsdutils)");
  fs::path dir = batch_inputs("bar");
  CommandResult r = run_command("cd '" + dir.string() + "' && script -qec \"" + FACET_CLI +
                                " render in/a.obj more --size 16x16 -o out/\" /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.stdout_text << r.stderr_text;
  EXPECT_TRUE(contains(r.stdout_text, "\r[")) << r.stdout_text;
  EXPECT_TRUE(contains(r.stdout_text, "2/2 models")) << r.stdout_text;
  EXPECT_TRUE(contains(r.stdout_text, "2 rendered, 0 failed")) << r.stdout_text;
  EXPECT_FALSE(contains(r.stdout_text, "triangles in")) << r.stdout_text;
  EXPECT_EQ(files_under(dir / "out"), (std::vector<std::string>{"a-2.png", "a.png"}));
}

// A mistake in the options is one usage error before any model is drawn, not one per model,
// and leaves no folder behind.
TEST(CliBatch, UsageErrorsStopTheBatchBeforeItStarts) {
  fs::path dir = batch_inputs("usage");
  const char* const cases[] = {
      "render in more --shading bogus -o out/",
      "render in more --size 0x0 -o out/",
      "render in more --frames 0:2 -o out/",
      "render in more --format bmp -o out/",
      "render in/a.obj more/a.obj -o out.png",  // one file name for several images
      "render in/notes.txt more/a.obj --scene shapes -o out/",
  };
  for (const char* args : cases) {
    CommandResult r = run_facet(dir, args);
    EXPECT_EQ(r.exit_code, kUsageError) << args << "\n" << r.stdout_text;
    EXPECT_EQ(count_lines(r.stderr_text), 1) << args << "\n" << r.stderr_text;
    EXPECT_FALSE(fs::exists(dir / "out")) << args;
    EXPECT_FALSE(fs::exists(dir / "out.png")) << args;
  }
  fs::create_directories(dir / "empty");
  CommandResult r = run_facet(dir, "render empty -o out/");
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_TRUE(contains(r.stderr_text, "empty: no model files")) << r.stderr_text;
}

// --- thumbnail ----------------------------------------------------------------------------

TEST(CliThumbnail, WritesASquarePngAndNothingElse) {
  fs::path dir = batch_inputs("thumbnail");
  CommandResult r = run_facet(dir, "thumbnail -s 48 in/sub/a.stl a.png");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stdout_text, "");
  EXPECT_EQ(r.stderr_text, "");
  Rgba8Image image = read_png((dir / "a.png").string());
  EXPECT_EQ(image.width, 48);
  EXPECT_EQ(image.height, 48);
  // On a transparent background, so it sits on any file manager's theme.
  EXPECT_EQ(image.pixels[3], 0) << "the corner is background";
  // The same image as `facet render` at that size: the thumbnail is an ordinary render.
  ASSERT_EQ(
      run_facet(dir, "render in/sub/a.stl --size 48x48 --background none -q -o r.png").exit_code,
      0);
  EXPECT_EQ(read_file(dir / "a.png"), read_file(dir / "r.png"));
}

// Thumbnailers may pass %u (a file:// URI) and an output name without .png.
TEST(CliThumbnail, ReadsFileUrisAndWritesPngWhateverTheName) {
  fs::path dir = batch_inputs("uri");
  write_text(dir / "with space%.obj", kObj);
  const std::string uri = "file://" + (dir / "with%20space%25.obj").string();
  CommandResult r = run_facet(dir, "thumbnail -s 32 '" + uri + "' thumb.tmp");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  Rgba8Image image = read_png((dir / "thumb.tmp").string());
  EXPECT_EQ(image.width, 32);
  ASSERT_EQ(run_facet(dir, "thumbnail -s 32 in/a.obj a.png").exit_code, 0);
  EXPECT_EQ(read_file(dir / "thumb.tmp"), read_file(dir / "a.png"));
  // Only what the folder had before, and the two thumbnails: no temporary left.
  EXPECT_EQ(files_under(dir).size(), 8u);
}

TEST(CliThumbnail, ABadFileIsOneLineAndWritesNothing) {
  fs::path dir = batch_inputs("bad");
  for (const char* args :
       {"thumbnail -s 32 in/broken.obj t.png", "thumbnail -s 32 no_such.obj t.png",
        "thumbnail -s 32 http://example.com/a.obj t.png", "thumbnail -s 0 in/a.obj t.png",
        "thumbnail -s 32 in/broken.obj t"}) {
    CommandResult r = run_facet(dir, args);
    EXPECT_EQ(r.exit_code, kUsageError) << args;
    EXPECT_EQ(count_lines(r.stderr_text), 1) << args << "\n" << r.stderr_text;
    EXPECT_FALSE(fs::exists(dir / "t.png")) << args;
    EXPECT_FALSE(fs::exists(dir / "t")) << args;
  }
  EXPECT_EQ(files_under(dir).size(), 5u) << "a temporary was left behind";
}

// --- help and parse errors ----------------------------------------------------------------

TEST(CliHelp, ProgramHelpListsEachCommandInOneLineAndFitsAScreen) {
  CommandResult r = run_facet(::testing::TempDir(), "--help");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_LT(count_lines(r.stdout_text), 25) << r.stdout_text;
  EXPECT_TRUE(contains(r.stdout_text, "Usage: facet ")) << r.stdout_text;
  EXPECT_FALSE(contains(r.stdout_text, FACET_CLI)) << "the build path in the usage line";
  for (const char* command : {"render", "thumbnail", "view", "info", "bench"}) {
    EXPECT_TRUE(contains(r.stdout_text, "\n  " + std::string(command) + " ")) << command;
  }
  EXPECT_FALSE(contains(r.stdout_text, "--shading")) << "render's options belong to its help";
  CommandResult render = run_facet(::testing::TempDir(), "render --help");
  EXPECT_TRUE(contains(render.stdout_text, "Usage: facet render")) << render.stdout_text;
  EXPECT_TRUE(contains(render.stdout_text, "--ortho")) << render.stdout_text;
  CommandResult thumbnail = run_facet(::testing::TempDir(), "thumbnail --help");
  EXPECT_TRUE(contains(thumbnail.stdout_text, "Usage: facet thumbnail")) << thumbnail.stdout_text;
}

struct UsageCase {
  const char* args;
  const char* names;  // the flag or word the message must name
  const char* help;   // the --help it must point to
};

TEST(CliUsage, ParseErrorsAreOneLineInFacetsWords) {
  const UsageCase cases[] = {
      {"render --size", "--size", "facet render --help"},
      {"render --size 1x1 --size 2x2 -o a.png", "--size", "facet render --help"},
      {"render --no-such-flag -o a.png", "--no-such-flag", "facet render --help"},
      {"render --threads many -o a.png", "many", "facet render --help"},
      {"render --scene shapes", "--output", "facet render --help"},
      {"thumbnail -s 64 a.obj", "OUTPUT", "facet thumbnail --help"},
      {"info a.obj b.obj", "b.obj", "facet info --help"},
      {"render --ortho=maybe -o a.png", "--ortho", "facet render --help"},
      {"--no-such-flag render", "--no-such-flag", "facet --help"},
      {"rendr a.obj", "rendr", "facet --help"},
      {"", "command", "facet --help"},
  };
  // CLI11's own phrases, which must not reach the user.
  const char* const raw[] = {"At Most", "was not expected", "required TEXT missing",
                             "Could not convert", "A subcommand"};
  for (const UsageCase& c : cases) {
    CommandResult r = run_facet(::testing::TempDir(), c.args);
    EXPECT_EQ(r.exit_code, kUsageError) << c.args;
    EXPECT_EQ(count_lines(r.stderr_text), 1) << c.args << "\n" << r.stderr_text;
    EXPECT_EQ(r.stderr_text.rfind("facet: error: ", 0), 0u) << r.stderr_text;
    EXPECT_TRUE(contains(r.stderr_text, c.names)) << c.args << "\n" << r.stderr_text;
    EXPECT_TRUE(contains(r.stderr_text, "(see " + std::string(c.help) + ")")) << c.args << "\n"
                                                                              << r.stderr_text;
    for (const char* phrase : raw) EXPECT_FALSE(contains(r.stderr_text, phrase)) << r.stderr_text;
  }
}

TEST(CliRender, OrthoIsOrthographic) {
  fs::path dir = fresh_test_dir("facet_batch_", "ortho");
  const std::string common = "render --scene shapes --size 48x27 -q ";
  ASSERT_EQ(run_facet(dir, common + "--ortho -o short.png").exit_code, 0);
  ASSERT_EQ(run_facet(dir, common + "--orthographic -o long.png").exit_code, 0);
  ASSERT_EQ(run_facet(dir, common + "-o perspective.png").exit_code, 0);
  EXPECT_EQ(read_file(dir / "short.png"), read_file(dir / "long.png"));
  EXPECT_NE(read_file(dir / "short.png"), read_file(dir / "perspective.png"));
}

}  // namespace
}  // namespace facet::test
