// Damaged files of every format facet reads: 50 seeded mutations of one real small file per
// format (bit flips, truncations, lengths that lie in binary headers, repeated spans, numbers
// that lie in text), each imported (and drawn, when it imports) within a bounded time. Zero
// crashes, zero hangs, and every failure is one facet::Error line naming the file. The sweeps of
// the unmodified sample files are import_test.cpp's and import_formats_test.cpp's.
//
// FACET_MUTATIONS=N sets the number of mutations per format for a longer run.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <thread>
#include <typeinfo>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

// One import may take this long (a slow machine, a sanitizer build) before it counts as a hang;
// assimp's fenced read is stopped sooner (kFenceSeconds).
constexpr auto kHang = std::chrono::seconds(20);
constexpr double kFenceSeconds = 10.0;

struct Sample {
  const char* name;
  fs::path source;                   // the real file mutated
  std::string file_name;             // its name in the test folder
  std::vector<fs::path> beside;      // copied unmodified beside it (buffers, textures)
  std::vector<std::size_t> lengths;  // offsets of 32-bit little-endian length fields
  std::string model;                 // the file imported; empty: the mutated one
};

const fs::path kBoxGltf = kSampleModels / "glTF2/BoxTextured-glTF";

// A .d file and an OBJ whose material's texture is the mutated PNG, written by the test.
const char kOctahedronD[] =
    "data 6 8\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
    "3 1 3 5\n3 3 2 5\n3 2 4 5\n3 4 1 5\n3 3 1 6\n3 2 3 6\n3 4 2 6\n3 1 4 6\n";
const char kTexturedObj[] =
    "mtllib textured.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
    "f 1/1 2/2 3/3\n";
const char kTexturedMtl[] = "newmtl m\nKd 1 1 1\nmap_Kd texture.png\n";

