// Internal to the glTF 2.0 reader (src/import/gltf_*.cpp): tinygltf parses the file
// (gltf_load.cpp, every file it opens held to guarded_files.hpp's rules); facet reads the data
// through bounds-checked accessors (gltf_accessors.cpp), makes meshes of the primitives
// (gltf_meshes.cpp) posed by skins and morph targets (gltf_deform.cpp) and animations
// (gltf_animation.cpp), materials and textures (gltf_materials.cpp), cameras and lights
// (gltf_objects.cpp), and the node hierarchy that places them (gltf_scene.cpp).
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "facet/scene.hpp"
#include "import/guarded_files.hpp"
#include "import/import_internal.hpp"

namespace facet::io {

// A data URI longer than this (its text, in bytes) is refused before it is decoded: a model
// that needs more should keep its buffer in a .bin file beside it.
inline constexpr std::size_t kMaxDataUriBytes = std::size_t(256) << 20;
// JSON nested deeper than this is refused before parsing (tinygltf converts extras and
// extensions recursively; glTF itself never nests more than a handful of levels).
inline constexpr int kMaxJsonDepth = 128;

// The parsed file. Each image's encoded bytes are in images[i].image, not decoded (facet decodes
// the ones materials use, gltf_materials.cpp).
struct GltfFile {
  std::string path;  // the model file, as given (messages start with it)
  tinygltf::Model model;
  // Referenced files refused or unreadable, by the URI as tinygltf asked for it (relative to
  // the model's folder): "is a named pipe, not a file", "is outside the model's folder ...".
  std::map<std::string, std::string> refused;
};

// Parses `bytes` (the whole .gltf or .glb file); external files through `rules` (null: none may
// be read, as for the fuzz target). Throws facet::Error "<path>: ..." naming what is wrong.
GltfFile parse_gltf(std::string_view bytes, const std::string& path, const ReferenceRules* rules);

// Compressed data (gltf_compressed.cpp). The file's bytes with the JSON adapted to what tinygltf
// reads of KHR_draco_mesh_compression and EXT_meshopt_compression; empty when nothing changes.
std::string gltf_json_for_tinygltf(std::string_view bytes, bool binary);
// Every EXT_meshopt_compression buffer view decoded into a buffer of its own; throws
// facet::Error for damaged data or a count the compressed size cannot hold.
void decode_meshopt_views(GltfFile& file);

// A primitive's KHR_draco_mesh_compression data decoded (gltf_draco.cpp): each glTF attribute
// name the extension lists, as floats (normalized as Draco stores them), and the triangle
// corners. Throws facet::Error "<where>: ..." for damaged data.
struct DracoPrimitive {
  std::map<std::string, std::vector<glm::vec4>> attributes;
  std::map<std::string, int> components;
  std::vector<std::uint32_t> indices;
};
class GltfAccessors;
DracoPrimitive decode_draco_primitive(const GltfAccessors& data, const tinygltf::Value& extension,
                                      const std::string& where);

// Bounds-checked reading of accessors: every offset, stride and count is checked against the
// buffer it points into before a byte is read; errors are facet::Error "<path>: accessor N:
// ...". Normalized integers become floats as glTF 2.0 §3.11 says.
class GltfAccessors {
 public:
  explicit GltfAccessors(const GltfFile& file) : file_(file) {}
  // Elements of accessor `index` as up to four floats each (missing components 0, w 1).
  // `components`: how many the accessor has.
  std::vector<glm::vec4> floats(int index, int& components) const;
  // An index accessor (unsigned byte, short or int, SCALAR), each checked < vertex_count.
  std::vector<std::uint32_t> indices(int index, std::size_t vertex_count) const;
  std::size_t count(int index) const;  // the accessor's element count (checked to exist)
  // The bytes of a buffer view, checked to lie within its buffer.
  const std::uint8_t* view_bytes(int view, std::size_t& length) const;

 private:
  const tinygltf::Accessor& accessor(int index) const;
  [[noreturn]] void fail(int accessor, const std::string& what) const;

