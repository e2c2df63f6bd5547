// `facet render --frames` through the real binary: numbered files, reruns that skip finished
// frames, shards that together write what one run writes, --time, camera paths, progress on a
// terminal and off it, stopping on SIGTERM, and the error contract for bad sequences (one
// "facet: error:" line naming the flag, exit code 2, no file written).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include "support/cli_content_inputs.hpp"
#include "support/render_helpers.hpp"
#include "support/text.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const std::string kSmall = " --size 64x48";

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

long count_lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// A camera path through the shapes scene: keys at 0 s and 1 s.
fs::path write_camera_path(const fs::path& dir) {
  fs::path path = dir / "path.txt";
  std::ofstream(path) << "# t x y z yaw pitch\n0  0 2 9  0 -8\n1  4 3 8  25 -12\n";
  return path;
}

TEST(CliFrames, SequenceWritesOneNumberedFilePerFrameEndExclusive) {
  fs::path dir = fresh_test_dir("facet_cli_frames_", "names");
  fs::create_directory(dir / "out");
  CommandResult r = run_facet(dir, "render --scene shapes --frames 2:5 -o out/f_%03d.png" + kSmall);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stderr_text, "");
  EXPECT_EQ(list_dir(dir / "out"),
            (std::vector<std::string>{"f_002.png", "f_003.png", "f_004.png"}));
  // Not a terminal: a first line, one line per frame, a summary.
  std::vector<std::string> lines = lines_of(r.stdout_text);
  ASSERT_EQ(lines.size(), 5u) << r.stdout_text;
  EXPECT_EQ(lines[0], "out/f_%03d.png: 64x48, frames 2:5 at 30 fps");
  EXPECT_EQ(lines[1].rfind("frame 2 (1/3): out/f_002.png; render ", 0), 0u) << lines[1];
  EXPECT_EQ(lines[3].rfind("frame 4 (3/3): out/f_004.png; render ", 0), 0u) << lines[3];
  EXPECT_EQ(lines[4].rfind("3 frames in ", 0), 0u) << lines[4];
  EXPECT_TRUE(contains(lines[4], ": 3 rendered, 0 skipped")) << lines[4];
  Rgba8Image image = read_png((dir / "out/f_003.png").string());
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
}

TEST(CliFrames, RerunSkipsFramesWhoseFilesAllExist) {
  fs::path dir = fresh_test_dir("facet_cli_frames_", "rerun");
  const std::string args = "render --scene shapes -o f_%d.png --outputs color,depth" + kSmall;
  ASSERT_EQ(run_facet(dir, args + " --frames 0:2").exit_code, 0);
  // Frame 1 lost a file: it is not complete, so it is rendered again.
  fs::remove(dir / "f_1.depth.exr");
  const auto old_time = fs::file_time_type::clock::now() - std::chrono::hours(1);
  for (const char* name : {"f_0.png", "f_0.depth.exr", "f_1.png"})
    fs::last_write_time(dir / name, old_time);

  CommandResult r = run_facet(dir, args + " --frames 0:3");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_TRUE(contains(r.stdout_text, "frame 0 (1/3): skipped, already written\n"))
      << r.stdout_text;
  EXPECT_TRUE(contains(r.stdout_text, "frame 1 (2/3): f_1.png, f_1.depth.exr; render"));
  EXPECT_TRUE(contains(r.stdout_text, ": 2 rendered, 1 skipped as already written\n"));
  EXPECT_EQ(fs::last_write_time(dir / "f_0.png"), old_time);
  EXPECT_EQ(fs::last_write_time(dir / "f_0.depth.exr"), old_time);
  EXPECT_NE(fs::last_write_time(dir / "f_1.png"), old_time);
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"f_0.depth.exr", "f_0.png", "f_1.depth.exr",
                                                     "f_1.png", "f_2.depth.exr", "f_2.png"}));

  // --overwrite renders them all again.
  CommandResult again = run_facet(dir, args + " --frames 0:3 --overwrite");
  ASSERT_EQ(again.exit_code, 0) << again.stderr_text;
  EXPECT_FALSE(contains(again.stdout_text, "skipped, already written")) << again.stdout_text;
  EXPECT_NE(fs::last_write_time(dir / "f_0.png"), old_time);
}

