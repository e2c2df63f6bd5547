// The inputs and the runner shared by the `facet render MODEL` tests through the real binary
// (cli_content_test.cpp: models and flags; cli_content_errors_test.cpp: the error contract).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {

inline constexpr int kUsageError = 2;
inline constexpr int kCliWidth = 320;
inline constexpr int kCliHeight = 180;
inline const std::string kCliSize = " --size 320x180";
inline const std::string kBunny = "/usr/share/glmark2/models/bunny.obj";
inline const std::string kBoxGlb =
    "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
inline const std::string kCamerasGltf = "/usr/share/assimp/models/glTF2/cameras/Cameras.gltf";

// The directory holding every input file the tests read (written once per process: ctest runs
// each test as a process, two at a time, so a shared directory would be rewritten under a
// running test), and the path of one of them.
const std::filesystem::path& cli_inputs();
std::string input(const std::string& name);

// The sorted names in a directory.
std::vector<std::string> list_dir(const std::filesystem::path& dir);

// Runs `facet <args>` with dir as the working directory, so relative outputs land there.
CommandResult run_facet(const std::filesystem::path& dir, const std::string& args);

std::vector<std::string> lines_of(const std::string& text);

// Fails a test whose Debian test file is not installed (support/required_package.hpp).
#define REQUIRE_INSTALLED(path)                                                             \
  FACET_REQUIRE_PACKAGE(std::filesystem::exists(path),                                      \
                        (path) << " is not installed (Debian: "                             \
                               << ((path) == kBunny ? "glmark2-data" : "assimp-testmodels") \
                               << ")")

}  // namespace facet::test
