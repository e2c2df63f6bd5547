// Test helper: glTF 2.0 files made by the tests themselves, so that each glTF feature is tested
// on a model made for it. Data goes into one binary buffer; the JSON is nlohmann::json that a
// test fills in (meshes, nodes, materials, extensions); the file is written as .gltf (buffer in
// a base64 data URI) or .glb (buffer in the BIN chunk). Also the few helpers the glTF tests
// share (gltf_import_test.cpp, gltf_geometry_test.cpp, gltf_materials_test.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "facet/import.hpp"

namespace facet::test {

// glTF component types (the OpenGL enums).
inline constexpr int kGlByte = 5120, kGlUnsignedByte = 5121, kGlShort = 5122,
                     kGlUnsignedShort = 5123, kGlUnsignedInt = 5125, kGlFloat = 5126;

class GltfBuilder {
 public:
  GltfBuilder();

  // Bytes appended to the buffer (4-byte aligned) as a new buffer view; returns its index.
  int view(const void* data, std::size_t size, int stride = 0);
  // An accessor of `count` elements of `type` ("SCALAR", "VEC2", ...) on a view.
  int accessor(int view, int component_type, std::size_t count, const std::string& type,
               bool normalized = false);
  // Float accessors (positions get the min and max glTF requires).
  int positions(const std::vector<glm::vec3>& values);
  int vec2s(const std::vector<glm::vec2>& values);
  int vec3s(const std::vector<glm::vec3>& values);
  int vec4s(const std::vector<glm::vec4>& values);
  int indices(const std::vector<std::uint16_t>& values);
  int scalars(const std::vector<float>& values);
  int mat4s(const std::vector<glm::mat4>& values);  // column-major, as glTF stores them

  // A channel of animation `animation` (created as needed) moving `path` ("translation",
  // "rotation", "scale", "weights") of `node`: keys at `times`, `values` flat (3 or 4 numbers a
  // key, or one per morph target; three times as many for CUBICSPLINE: in-tangent, value,
  // out-tangent per key), `interpolation` "LINEAR", "STEP" or "CUBICSPLINE".
  void animate(int node, const std::string& path, const std::vector<float>& times,
               const std::vector<float>& values, const std::string& interpolation = "LINEAR",
               int animation = 0);

  // A mesh of one primitive ({"attributes": ..., "indices": ..., "material": ..., "mode": ...}
  // as given) and a root node drawing it; returns the node's index.
  int add_mesh_node(const nlohmann::json& primitive, const nlohmann::json& node_fields = {});

  std::string gltf_text() const;
  std::string glb_bytes() const;
  std::filesystem::path write_gltf(const std::filesystem::path& path) const;
  std::filesystem::path write_glb(const std::filesystem::path& path) const;

  // The document. Buffer 0 (`buffer`) is filled in when written; a test may add more buffers
  // after it in json["buffers"] (put a null first).
  nlohmann::json json;
  std::vector<std::uint8_t> buffer;
};

// The unit quad [0, 1] x [0, 1] at z = 0 facing +Z, as two counter-clockwise triangles with
// normals and texture coordinates (glTF's: v = 0 at the top), in builder `b`: its primitive.
nlohmann::json unit_quad(GltfBuilder& b);

// A bar 0.2 wide from y = 0 to y = 2 (rows of two vertices at y = 0, 1, 2), skinned to two
// joints: joint 0 at the bar's foot, joint 1 at y = 1 (its child). The bottom row follows
// joint 0, the top row joint 1, the middle row both (weights as normalized unsigned bytes 128
// and 127, joints as unsigned bytes). Animation 0 turns joint 1 by 90 degrees about +Z from
// t = 0 to t = 1.
//
// The skeleton hangs under a node translated by (10, 0, 0) that is not the skin's (nor the
// mesh's) root: the bind space is the skeleton's own, so the inverse bind matrices are the
// identity and translate(0, -1, 0), and the joints' parent moves the whole bar to x = 10
// (RecursiveSkeletons-like). The mesh node itself is translated by (0, 0, 5), which a skinned
// mesh ignores (glTF 2.0 §3.7.3.1). Returns the mesh node's index.
int add_skinned_bar(GltfBuilder& b);

// What a glTF test imports: the scene and the warnings the import gave.
struct ImportedGltf {
  Scene scene;
  std::vector<std::string> warnings;
};
ImportedGltf import_gltf(const std::filesystem::path& path, bool allow_outside = false);
// The same with options of the test's own (their warn is replaced).
ImportedGltf import_gltf(const std::filesystem::path& path, ImportOptions options);

// A fresh directory for one glTF test's files.
std::filesystem::path gltf_test_dir(const std::string& name);

// A 2x2 binary PPM (stb_image reads it; readers decode by content, not by mimeType): red,
// green / blue, white; and that image embedded in `b` as a new texture (its index returned).
std::string ppm_2x2();
int add_embedded_image(GltfBuilder& b);

// The material and the mesh of the first node that draws one (material_of: or of node `node`).
const Material& material_of(const Scene& scene, int node = -1);
const Mesh& mesh_of(const Scene& scene);

}  // namespace facet::test
