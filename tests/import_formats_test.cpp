// Every file of Debian's assimp-testmodels in the folders import_test.cpp does not sweep (FBX,
// COLLADA, X, MD2, MD5, BLEND, ASE, IFC, LWO, MS3D, ... and the folders of textures, sources and
// reference images): it imports and renders, or import_scene throws one facet::Error of one
// line naming the file. Never a crash, a hang or another exception type. One test per folder,
// so that ctest spreads them over its jobs; the whole sweep takes a few seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";  // Debian package assimp-testmodels

// The folders of kModels, but for OBJ, glTF2, PLY, STL, 3DS and OFF (ImportModels in
// import_test.cpp, with their expected failures) and invalid (ImportModels.BrokenFilesFailCleanly).
const char* const kFolders[] = {
    "3D",           "3MF",
    "AC",           "AMF",
    "ASE",          "B3D",
    "BLEND",        "BVH",
    "COB",          "CSM",
    "Collada",      "DXF",
    "FBX",          "HMP",
    "IFC",          "IQM",
    "IRR",          "IRRMesh",
    "JT",           "LWO",
    "LWS",          "M3D",
    "MD2",          "MD5",
    "MDC",          "MDL",
    "MS3D",         "NFF",
    "Ogre",         "OpenGEX",
    "ParsingFiles", "Q3D",
    "RAW",          "ReferenceImages",
    "SIB",          "SMD",
    "SourceFiles",  "TER",
    "WRL",          "X",
    "X3D",          "XGL",
    "glTF",
};

class ImportEveryFormat : public ::testing::TestWithParam<const char*> {};

TEST_P(ImportEveryFormat, ImportsOrFailsInOneLine) {
  const fs::path folder = kModels / GetParam();
  FACET_REQUIRE_PACKAGE(fs::is_directory(folder), folder << " is missing (assimp-testmodels)");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ImportOptions quiet;
  quiet.warn = [](const std::string&) {};
  int rendered = 0;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    try {
      render_small(import_scene(file.string(), quiet));
      ++rendered;
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u)
          << "does not name the file: " << message;
    }
  }
  EXPECT_FALSE(files.empty());
  RecordProperty("rendered", rendered);
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, ImportEveryFormat, ::testing::ValuesIn(kFolders),
                         [](const ::testing::TestParamInfo<const char*>& folder) {
                           return std::string(folder.param);
                         });

}  // namespace
}  // namespace facet::test
