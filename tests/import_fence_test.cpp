// The fence around assimp (src/import/assimp_fence.cpp): a read by assimp that crashes, aborts
// on an assertion, loops for ever or allocates without end is one facet::Error naming the file
// and what happened, within the time limit, and the calling process lives on. The faults are
// made on purpose in the fenced child (FACET_FENCE_TEST_FAULT: assimp 5.2 has no known file
// that crashes or hangs its OBJ, STL, 3DS, COLLADA or OFF readers once facet's prechecks ran;
// import_mutations_test.cpp looks for them). Fenced imports are the same as unfenced ones, and
// fork from a process whose oneTBB workers are busy without stalling.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "import/assimp_fence.hpp"
#include "import/assimp_read_report.hpp"
#include "import/import_internal.hpp"
#include "support/cli_content_inputs.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"
#include "support/scene_compare.hpp"

#ifndef FACET_SANITIZE_THREAD
#include <tbb/parallel_for.h>
#endif

namespace facet::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const fs::path kBox = kSampleModels / "OBJ/box.obj";
const fs::path kOff = kSampleModels / "OFF/Wuson.off";

// Sets FACET_FENCE_TEST_FAULT for one test (the fenced child reads it).
class ScopedFault {
 public:
  explicit ScopedFault(const char* fault) { ::setenv("FACET_FENCE_TEST_FAULT", fault, 1); }
  ~ScopedFault() { ::unsetenv("FACET_FENCE_TEST_FAULT"); }
  ScopedFault(const ScopedFault&) = delete;
  ScopedFault& operator=(const ScopedFault&) = delete;
};

ImportOptions quiet() {
  ImportOptions options;
  options.warn = [](const std::string&) {};
  return options;
}

// The error import_scene throws, or "" if it imported.
std::string import_error(const fs::path& model, const ImportOptions& options) {
  try {
    import_scene(model.string(), options);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// import_error and how long it took, in seconds.
struct TimedError {
  std::string message;
  double seconds;
};
TimedError timed_import_error(const fs::path& model, const ImportOptions& options) {
  const auto start = Clock::now();
  std::string message = import_error(model, options);
  return {std::move(message), std::chrono::duration<double>(Clock::now() - start).count()};
}

void expect_one_line_naming(const std::string& message, const fs::path& model) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.rfind(model.string() + ": cannot import: ", 0), 0u) << message;
}

TEST(ImportFence, CrashInsideAssimpIsOneError) {
  REQUIRE_INSTALLED(kBox);
  const ScopedFault fault("crash");
  const std::string message = import_error(kBox, quiet());
  expect_one_line_naming(message, kBox);
  EXPECT_NE(message.find("assimp crashed (signal 11, Segmentation fault) reading it"),
            std::string::npos)
      << message;
}

TEST(ImportFence, AssertionInsideAssimpIsOneErrorQuotingIt) {
  REQUIRE_INSTALLED(kBox);
  const ScopedFault fault("abort");
  const std::string message = import_error(kBox, quiet());
  expect_one_line_naming(message, kBox);
  EXPECT_NE(message.find("assimp aborted (signal 6, Aborted) reading it: "), std::string::npos)
      << message;
  EXPECT_NE(message.find("Assertion `probe' failed."), std::string::npos) << message;
}

TEST(ImportFence, EndlessLoopStopsAtTheTimeLimit) {
  REQUIRE_INSTALLED(kBox);
  const ScopedFault fault("hang");
  ImportOptions options = quiet();
  options.import_time_limit_seconds = 0.5;
  const auto [message, seconds] = timed_import_error(kBox, options);
  expect_one_line_naming(message, kBox);
  EXPECT_NE(message.find("assimp took longer than 0.5 s reading it and was stopped"),
            std::string::npos)
      << message;
  EXPECT_GE(seconds, 0.5);
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  // A sanitizer's locks spin in a child forked while another thread held one: a child that
  // timed out is started again, twice.
  EXPECT_GE(seconds, 3 * 0.5);
#endif
  EXPECT_LT(seconds, 10.0);  // the child would hang for ever: it was stopped
}

