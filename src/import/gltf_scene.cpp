// The glTF 2.0 reader's entry (import_gltf_scene, import_internal.hpp) and the node hierarchy it
// builds (gltf_scene). Runs once per model at load time; the renderer only ever sees the Scene.
//
// The scene drawn is the file's `scene`, else its first; a file without scenes draws every
// root node. Nodes keep their hierarchy (SceneNode::parent); a node reached twice (two parents,
// or a cycle) makes the file invalid. A node whose world transform mirrors (determinant < 0)
// draws its meshes with the winding reversed (gltf_primitive_mesh), so that the faces glTF
// calls front stay front. EXT_mesh_gpu_instancing's instances become child nodes, one per
// instance, each drawing the node's meshes. Node transforms, skins and morph weights are those
// of the pose (gltf_animation.cpp: at rest, or an animation sampled at ImportOptions::time);
// skinned and morphed meshes are posed per drawing node (gltf_deform.cpp).
#include <algorithm>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>
#include <map>
#include <string>
#include <tuple>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

// Extensions this reader understands; a file that requires another is warned about.
const std::set<std::string> kSupported = {
    "KHR_mesh_quantization",
    "KHR_texture_transform",
    "KHR_materials_unlit",
    "KHR_materials_pbrSpecularGlossiness",
    "KHR_materials_emissive_strength",
    "KHR_materials_transmission",
    "KHR_materials_clearcoat",
    "KHR_draco_mesh_compression",
    "EXT_meshopt_compression",
    "KHR_lights_punctual",
    "EXT_mesh_gpu_instancing",
    "KHR_materials_sheen",
    "KHR_materials_specular",
    "KHR_materials_ior",
};

class SceneBuilder {
 public:
  SceneBuilder(const GltfFile& file, const ImportOptions& options)
      : file_(file), model_(file.model), options_(options), data_(file) {}

  Scene build(const GltfMaterials* imported) {
    GltfMaterials materials = imported ? *imported : import_gltf_materials(file_, options_);
    scene_.materials = std::move(materials.materials);
    scene_.textures = std::move(materials.textures);
    texcoord_set_ = std::move(materials.texcoord_set);
    file_materials_ = scene_.materials.size();
    pose_ = gltf_pose(file_, data_, options_);
    node_of_.assign(model_.nodes.size(), -1);
    for (int root : roots()) add_tree(root);
    // A valid file may still draw nothing (a scene of cameras, meshes no node places, quantized
    // data a reader did not scale): say so rather than leave an empty image.
    const bool drawn = std::any_of(scene_.nodes.begin(), scene_.nodes.end(),
                                   [](const SceneNode& n) { return !n.instances.empty(); });
    if (!drawn)
      throw Error(file_.path + ": nothing to draw: the scene places no mesh with positions (" +
                  std::to_string(model_.nodes.size()) + " nodes and " +
                  std::to_string(model_.meshes.size()) + " meshes in the file)");
    import_gltf_cameras_and_lights(file_, node_of_, options_, scene_);
    return std::move(scene_);
  }

 private:
  std::vector<int> roots() const {
    if (!model_.scenes.empty()) {
      const int chosen = model_.defaultScene >= 0 && static_cast<std::size_t>(model_.defaultScene) <
                                                         model_.scenes.size()
                             ? model_.defaultScene
                             : 0;
      return model_.scenes[static_cast<std::size_t>(chosen)].nodes;
    }
    std::vector<bool> child(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes) {
      for (int c : node.children) {
        if (c >= 0 && static_cast<std::size_t>(c) < child.size())
          child[static_cast<std::size_t>(c)] = true;
      }
    }
    std::vector<int> out;
    for (std::size_t i = 0; i < child.size(); ++i) {
      if (!child[i]) out.push_back(static_cast<int>(i));
    }
    return out;
  }

  std::string where(int node) const { return file_.path + ": node " + std::to_string(node); }

