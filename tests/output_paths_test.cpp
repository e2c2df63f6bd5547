// Where output files end up and what a failed write says: a symbolic link is written through
// (its target replaced atomically, the link kept), a full disk gives one error line and leaves
// nothing behind, and paths that are not files say what they are. Through the library's
// write_image and through `facet render`.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "support/cli_content_inputs.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const std::string kShapes = "render --scene shapes --size 64x48 ";

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool is_png(const fs::path& path) { return bytes_of(path).rfind("\x89PNG", 0) == 0; }

TEST(OutputPaths, LibraryWritesThroughASymbolicLink) {
  fs::path dir = fresh_test_dir("facet_output_paths_", "library_link");
  fs::create_directory(dir / "store");
  fs::create_symlink("store/picture.ppm", dir / "link.ppm");  // dangling: the target is made
  Framebuffer image(4, 2);
  write_image(image, (dir / "link.ppm").string());
  ASSERT_TRUE(fs::is_symlink(dir / "link.ppm")) << "the link was replaced by a file";
  EXPECT_EQ(bytes_of(dir / "store/picture.ppm").rfind("P6\n4 2\n255\n", 0), 0u);
  EXPECT_EQ(list_dir(dir / "store"), std::vector<std::string>{"picture.ppm"});
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"link.ppm", "store"}));
}

TEST(OutputPaths, LibraryRefusesALinkLoop) {
  fs::path dir = fresh_test_dir("facet_output_paths_", "library_loop");
  fs::create_symlink("b.png", dir / "a.png");
  fs::create_symlink("a.png", dir / "b.png");
  Framebuffer image(4, 2);
  try {
    write_image(image, (dir / "a.png").string());
    ADD_FAILURE() << "a link loop was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("too many levels of symbolic links"), std::string::npos)
        << e.what();
  }
}

// The link stays a link and its target holds the image; a second output beside it (depth)
// lands under the link's name, and a link to a file without an extension still gets a PNG.
TEST(OutputPaths, RenderWritesThroughSymbolicLinks) {
  fs::path dir = fresh_test_dir("facet_output_paths_", "cli_links");
  fs::create_directory(dir / "store");
  fs::create_symlink("store/thumb.png", dir / "new.png");  // dangling
  fs::create_symlink(dir / "store" / "blob", dir / "old.png");
  std::ofstream(dir / "store" / "blob") << "an older file";
  CommandResult made = run_facet(dir, kShapes + "-o new.png");
  ASSERT_EQ(made.exit_code, 0) << made.stderr_text;
  CommandResult replaced = run_facet(dir, kShapes + "-o old.png --outputs color,depth");
  ASSERT_EQ(replaced.exit_code, 0) << replaced.stderr_text;
  EXPECT_TRUE(fs::is_symlink(dir / "new.png"));
  EXPECT_TRUE(fs::is_symlink(dir / "old.png"));
  EXPECT_TRUE(is_png(dir / "store" / "thumb.png"));
  EXPECT_TRUE(is_png(dir / "store" / "blob"));
  EXPECT_EQ(bytes_of(dir / "store" / "thumb.png"), bytes_of(dir / "store" / "blob"));
  EXPECT_EQ(list_dir(dir / "store"), (std::vector<std::string>{"blob", "thumb.png"}));
  EXPECT_EQ(list_dir(dir),
            (std::vector<std::string>{"new.png", "old.depth.exr", "old.png", "store"}));
}

// A full disk, made without root: RLIMIT_FSIZE (`ulimit -f`, 512-byte blocks) with SIGXFSZ
// ignored (the ignored disposition survives exec), so a write past the limit fails with EFBIG
// at the same places ENOSPC would. /dev/full cannot stand in: the temporary file and the rename
// are what is being tested, and a device cannot be renamed onto.
CommandResult render_into_a_full_disk(const fs::path& dir, const std::string& args) {
  return run_command("cd '" + dir.string() + "' && trap '' XFSZ && ulimit -f 1 && exec " +
                     FACET_CLI + " " + args);
}

TEST(OutputPaths, FullDiskGivesOneLineAndNoFile) {
  fs::path dir = fresh_test_dir("facet_output_paths_", "full_disk");
  const std::string big = "render --scene shapes --size 256x256 ";
  for (const std::string name : {"full.png", "full.ppm"}) {
    CommandResult r = render_into_a_full_disk(dir, big + "-o " + name);
    EXPECT_EQ(r.exit_code, kUsageError) << name;
    EXPECT_EQ(r.stderr_text, "facet: error: " + name + ": write failed (File too large)\n");
  }
  CommandResult ids = render_into_a_full_disk(dir, big + "-o ids.png --outputs color,instance");
  EXPECT_EQ(ids.exit_code, kUsageError);
  EXPECT_EQ(lines_of(ids.stderr_text).size(), 1u) << ids.stderr_text;
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{}) << "a half-written file was left";
}

TEST(OutputPaths, PathsThatAreNotFilesSayWhatTheyAre) {
  fs::path dir = fresh_test_dir("facet_output_paths_", "not_files");
  fs::create_directory(dir / "somedir");
  EXPECT_EQ(run_facet(dir, kShapes + "-o somedir").stderr_text,
            "facet: error: somedir: is a directory\n");
  EXPECT_EQ(run_facet(dir, "render /dev/null -o out.png").stderr_text,
            "facet: error: /dev/null: is a character device, not a model file\n");
  ASSERT_EQ(::mkfifo((dir / "pipe.obj").c_str(), 0600), 0);
  EXPECT_EQ(run_facet(dir, "render pipe.obj -o out.png").stderr_text,
            "facet: error: pipe.obj: is a named pipe, not a model file\n");
}

}  // namespace
}  // namespace facet::test
