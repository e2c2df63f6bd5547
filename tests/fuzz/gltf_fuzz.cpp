// libFuzzer target for facet's glTF 2.0 reader: tinygltf's parser as facet drives it
// (src/import/gltf_load.cpp, gltf_compressed.cpp), the bounds-checked accessors, Draco and
// meshopt decoding, and every primitive made into a mesh (gltf_meshes.cpp, mesh_finish.cpp).
// Any input, .gltf text or .glb bytes, must either give meshes that pass Mesh::validate() or
// throw facet::Error. A crash, a hang or a sanitizer report is a bug. No external file is read
// (parse_gltf without reference rules). Run with `make test-fuzz` (corpus: corpus/gltf/).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const facet::io::GltfFile file = facet::io::parse_gltf(bytes, "fuzz.glb", nullptr);
    const facet::io::GltfAccessors accessors(file);
    const facet::Material material;
    const facet::ImportOptions options;
    for (std::size_t m = 0; m < file.model.meshes.size(); ++m) {
      // The mesh's default morph weights, so that its targets are read too (no skin: joints
      // come from the node hierarchy, which this target does not build).
      facet::io::MeshPose pose;
      for (double weight : file.model.meshes[m].weights)
        pose.weights.push_back(static_cast<float>(weight));
      for (std::size_t p = 0; p < file.model.meshes[m].primitives.size(); ++p) {
        for (bool mirrored : {false, true}) {
          try {
            auto mesh = facet::io::gltf_primitive_mesh(file, accessors, static_cast<int>(m),
                                                       static_cast<int>(p), 0, material, mirrored,
                                                       pose, options);
            if (mesh) mesh->validate();
          } catch (const facet::Error&) {
            // One damaged primitive: the next may still be read.
          }
        }
      }
    }
  } catch (const facet::Error&) {
    // Malformed input: the expected outcome for most fuzz inputs.
  }
  return 0;
}