// A reader asleep for good (as one forked while another thread held its allocator's lock) is
// started again, and after three such starts reported, long before the time limit.
TEST(ImportFence, AReaderAsleepForGoodIsStartedAgainThenReported) {
  REQUIRE_INSTALLED(kBox);
  const ScopedFault fault("stall");
  ImportOptions options = quiet();
  options.import_time_limit_seconds = 60.0;
  const auto [message, seconds] = timed_import_error(kBox, options);
  expect_one_line_naming(message, kBox);
  EXPECT_NE(message.find("assimp's fenced reader stalled 3 times"), std::string::npos) << message;
  EXPECT_GE(seconds, 3 * 2.0);  // three starts, each still for 2 s
  EXPECT_LT(seconds, 20.0);
}

TEST(ImportFence, HugeAllocationStopsAtTheMemoryLimit) {
  REQUIRE_INSTALLED(kBox);
  const ScopedFault fault("memory");
  ImportOptions options = quiet();
  options.import_memory_limit_bytes = 256ull << 20;
  const std::string message = import_error(kBox, options);
  expect_one_line_naming(message, kBox);
  // An AddressSanitizer build's allocator reports and exits on its own instead.
  EXPECT_TRUE(message.find("assimp needed more than 256 MiB of memory reading it") !=
                  std::string::npos ||
              message.find("assimp's reader exited with status") != std::string::npos)
      << message;
}

TEST(ImportFence, TurnedOffTheChildIsNotStarted) {
  REQUIRE_INSTALLED(kBox);
  const ScopedFault fault("crash");  // would fail the import, were a child started
  ImportOptions options = quiet();
  options.fence_assimp = false;
  EXPECT_EQ(import_error(kBox, options), "");
}

// Every file of assimp-testmodels that goes to assimp, models or not: the same scene, the same
// warnings, or the same error, fenced and unfenced. The fenced import must take the dump: it
// warns when it falls back to reading the file itself.
TEST(ImportFence, FencedImportIsTheUnfencedOne) {
  REQUIRE_INSTALLED(kOff);
  int compared = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kSampleModels)) {
    const std::string extension = io::lower_case(entry.path().extension().string());
    if (!entry.is_regular_file() || extension == ".ply" || extension == ".stl" ||
        extension == ".gltf" || extension == ".glb" || extension == ".d") {
      continue;  // facet's own readers
    }
    SCOPED_TRACE(entry.path().string());
    struct Import {
      Scene scene;
      std::vector<std::string> warnings;
      std::string error;
    };
    auto import = [&](bool fenced) {
      Import out;
      ImportOptions options;
      options.fence_assimp = fenced;
      options.warn = [&](const std::string& message) { out.warnings.push_back(message); };
      try {
        out.scene = io::import_assimp_scene(entry.path().string(), options);
      } catch (const Error& e) {
        out.error = e.what();
      }
      return out;
    };
    const Import a = import(true), b = import(false);
    EXPECT_EQ(a.error, b.error);
    EXPECT_EQ(a.warnings, b.warnings);
    if (!a.error.empty() || !b.error.empty()) continue;
    expect_same_scene(a.scene, b.scene);
    ++compared;
  }
  // OBJ+MTL, 3DS, COLLADA, FBX, OFF and more; embedded textures (FBX, .zae, Half-Life MDL).
  EXPECT_GT(compared, 250);
}

// What the read writes in the child is what the caller gets back.
TEST(ImportFence, WhatTheChildWritesComesBack) {
  const io::FencedResult result = io::run_fenced("model", quiet(), [](int out) {
    [[maybe_unused]] auto written = ::write(out, "the scene", 9);
  });
  EXPECT_EQ(result.bytes(), "the scene");
  ImportOptions unfenced = quiet();
  unfenced.fence_assimp = false;
  EXPECT_EQ(io::run_fenced("model", unfenced, [](int) {}).bytes(), "");
}

