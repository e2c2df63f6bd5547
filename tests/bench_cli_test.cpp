// `facet bench` through the real binary: the table it prints, the JSON file it writes, and one
// error line for bad values.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::vector<std::string> lines(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(BenchCli, PrintsOneRowPerSceneWithEveryStageAndWritesJson) {
  auto dir = fresh_test_dir("facet_bench_cli_", "table");
  const std::string json = (dir / "out.json").string();
  std::string command = FACET_CLI;
  command +=
      " bench --scene overdraw --size 96x54 --frames 3 --warmup 1 --threads 2 --tile-size 32 "
      "--json ";
  command += json;
  CommandResult r = run_command(command);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::vector<std::string> out = lines(r.stdout_text);
  ASSERT_EQ(out.size(), 3u) << r.stdout_text;  // header, the scene, the footnote
  EXPECT_EQ(words(out[0]),
            (std::vector<std::string>{"scene", "median", "min", "max", "Mtri/s", "Mpix/s", "geom",
                                      "bin", "raster", "resolve"}));
  std::vector<std::string> row = words(out[1]);
  ASSERT_EQ(row.size(), 10u) << out[1];
  EXPECT_EQ(row[0], "overdraw");
  for (std::size_t i = 1; i < row.size(); ++i) {
    EXPECT_GE(std::stod(row[i]), 0.0) << "column " << i << " of " << out[1];
  }
  EXPECT_LE(std::stod(row[2]), std::stod(row[1]));  // min <= median
  EXPECT_LE(std::stod(row[1]), std::stod(row[3]));  // median <= max
  std::ifstream file(json);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  for (const char* key :
       {"\"size\": \"96x54\"", "\"threads\": 2", "\"tile_size\": 32", "\"frames\": 3",
        "\"name\": \"overdraw\"", "\"median_ms\"", "\"triangles_per_s\"", "\"pixels_per_s\"",
        "\"geometry_ms\"", "\"binning_ms\"", "\"raster_ms\"", "\"resolve_ms\"",
        // overdraw is eight quads, all in view and facing the camera
        "\"triangles_in\": 16", "\"triangles_drawn\": 16", "\"pixels_shaded\"",
        "\"tile_size\": 32}"}) {
    EXPECT_NE(text.find(key), std::string::npos) << key << " missing from\n" << text;
  }
}

// Without --tile-size the size is chosen per frame: the JSON says "auto", and each scene the size
// its frames used (overdraw's tiles hold floats: 64).
TEST(BenchCli, JsonNamesTheAutomaticTileSizeAndTheOneUsed) {
  auto dir = fresh_test_dir("facet_bench_cli_", "auto_tiles");
  const std::string json = (dir / "out.json").string();
  std::string command = FACET_CLI;
  command += " bench --scene overdraw --size 32x18 --frames 1 --warmup 0 --json " + json;
  CommandResult r = run_command(command);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::ifstream file(json);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  for (const char* key : {"\"tile_size\": \"auto\"", "\"tile_size\": 64}"}) {
    EXPECT_NE(text.find(key), std::string::npos) << key << " missing from\n" << text;
  }
}

// --scene takes a list: one row per scene, in the order given.
TEST(BenchCli, SceneListRunsEachSceneInOrder) {
  std::string command = FACET_CLI;
  command += " bench --scene overdraw-front-to-back,shapes --size 32x18 --frames 1 --warmup 0";
  CommandResult r = run_command(command);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::vector<std::string> out = lines(r.stdout_text);
  ASSERT_EQ(out.size(), 4u) << r.stdout_text;
  EXPECT_EQ(words(out[1]).at(0), "overdraw-front-to-back");
  EXPECT_EQ(words(out[2]).at(0), "shapes");
}

TEST(BenchCli, BadValuesGiveOneErrorLine) {
  for (const char* args :
       {"--scene no_such_scene", "--scene overdraw,", "--scene shapes,nope", "--backend vulkan",
        "--frames 0", "--warmup -1", "--threads -2", "--size 0x10", "--tile-size 48", "--msaa 3",
        "--shadows yes", "--shadow-map-size 0", "--shadow-map-size 100000",
        "--gl-readback maybe"}) {
    std::string command = FACET_CLI;
    command += " bench --size 32x18 ";
    command += args;
    CommandResult r = run_command(command);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(lines(r.stderr_text).size(), 1u) << args << ": " << r.stderr_text;
    EXPECT_EQ(r.stderr_text.rfind("facet: error: ", 0), 0u) << r.stderr_text;
  }
}

}  // namespace
}  // namespace facet::test
