// The sample models Debian ships in assimp-testmodels (/usr/share/assimp/models), listed as the
// import and framing tests walk them: model files by extension, and the broken-on-purpose ones.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "facet/renderer.hpp"
#include "facet/scene.hpp"

namespace facet::test {

inline const std::filesystem::path kSampleModels = "/usr/share/assimp/models";

// Broken on purpose: any facet::Error or a clean render is fine, a crash is not. Matched
// against the path relative to kSampleModels.
bool is_robustness_sample(const std::string& relative);

// A file of a format facet imports (by extension, or an extension-less format-detection copy).
bool is_model_file(const std::filesystem::path& path);

// A path (relative to kSampleModels) inside a folder named for invalid files.
bool under_invalid_directory(const std::filesystem::path& relative);

// Every model file under kSampleModels / directory, sorted.
std::vector<std::filesystem::path> model_files(const std::string& directory);

// model_files without the broken-on-purpose ones (under_invalid_directory,
// is_robustness_sample): the files that must import or fail with an expected error.
std::vector<std::filesystem::path> wellformed_model_files(const std::string& directory);

// Renders an imported scene small (96x64) with its automatic camera and its lights (the file's,
// or the three-point lights import gives a file without any): what the import sweeps draw.
FrameStats render_small(const Scene& scene);

}  // namespace facet::test
