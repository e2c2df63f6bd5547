// deform_primitive() (gltf_internal.hpp): morph targets and skins applied to a primitive's
// vertices on the CPU. Runs once per (primitive, drawing node) at import; facet's pipeline draws
// static meshes, so the posed mesh is what the scene holds.
//
// Order as glTF 2.0 §3.7.2.2 and §3.8.3 have it: a vertex is first morphed (its attribute plus
// the weighted sum of the targets' deltas), then skinned (the weighted sum of the joint
// matrices applied to the morphed vertex). Normals are skinned by the inverse transpose of the
// blended matrix and renormalized; tangents by the blended matrix, their w kept.
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <string>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

int attribute(const std::map<std::string, int>& attributes, const std::string& name) {
  auto it = attributes.find(name);
  return it == attributes.end() ? -1 : it->second;
}

// Adds weight * delta for one target attribute; the accessor must match the vertex count.
template <class Vec>
void add_deltas(const GltfAccessors& data, int accessor, float weight, std::vector<Vec>& values,
                const std::string& where) {
  if (accessor < 0 || values.empty()) return;
  int components = 0;
  const std::vector<glm::vec4> deltas = data.floats(accessor, components);
  if (deltas.size() != values.size())
    throw Error(where + ": a morph target has " + std::to_string(deltas.size()) + " elements for " +
                std::to_string(values.size()) + " vertices");
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (int c = 0; c < 3; ++c) values[i][c] += weight * deltas[i][c];  // a tangent's w stays
  }
}

void morph(const GltfAccessors& data, const tinygltf::Primitive& p, const std::vector<float>& w,
           std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
           std::vector<glm::vec4>& tangents, const std::string& where) {
  for (std::size_t t = 0; t < p.targets.size() && t < w.size(); ++t) {
    if (w[t] == 0.0f || !std::isfinite(w[t])) continue;
    const std::string target = where + ": morph target " + std::to_string(t);
    add_deltas(data, attribute(p.targets[t], "POSITION"), w[t], positions, target);
    add_deltas(data, attribute(p.targets[t], "NORMAL"), w[t], normals, target);
    add_deltas(data, attribute(p.targets[t], "TANGENT"), w[t], tangents, target);
  }
}

void skin(const GltfAccessors& data, const tinygltf::Primitive& p,
          const std::vector<glm::mat4>& joints, std::vector<glm::vec3>& positions,
          std::vector<glm::vec3>& normals, std::vector<glm::vec4>& tangents,
          const std::string& where) {
  const std::size_t n = positions.size();
  std::vector<glm::mat4> blended(n, glm::mat4(0.0f));
  std::vector<float> total(n, 0.0f);
  for (int set = 0;; ++set) {
    const int joint_accessor = attribute(p.attributes, "JOINTS_" + std::to_string(set));
    const int weight_accessor = attribute(p.attributes, "WEIGHTS_" + std::to_string(set));
    if (joint_accessor < 0 || weight_accessor < 0) break;
    int components = 0;
    const std::vector<glm::vec4> index = data.floats(joint_accessor, components);
    const std::vector<glm::vec4> weight = data.floats(weight_accessor, components);
    if (index.size() != n || weight.size() != n)
      throw Error(where + ": JOINTS_" + std::to_string(set) + " or WEIGHTS_" + std::to_string(set) +
                  " does not have one element per vertex");
    for (std::size_t v = 0; v < n; ++v) {
      for (int c = 0; c < 4; ++c) {
        const float w = weight[v][c];
        if (!(w > 0.0f) || !std::isfinite(w)) continue;  // an unused slot may name any joint
        const float j = index[v][c];
        if (!(j >= 0.0f && j < static_cast<float>(joints.size())))
          throw Error(where + ": vertex " + std::to_string(v) + " names joint " +
                      std::to_string(static_cast<long long>(j)) + ", but the skin has " +
                      std::to_string(joints.size()));
        blended[v] += w * joints[static_cast<std::size_t>(j)];
        total[v] += w;
      }
    }
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (!(total[v] > 0.0f)) continue;  // no weights: the vertex stays where the node puts it
    // Quantized weights need not sum to exactly 1 (glTF 2.0 §3.7.3.3): normalized here.
    const glm::mat4 m = blended[v] / total[v];
    positions[v] = glm::vec3(m * glm::vec4(positions[v], 1.0f));
    if (!normals.empty()) {
      const glm::vec3 normal = glm::transpose(glm::inverse(glm::mat3(m))) * normals[v];
      const float length = glm::length(normal);
      if (length > 0.0f && std::isfinite(length)) normals[v] = normal / length;
    }
    if (!tangents.empty())
      tangents[v] = glm::vec4(glm::mat3(m) * glm::vec3(tangents[v]), tangents[v].w);
  }
}

}  // namespace

void deform_primitive(const GltfAccessors& data, const tinygltf::Primitive& p, const MeshPose& pose,
                      std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                      std::vector<glm::vec4>& tangents, const std::string& where) {
  if (!pose.weights.empty() && !p.targets.empty())
    morph(data, p, pose.weights, positions, normals, tangents, where);
  if (!pose.joints.empty()) skin(data, p, pose.joints, positions, normals, tangents, where);
  // Morphed normals and tangents are no longer unit length.
  for (glm::vec3& normal : normals) {
    const float length = glm::length(normal);
    if (length > 0.0f && std::isfinite(length)) normal /= length;
  }
}

}  // namespace facet::io
