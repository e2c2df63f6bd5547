// facet::AnimatedModel (facet/import.hpp): a glTF file parsed and its materials imported once,
// then posed by gltf_scene for each time asked.
#include <algorithm>
#include <filesystem>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "import/gltf_internal.hpp"

namespace facet {

struct AnimatedModel::Impl {
  io::GltfFile file;
  io::GltfMaterials materials;
  ImportOptions options;
  double duration = 0.0;
};

AnimatedModel::AnimatedModel(const std::string& path, const ImportOptions& options)
    : impl_(std::make_unique<Impl>()) {
  io::check_model_file(path);
  const std::string extension = io::lower_case(std::filesystem::path(path).extension().string());
  if (extension != ".gltf" && extension != ".glb") {
    throw Error(path + ": only glTF models (.gltf, .glb) are animated");
  }
  io::precheck_model(path);
  const io::ReferenceRules rules(path, options);
  impl_->file = io::parse_gltf(io::read_whole_file(path), path, &rules);
  impl_->options = options;
  const auto& animations = impl_->file.model.animations;
  try {
    impl_->materials = io::import_gltf_materials(impl_->file, options);
    // An animation the file does not have fails the first pose, below, as it fails an import.
    if (options.animation >= 0 && static_cast<std::size_t>(options.animation) < animations.size()) {
      const io::GltfAccessors data(impl_->file);
      for (const tinygltf::AnimationSampler& sampler :
           animations[static_cast<std::size_t>(options.animation)].samplers) {
        int components = 0;
        for (const glm::vec4& key : data.floats(sampler.input, components)) {
          impl_->duration = std::max(impl_->duration, static_cast<double>(key.x));
        }
      }
    }
    pose(0.0);  // a file that cannot be posed fails here, not at the first pose asked for
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {  // bad_alloc on absurd sizes, and the like
    throw Error(path + ": cannot import: " + e.what());
  }
}

AnimatedModel::~AnimatedModel() = default;
AnimatedModel::AnimatedModel(AnimatedModel&&) noexcept = default;
AnimatedModel& AnimatedModel::operator=(AnimatedModel&&) noexcept = default;

int AnimatedModel::animation_count() const {
  return static_cast<int>(impl_->file.model.animations.size());
}

double AnimatedModel::duration() const { return impl_->duration; }

Scene AnimatedModel::pose(double seconds) const {
  ImportOptions options = impl_->options;
  options.time = seconds;
  return io::gltf_scene(impl_->file, options, &impl_->materials);
}

}  // namespace facet