std::vector<Sample> samples() {
  return {
      {"gltf",
       kBoxGltf / "BoxTextured.gltf",
       "box.gltf",
       {kBoxGltf / "BoxTextured0.bin", kBoxGltf / "CesiumLogoFlat.png"},
       {},
       ""},
      // The GLB's total length, JSON chunk length, and (for this file) its BIN chunk length.
      {"glb",
       kSampleModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
       "box.glb",
       {},
       {8, 12},
       ""},
      {"obj",
       kSampleModels / "OBJ/cube_usemtl.obj",
       "cube.obj",
       {kSampleModels / "OBJ/cube_usemtl.mtl"},
       {},
       ""},
      // Plain geometry, facet's own reader's (obj_plain.cpp) unless a mutation makes it more.
      {"obj_plain", kSampleModels / "OBJ/multiple_spaces.obj", "spaces.obj", {}, {}, ""},
      {"stl_binary", kSampleModels / "STL/Spider_binary.stl", "spider.stl", {}, {80}, ""},
      {"stl_ascii",
       kSampleModels / "STL/triangle_with_two_solids.stl",
       "triangles.stl",
       {},
       {},
       ""},
      {"ply_ascii", kSampleModels / "PLY/cube.ply", "cube.ply", {}, {}, ""},
      {"ply_binary", kSampleModels / "PLY/cube_binary.ply", "cube.ply", {}, {}, ""},
      // The main chunk's length, and its first two children's.
      {"3ds", kSampleModels / "3DS/cube_with_diffuse_texture.3DS", "cube.3ds", {}, {2, 8, 18}, ""},
      {"collada", kSampleModels / "Collada/cameras.dae", "cameras.dae", {}, {}, ""},
      {"off", kSampleModels / "OFF/Cube.off", "cube.off", {}, {}, ""},
      {"d", "", "octahedron.d", {}, {}, ""},
      // IHDR's length and the next chunk's.
      {"png", kBoxGltf / "CesiumLogoFlat.png", "texture.png", {}, {8, 33}, "textured.obj"},
  };
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// Mutation `index` of `bytes`: the kind cycles through the five, the details come from a
// generator seeded with the index, so every run makes the same files.
std::string mutate(std::string bytes, const Sample& sample, unsigned index) {
  std::mt19937 random(0x5eed0000u + index);
  auto below = [&](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(random() % n); };
  if (bytes.empty()) return bytes;
  switch (index % 5) {
    case 0:  // bit flips
      for (std::size_t flips = 1 + below(8); flips-- > 0;)
        bytes[below(bytes.size())] ^= static_cast<char>(1u << below(8));
      break;
    case 1:  // cut short
      bytes.resize(below(bytes.size()));
      break;
    case 2: {  // a length field that lies (a random 4 bytes when the format has none known)
      static const std::uint32_t kLies[] = {0xffffffffu, 0x7fffffffu, 0x80000000u, 0u, 0x10000u};
      std::size_t at = sample.lengths.empty() ? below(bytes.size())
                                              : sample.lengths[below(sample.lengths.size())];
      const std::uint32_t lie = kLies[below(std::size(kLies))];
      for (int b = 0; b < 4 && at + b < bytes.size(); ++b)
        bytes[at + b] = static_cast<char>(lie >> (8 * b));
      break;
    }
    case 3: {  // a span repeated
      const std::size_t from = below(bytes.size());
      const std::size_t length = std::min(bytes.size() - from, 1 + below(64));
      const std::string span = bytes.substr(from, length);
      std::string repeated;
      for (std::size_t n = 2 + below(20); n-- > 0;) repeated += span;
      bytes.insert(from + length, repeated);
      break;
    }
    default: {  // a number that lies: a run of digits replaced by a huge or negative one
      static const char* const kNumbers[] = {"4294967295", "99999999999999999999", "-1",
                                             "0",          "2147483648",           "1e38"};
      std::vector<std::size_t> runs;
      for (std::size_t i = 0; i < bytes.size(); ++i) {
        const bool digit = bytes[i] >= '0' && bytes[i] <= '9';
        if (digit && (i == 0 || bytes[i - 1] < '0' || bytes[i - 1] > '9')) runs.push_back(i);
      }
      if (runs.empty()) {
        bytes[below(bytes.size())] = '9';
        break;
      }
      const std::size_t start = runs[below(runs.size())];
      std::size_t end = start;
      while (end < bytes.size() && bytes[end] >= '0' && bytes[end] <= '9') ++end;
      bytes.replace(start, end - start, kNumbers[below(std::size(kNumbers))]);
      break;
    }
  }
  return bytes;
}

unsigned mutation_count() {
  const char* value = std::getenv("FACET_MUTATIONS");
  return value ? static_cast<unsigned>(std::strtoul(value, nullptr, 10)) : 50u;
}

enum class Result { imported, failed, hung };

// Imports (and draws) the model on a thread of its own, so that a hang fails the test instead
// of stalling it; a hung thread is left behind (the test has failed).
Result import_bounded(const fs::path& model, std::string& error) {
  auto outcome = std::make_shared<std::promise<std::string>>();
  std::future<std::string> done = outcome->get_future();
  std::thread([model, outcome] {
    ImportOptions options;
    options.warn = [](const std::string&) {};
    options.import_time_limit_seconds = kFenceSeconds;
    try {
      render_small(import_scene(model.string(), options));
      outcome->set_value("");
    } catch (const Error& e) {
      outcome->set_value(std::string("E") + e.what());
    } catch (const std::exception& e) {
      outcome->set_value(std::string("X") + typeid(e).name() + ": " + e.what());
    }
  }).detach();
  if (done.wait_for(kHang) != std::future_status::ready) return Result::hung;
  error = done.get();
  return error.empty() ? Result::imported : Result::failed;
}

void PrintTo(const Sample& sample, std::ostream* os) { *os << sample.name; }

class ImportMutations : public ::testing::TestWithParam<Sample> {};

TEST_P(ImportMutations, NeverCrashHangOrThrowAnythingButOneLine) {
  const Sample& sample = GetParam();
  FACET_REQUIRE_PACKAGE(sample.source.empty() || fs::exists(sample.source),
                        sample.source << " is missing (assimp-testmodels)");
  const fs::path dir = fresh_test_dir("facet_import_mutations_", sample.name);
  for (const fs::path& file : sample.beside) fs::copy_file(file, dir / file.filename());
  if (std::string(sample.name) == "png") {
    write_bytes(dir / "textured.obj", kTexturedObj);
    write_bytes(dir / "textured.mtl", kTexturedMtl);
  }
  const std::string original =
      sample.source.empty() ? std::string(kOctahedronD) : read_bytes(sample.source);
  const fs::path mutated = dir / sample.file_name;
  const fs::path model = sample.model.empty() ? mutated : dir / sample.model;
  int imported = 0, failed = 0;
  for (unsigned i = 0; i < mutation_count(); ++i) {
    SCOPED_TRACE("mutation " + std::to_string(i) + " (kind " + std::to_string(i % 5) + ")");
    write_bytes(mutated, mutate(original, sample, i));
    std::string error;
    switch (import_bounded(model, error)) {
      case Result::hung:
        write_bytes(dir / ("hang_" + std::to_string(i) + "_" + sample.file_name),
                    mutate(original, sample, i));
        FAIL() << "import of " << model << " hung (kept beside it as hang_" << i << "_...)";
      case Result::imported:
        ++imported;
        break;
      case Result::failed:
        ++failed;
        ASSERT_EQ(error[0], 'E') << "not a facet::Error: " << error.substr(1);
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        EXPECT_GT(error.size(), model.string().size() + 3) << error;
        EXPECT_EQ(error.rfind("E" + model.string(), 0), 0u)
            << "does not name the file: " << error.substr(1);
        break;
    }
  }
  RecordProperty("imported", imported);
  RecordProperty("failed", failed);
}

INSTANTIATE_TEST_SUITE_P(Formats, ImportMutations, ::testing::ValuesIn(samples()),
                         [](const ::testing::TestParamInfo<Sample>& sample) {
                           return std::string(sample.param.name);
                         });

}  // namespace
}  // namespace facet::test