// The islands move with time: shards 0/2 and 1/2 write exactly the frames one run writes, byte
// for byte, and --time T draws what the frame at T draws.
TEST(CliFrames, ShardsTogetherWriteWhatOneRunWrites) {
  fs::path whole = fresh_test_dir("facet_cli_frames_", "shard_whole");
  fs::path parts = fresh_test_dir("facet_cli_frames_", "shard_parts");
  const std::string args = "render --scene islands --frames 0:3 --fps 2 -o f_%02d.png" + kSmall;
  ASSERT_EQ(run_facet(whole, args).exit_code, 0);
  CommandResult first = run_facet(parts, args + " --shard 0/2");
  ASSERT_EQ(first.exit_code, 0) << first.stderr_text;
  EXPECT_TRUE(contains(first.stdout_text, "shard 0/2: 2 of 3 frames")) << first.stdout_text;
  EXPECT_EQ(list_dir(parts), (std::vector<std::string>{"f_00.png", "f_02.png"}));
  ASSERT_EQ(run_facet(parts, args + " --shard 1/2").exit_code, 0);

  ASSERT_EQ(list_dir(whole), list_dir(parts));
  for (const std::string& name : list_dir(whole)) {
    EXPECT_EQ(read_file(whole / name), read_file(parts / name)) << name;
  }
  EXPECT_NE(read_file(whole / "f_00.png"), read_file(whole / "f_01.png")) << "nothing moved";
  EXPECT_NE(read_file(whole / "f_01.png"), read_file(whole / "f_02.png")) << "nothing moved";

  ASSERT_EQ(run_facet(parts, "render --scene islands --time 0.5 -o t.png" + kSmall).exit_code, 0);
  EXPECT_EQ(read_file(parts / "t.png"), read_file(whole / "f_01.png"));
}

// A scene that does not move gives the same image every frame; a camera path moves it, and
// --time poses the path as --frames does.
TEST(CliFrames, CameraPathMovesAStillScene) {
  fs::path dir = fresh_test_dir("facet_cli_frames_", "camera_path");
  fs::path path = write_camera_path(dir);
  ASSERT_EQ(run_facet(dir, "render --scene shapes --frames 0:2 -o still_%d.png" + kSmall).exit_code,
            0);
  EXPECT_EQ(read_file(dir / "still_0.png"), read_file(dir / "still_1.png"));
  const std::string moving = "render --scene shapes --camera-path path.txt" + kSmall;
  ASSERT_EQ(run_facet(dir, moving + " --frames 0:3 --fps 4 -o path_%d.png").exit_code, 0);
  EXPECT_NE(read_file(dir / "path_0.png"), read_file(dir / "path_1.png"));
  EXPECT_NE(read_file(dir / "path_0.png"), read_file(dir / "still_0.png"));
  ASSERT_EQ(run_facet(dir, moving + " --time 0.25 -o t.png").exit_code, 0);
  EXPECT_EQ(read_file(dir / "t.png"), read_file(dir / "path_1.png"));
}

TEST(CliFrames, QuietPrintsNothing) {
  fs::path dir = fresh_test_dir("facet_cli_frames_", "quiet");
  for (const char* args : {"--frames 0:2 -o f_%d.png --quiet", "-o one.png -q"}) {
    CommandResult r = run_facet(dir, std::string("render --scene shapes ") + args + kSmall);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.stderr_text;
    EXPECT_EQ(r.stdout_text, "") << args;
    EXPECT_EQ(r.stderr_text, "") << args;
  }
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"f_0.png", "f_1.png", "one.png"}));
}