  const GltfFile& file_;
};

// Materials, each with the texture coordinate set its maps read (Mesh has one set).
struct GltfMaterials {
  std::vector<Material> materials;                       // the file's, in its order
  std::vector<int> texcoord_set;                         // per material
  std::vector<std::shared_ptr<const Texture>> textures;  // every texture they use, once
};
GltfMaterials import_gltf_materials(const GltfFile& file, const ImportOptions& options);
// glTF 2.0 §3.9.6's material for a primitive without one: white, metallic 1, roughness 1.
Material gltf_default_material();

// How a primitive is deformed where a node draws it (gltf_deform.cpp): morph target weights
// (empty: none) and skin matrices, each joint's world transform times its inverse bind matrix
// brought into the drawing node's space (empty: not skinned).
struct MeshPose {
  std::vector<float> weights;
  std::vector<glm::mat4> joints;
};
// Applies the pose to a primitive's positions, normals and tangents as read (before normals
// are made for a mesh without): the weighted morph target deltas (POSITION, NORMAL, TANGENT),
// then linear blend skinning with JOINTS_n / WEIGHTS_n (weights normalized to sum 1; a vertex
// with none stays put). `attribute_values` reads a primitive or target attribute's accessor.
// Throws facet::Error "<where>: ..." for a target or joint index out of range.
void deform_primitive(const GltfAccessors& data, const tinygltf::Primitive& primitive,
                      const MeshPose& pose, std::vector<glm::vec3>& positions,
                      std::vector<glm::vec3>& normals, std::vector<glm::vec4>& tangents,
                      const std::string& where);

// The pose of every glTF node (gltf_animation.cpp): its local transform and the morph weights
// of its mesh, at rest or with ImportOptions::animation sampled at ImportOptions::time, and
// the world transform that follows from its ancestors (for joints, which need not be in the
// scene drawn). Throws facet::Error for an animation the file does not have, or damaged
// animation data.
struct GltfPose {
  std::vector<glm::mat4> local;
  std::vector<glm::mat4> world;
  std::vector<std::vector<float>> weights;  // empty for a node without a morphed mesh
};
GltfPose gltf_pose(const GltfFile& file, const GltfAccessors& data, const ImportOptions& options);
// The skin matrices of `skin` for a mesh drawn at `node` (MeshPose::joints).
std::vector<glm::mat4> gltf_skin_matrices(const GltfFile& file, const GltfAccessors& data,
                                          const GltfPose& pose, int skin, int node);

// One primitive of a mesh as a facet Mesh (triangles, lines or points), finished (finish_mesh),
// texture coordinates from set `texcoord_set` with v flipped to facet's v-up; `flip_winding`
// reverses each triangle (a mirrored node). Null when the primitive has nothing to draw.
std::shared_ptr<const Mesh> gltf_primitive_mesh(const GltfFile& file, const GltfAccessors& data,
                                                int mesh, int primitive, int texcoord_set,
                                                const Material& material, bool flip_winding,
                                                const MeshPose& pose, const ImportOptions& options);

// A node's local transform (matrix, or translation * rotation * scale); throws if not finite.
glm::mat4 gltf_node_transform(const tinygltf::Node& node, const std::string& where);

// The file's cameras (Scene::cameras) and KHR_lights_punctual lights (Scene::lighting,
// has_file_lights), placed by the nodes that use them: `node_of[i]` is glTF node i's
// Scene::nodes index (-1: not in the scene). Needs the scene's meshes placed (for its size).
void import_gltf_cameras_and_lights(const GltfFile& file, const std::vector<int>& node_of,
                                    const ImportOptions& options, Scene& scene);

// The whole scene from a parsed file (gltf_scene.cpp): no default camera yet. With `materials`
// (imported before from the same file) they are used again, textures shared, and the file's
// unsupported extensions are not warned about again.
Scene gltf_scene(const GltfFile& file, const ImportOptions& options,
                 const GltfMaterials* materials = nullptr);

}  // namespace facet::io