// The child's report (the dump, the read's error, refusals, points left out, texture names)
// reads back whole; bytes that are not a whole report read as none (the caller then reads the
// file itself).
TEST(ImportFence, ReadReportsReadBackWholeOrNotAtAll) {
  io::AssimpReadReport report;
  report.error = "OBJ: vertex index out of range";
  report.refusals = {"a.mtl: refused", "b.png: refused"};
  report.dropped_points = 7;
  report.dump = "ASSIMP.binary-dump.";
  report.texture_names = {"skin.png", ""};
  report.orthographic_widths = {0.0f, 2.5f};
  const int fd = ::memfd_create("facet-test-report", MFD_CLOEXEC);
  ASSERT_GE(fd, 0);
  EXPECT_TRUE(io::write_read_report(fd, report));
  std::string bytes(static_cast<std::size_t>(::lseek(fd, 0, SEEK_END)), '\0');
  EXPECT_EQ(::pread(fd, bytes.data(), bytes.size(), 0), static_cast<ssize_t>(bytes.size()));
  ::close(fd);
  const std::optional<io::AssimpReadReport> back = io::parse_read_report(bytes);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->error, report.error);
  EXPECT_EQ(back->refusals, report.refusals);
  EXPECT_EQ(back->dropped_points, 7u);
  EXPECT_EQ(back->dump, report.dump);
  EXPECT_EQ(back->texture_names, report.texture_names);
  EXPECT_EQ(back->orthographic_widths, report.orthographic_widths);
  for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
    EXPECT_FALSE(io::parse_read_report(std::string_view(bytes).substr(0, cut))) << cut;
  }
  EXPECT_FALSE(io::parse_read_report(bytes + "x"));
  std::string retagged = bytes;
  retagged[0] = 'F';
  EXPECT_FALSE(io::parse_read_report(retagged));
}

// fork() copies only the calling thread: the child must not need a lock another thread holds.
// Imports from four threads at once while oneTBB's workers are busy: all finish, promptly.
TEST(ImportFence, ForksWhileOtherThreadsWork) {
  REQUIRE_INSTALLED(kBox);
  std::atomic<bool> stop{false};
  auto busy = std::async(std::launch::async, [&] {
    while (!stop) {
#ifndef FACET_SANITIZE_THREAD
      tbb::parallel_for(0, 1000, [](int i) {
        std::vector<int> scratch(static_cast<std::size_t>(i % 97) + 1);  // malloc under way
        scratch.back() = i;
      });
#else
      std::vector<int> scratch(97);
#endif
    }
  });
  std::vector<std::future<std::size_t>> imports;
  for (int t = 0; t < 4; ++t) {
    imports.push_back(std::async(std::launch::async, [] {
      std::size_t triangles = 0;
      for (int i = 0; i < 5; ++i)
        triangles += import_scene(kBox.string(), quiet()).triangle_count();
      return triangles;
    }));
  }
  for (auto& import : imports) {
    ASSERT_EQ(import.wait_for(std::chrono::seconds(30)), std::future_status::ready);
    EXPECT_EQ(import.get(), 5u * 12u);
  }
  stop = true;
  busy.get();
}

// The CLI on a model whose read crashes or hangs assimp: one line on stderr, exit 2, no image.
TEST(ImportFence, CliSaysOneLineAndWritesNothing) {
  REQUIRE_INSTALLED(kBox);
  for (const char* fault : {"crash", "hang"}) {
    SCOPED_TRACE(fault);
    const fs::path dir = fresh_test_dir("facet_import_fence_", fault);
    const auto start = Clock::now();
    const CommandResult r = run_command(
        "cd '" + dir.string() + "' && FACET_FENCE_TEST_FAULT=" + fault + " " + FACET_CLI +
        " render " + kBox.string() + " --import-timeout 1 -o out.png" + kCliSize);
    EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 10.0);
    EXPECT_EQ(r.exit_code, kUsageError);
    const std::vector<std::string> lines = lines_of(r.stderr_text);
    ASSERT_EQ(lines.size(), 1u) << r.stderr_text;
    EXPECT_EQ(lines[0].rfind("facet: error: " + kBox.string() + ": cannot import: assimp ", 0), 0u)
        << lines[0];
    EXPECT_EQ(list_dir(dir), std::vector<std::string>{});
  }
}

TEST(ImportFence, CliRefusesANegativeTimeout) {
  REQUIRE_INSTALLED(kBox);
  const fs::path dir = fresh_test_dir("facet_import_fence_", "negative");
  const CommandResult r = run_facet(dir, "info " + kBox.string() + " --import-timeout -1");
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_NE(r.stderr_text.find("--import-timeout"), std::string::npos) << r.stderr_text;
}

}  // namespace
}  // namespace facet::test