// On a terminal (script(1) gives the command one) the progress is one line redrawn with a bar,
// frames done, the rate and the time left.
TEST(CliFrames, TerminalShowsARedrawnBar) {
  fs::path dir = fresh_test_dir("facet_cli_frames_", "terminal");
  std::string command = std::string(FACET_CLI) + " render --scene shapes --frames 0:3 -o " +
                        (dir / "f_%d.png").string() + kSmall;
  CommandResult r = run_command("script -qec '" + command + "' /dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.stdout_text << r.stderr_text;
  const std::string& out = r.stdout_text;
  EXPECT_TRUE(contains(out, "\r[")) << out;
  EXPECT_TRUE(contains(out, "] 3/3 frames  ")) << out;
  EXPECT_TRUE(contains(out, " frames/s  ")) << out;
  EXPECT_TRUE(contains(out, " left\033[K")) << out;
  EXPECT_FALSE(contains(out, "frame 1 (2/3)")) << "plain lines on a terminal:\n" << out;
  EXPECT_TRUE(contains(out, "3 frames in ")) << out;
}

// SIGTERM (what a scheduler sends before it kills) ends the sequence after a whole frame: exit
// code 128 + 15, a line saying how to go on, only finished files left.
TEST(CliFrames, SigtermStopsAfterAWholeFrame) {
  fs::path dir = fresh_test_dir("facet_cli_frames_", "sigterm");
  std::string command = std::string(FACET_CLI) +
                        " render --scene shapes --size 320x180 --frames 0:2000 -o f_%04d.png";
  // Started in the background, stopped once the second frame is there (at most 10 s).
  CommandResult r = run_command("cd '" + dir.string() + "' && (" + command +
                                " & pid=$!; for i in $(seq 1000); do [ -e f_0001.png ] && break; "
                                "sleep 0.01; done; kill -TERM $pid; wait $pid)");
  EXPECT_EQ(r.exit_code, 128 + 15) << r.stderr_text;
  EXPECT_TRUE(contains(r.stderr_text, "facet: stopped by SIGTERM after ")) << r.stderr_text;
  EXPECT_TRUE(contains(r.stderr_text, "run the same command again")) << r.stderr_text;
  EXPECT_EQ(count_lines(r.stderr_text), 1) << r.stderr_text;
  std::vector<std::string> files = list_dir(dir);
  ASSERT_GE(files.size(), 2u);
  ASSERT_LT(files.size(), 2000u);
  for (const std::string& name : files) {
    ASSERT_EQ(name.rfind("f_", 0), 0u) << "left behind: " << name;
    EXPECT_EQ(read_png((dir / name).string()).width, 320) << name;
  }
}

// --- bad sequences ------------------------------------------------------------------------

struct BadCase {
  const char* name;
  const char* args;     // after `facet render --scene shapes --size 64x48`, in a fresh folder
  const char* message;  // the whole error line after "facet: error: "
};

const BadCase kBadCases[] = {
    {"frames_backwards", "--frames 5:2 -o f_%d.png",
     "--frames: 5:2 ends before it starts (A:B is frames A to B - 1)"},
    {"frames_empty", "--frames 2:2 -o f_%d.png",
     "--frames: 2:2 holds no frame; the end is exclusive, so 2:3 is frame 2 alone"},
    {"frames_not_a_range", "--frames 10 -o f_%d.png",
     "--frames: expected A:B with whole numbers 0 <= A < B such as 0:120, got '10'"},
    {"shard_past_count", "--frames 0:4 --shard 3/2 -o f_%d.png",
     "--shard: 3/2: I counts from 0, so the shards of 2 are 0/2 to 1/2"},
    {"shard_without_frames", "--shard 0/2 -o f.png",
     "--shard: shares out the frames of --frames A:B; give that too"},
    {"pattern_without_number", "--frames 0:3 -o f.png",
     "--output: 'f.png' has no %d for the frame number, and --frames 0:3 is 3 frames (name them "
     "like frame_%04d.png)"},
    {"number_without_frames", "-o f_%04d.png",
     "--output: 'f_%04d.png' has a frame number (%d) but there is no --frames A:B to fill it in"},
    {"pattern_bad_sequence", "--frames 0:3 -o f_%s.png",
     "--output: 'f_%s.png': '%s' is not a frame number (use %d or %04d for the frame number, %% "
     "for a percent sign)"},
    {"fps_zero", "--frames 0:3 --fps 0 -o f_%d.png",
     "--fps: must be a positive number of frames per second, got 0"},
    {"time_and_frames", "--frames 0:3 --time 1 -o f_%d.png",
     "--time: --frames gives each frame its own time (frame / fps); use one or the other"},
    {"folder_missing", "--frames 0:3 -o missing/f_%d.png",
     "missing/f_0.png: directory missing does not exist"},
    {"unknown_output", "--outputs color,dpeth -o f.png",
     "--outputs: 'dpeth' is not an output (color, depth, distance, normal, instance, triangle, "
     "barycentric, albedo)"},
    {"output_twice", "--outputs depth,color,depth -o f.png",
     "--outputs: 'depth' is asked for twice"},
    {"normal_space_unknown", "--outputs normal --normal-space tangent -o f.png",
     "--normal-space: expected world or camera, got 'tangent'"},
    {"unknown_extension", "--outputs depth -o f.tiff",
     "f.tiff: unknown output type '.tiff' (use .png, .ppm, .exr, .npy or .npz)"},
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << "facet render " << c.args; }

class BadSequence : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadSequence, OneErrorLineNamingTheFlagAndNoFile) {
  const BadCase& c = GetParam();
  fs::path dir = fresh_test_dir("facet_cli_frames_bad_", c.name);
  CommandResult r = run_facet(dir, std::string("render --scene shapes") + kSmall + " " + c.args);
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_EQ(r.stderr_text, std::string("facet: error: ") + c.message + "\n");
  EXPECT_EQ(r.stdout_text, "");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{}) << "files left behind";
}

INSTANTIATE_TEST_SUITE_P(Cli, BadSequence, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

// A folder that cannot be written to: a read-only one, or for root (who may write anyway) one
// of /proc's process folders, which no one may write.
TEST(CliFrames, UnwritableFolderIsOneErrorAndNoFile) {
  fs::path dir = fresh_test_dir("facet_cli_frames_", "unwritable");
  fs::path folder = "/proc/1";
  if (::geteuid() != 0) {
    folder = dir / "read_only";
    fs::create_directory(folder);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
  }
  const std::string pattern = (folder / "f_%02d.png").string();
  CommandResult r = run_facet(dir, "render --scene shapes --frames 0:3 -o " + pattern + kSmall);
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_EQ(r.stderr_text, "facet: error: " + (folder / "f_00.png").string() + ": directory " +
                               folder.string() + " is not writable\n");
  EXPECT_EQ(r.stdout_text, "");
  if (folder != "/proc/1") {
    EXPECT_EQ(list_dir(folder), std::vector<std::string>{});
  }
}

}  // namespace
}  // namespace facet::test