  // Depth first, parents before children (SceneNode::parent must come first), with a stack
  // rather than recursion so that a deep hierarchy cannot overflow the call stack.
  void add_tree(int root) {
    struct Pending {
      int node;
      int parent;
      glm::mat4 parent_world;
    };
    std::vector<Pending> stack{{root, -1, glm::mat4(1.0f)}};
    while (!stack.empty()) {
      const Pending next = stack.back();
      stack.pop_back();
      if (next.node < 0 || static_cast<std::size_t>(next.node) >= model_.nodes.size())
        throw Error(file_.path + ": node " + std::to_string(next.node) + " does not exist");
      if (node_of_[static_cast<std::size_t>(next.node)] >= 0)
        throw Error(where(next.node) +
                    " is reached twice: a node has one parent and is not its own ancestor");
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(next.node)];
      SceneNode out;
      out.name = node.name;
      out.transform = pose_.local[static_cast<std::size_t>(next.node)];
      out.parent = next.parent;
      const glm::mat4 world = next.parent_world * out.transform;
      const int index = static_cast<int>(scene_.nodes.size());
      node_of_[static_cast<std::size_t>(next.node)] = index;
      scene_.nodes.push_back(std::move(out));
      if (node.mesh >= 0) place_mesh(next.node, node, index, world);
      for (std::size_t c = node.children.size(); c-- > 0;)
        stack.push_back({node.children[c], index, world});
    }
  }

  void place_mesh(int gltf_node, const tinygltf::Node& node, int index, const glm::mat4& world) {
    if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
      throw Error(where(gltf_node) + ": mesh " + std::to_string(node.mesh) + " does not exist");
    auto instancing = node.extensions.find("EXT_mesh_gpu_instancing");
    if (instancing == node.extensions.end()) {
      scene_.nodes[static_cast<std::size_t>(index)].instances = instances(gltf_node, world);
      return;
    }
    const std::vector<glm::mat4> copies = instance_transforms(instancing->second, gltf_node);
    for (std::size_t i = 0; i < copies.size(); ++i) {
      SceneNode copy;
      copy.name = node.name + " instance " + std::to_string(i);
      copy.transform = copies[i];
      copy.parent = index;
      copy.instances = instances(gltf_node, world * copies[i]);
      scene_.nodes.push_back(std::move(copy));
    }
  }

  // EXT_mesh_gpu_instancing: TRANSLATION, ROTATION (unit quaternions) and SCALE accessors, each
  // optional, all of one count.
  std::vector<glm::mat4> instance_transforms(const tinygltf::Value& extension, int gltf_node) {
    const tinygltf::Value& attributes = extension.Get("attributes");
    std::vector<glm::vec4> values[3];
    const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
    std::size_t count = 0;
    bool any = false;
    for (int a = 0; a < 3; ++a) {
      const tinygltf::Value& accessor = attributes.Get(names[a]);
      if (!accessor.IsInt()) continue;
      int components = 0;
      values[a] = data_.floats(accessor.GetNumberAsInt(), components);
      if (any && values[a].size() != count)
        throw Error(where(gltf_node) + ": EXT_mesh_gpu_instancing's attributes differ in count");
      count = values[a].size();
      any = true;
    }
    std::vector<glm::mat4> out(count);
    for (std::size_t i = 0; i < count; ++i) {
      tinygltf::Node trs;
      if (!values[0].empty()) trs.translation = {values[0][i].x, values[0][i].y, values[0][i].z};
      if (!values[1].empty())
        trs.rotation = {values[1][i].x, values[1][i].y, values[1][i].z, values[1][i].w};
      if (!values[2].empty()) trs.scale = {values[2][i].x, values[2][i].y, values[2][i].z};
      out[i] = gltf_node_transform(trs, where(gltf_node) + ": instance " + std::to_string(i));
    }
    return out;
  }

  // The node's mesh's primitives, each a facet mesh in its material, mirrored or not as `world`
  // is, posed by the node's skin and morph weights.
  std::vector<MeshInstance> instances(int gltf_node, const glm::mat4& world) {
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(gltf_node)];
    const int mesh = node.mesh;
    MeshPose pose;
    pose.weights = pose_.weights[static_cast<std::size_t>(gltf_node)];
    if (node.skin >= 0) pose.joints = gltf_skin_matrices(file_, data_, pose_, node.skin, gltf_node);
    // A posed mesh is the drawing node's own; an unposed one is shared by every node drawing it.
    const int posed_by = pose.weights.empty() && pose.joints.empty() ? -1 : gltf_node;
    // A skinned mesh is placed by its joints: whether it mirrors is theirs to say (the first
    // joint's, brought into the node's space, stands for all).
    const glm::mat4 placing = pose.joints.empty() ? world : world * pose.joints.front();
    const bool mirrored = glm::determinant(glm::mat3(placing)) < 0.0f;
    std::vector<MeshInstance> out;
    const auto& primitives = model_.meshes[static_cast<std::size_t>(mesh)].primitives;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const int m = primitives[p].material;
      const int material = m >= 0 && m < static_cast<int>(file_materials_) ? m : default_material();
      auto [it, added] = meshes_.try_emplace({mesh, static_cast<int>(p), mirrored, posed_by}, -1);
      if (added) {
        auto made = gltf_primitive_mesh(file_, data_, mesh, static_cast<int>(p),
                                        texcoord_set_[static_cast<std::size_t>(material)],
                                        scene_.materials[static_cast<std::size_t>(material)],
                                        mirrored, pose, options_);
        if (made) {
          scene_.meshes.push_back(std::move(made));
          it->second = static_cast<int>(scene_.meshes.size()) - 1;
        }
      }
      if (it->second >= 0) out.push_back({it->second, material});
    }
    return out;
  }

  const GltfFile& file_;
  const tinygltf::Model& model_;
  const ImportOptions& options_;
  GltfAccessors data_;
  Scene scene_;
  // The glTF default material, added after the file's when a primitive first needs it.
  int default_material() {
    if (default_material_ < 0) {
      scene_.materials.push_back(gltf_default_material());
      texcoord_set_.push_back(0);
      default_material_ = static_cast<int>(scene_.materials.size()) - 1;
    }
    return default_material_;
  }

  std::vector<int> texcoord_set_;
  std::size_t file_materials_ = 0;
  int default_material_ = -1;
  std::vector<int> node_of_;  // glTF node -> Scene::nodes, -1 until placed
  GltfPose pose_;
  // (mesh, primitive, mirrored, posing node or -1) -> Scene::meshes index
  std::map<std::tuple<int, int, bool, int>, int> meshes_;
};

void warn_unsupported(const GltfFile& file, const ImportOptions& options) {
  std::string missing;
  for (const std::string& name : file.model.extensionsRequired) {
    if (kSupported.count(name) == 0) missing += (missing.empty() ? "" : ", ") + name;
  }
  if (!missing.empty())
    warn(options, file.path + ": requires " + missing +
                      ", which facet does not read; drawing what it can without");
}

}  // namespace

Scene gltf_scene(const GltfFile& file, const ImportOptions& options,
                 const GltfMaterials* materials) {
  if (!materials) warn_unsupported(file, options);
  return SceneBuilder(file, options).build(materials);
}

Scene import_gltf_scene(const std::string& path, const ImportOptions& options) {
  precheck_model(path);  // a GLB's claimed sizes, before the file is read
  const ReferenceRules rules(path, options);
  const std::string bytes = read_whole_file(path);
  const GltfFile file = parse_gltf(bytes, path, &rules);
  try {
    return gltf_scene(file, options);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {  // bad_alloc on absurd sizes, and the like
    throw Error(path + ": cannot import: " + e.what());
  }
}

}  // namespace facet::io
