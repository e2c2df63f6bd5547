// The assimp-testmodels listing (see sample_models.hpp).
#include "support/sample_models.hpp"

#include <algorithm>
#include <cctype>

namespace facet::test {

namespace fs = std::filesystem;

bool is_robustness_sample(const std::string& relative) {
  for (const char* part :
       {"invalid/", "IndexOutOfRange/", "BoxWithInfinites", "MissingBin/", "wrongTypes/"}) {
    if (relative.find(part) != std::string::npos) return true;
  }
  return false;
}

bool is_model_file(const fs::path& p) {
  std::string extension = p.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
  for (const char* known : {".obj", ".gltf", ".glb", ".ply", ".stl", ".3ds", ".off"}) {
    if (extension == known) return true;
  }
  // Extension-less copies that test assimp's detection by content.
  return p.filename().string().find("ormatDetection") != std::string::npos;
}

bool under_invalid_directory(const fs::path& relative) {
  for (const fs::path& part : relative.parent_path()) {
    if (part.string().find("invalid") != std::string::npos) return true;
  }
  return false;
}

std::vector<fs::path> model_files(const std::string& directory) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(kSampleModels / directory)) {
    if (entry.is_regular_file() && is_model_file(entry.path())) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<fs::path> wellformed_model_files(const std::string& directory) {
  std::vector<fs::path> files;
  for (const fs::path& file : model_files(directory)) {
    const fs::path relative = fs::relative(file, kSampleModels);
    if (!under_invalid_directory(relative) && !is_robustness_sample(relative.string()))
      files.push_back(file);
  }
  return files;
}

FrameStats render_small(const Scene& scene) {
  constexpr int kWidth = 96, kHeight = 64;
  Renderer renderer;
  Framebuffer target(kWidth, kHeight);
  renderer.begin_frame(scene_camera(scene, static_cast<float>(kWidth) / kHeight), scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(target);
  return renderer.stats();
}

}  // namespace facet::test
