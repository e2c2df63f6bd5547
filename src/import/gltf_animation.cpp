// gltf_pose() and gltf_skin_matrices() (gltf_internal.hpp): the pose a glTF scene is drawn in.
// Runs once per import, before the node hierarchy is built (gltf_scene.cpp).
//
// Animation sampling follows glTF 2.0 §3.11 and Appendix C: each channel's sampler has key
// times (input) and values (output). Before the first key the first value holds, after the
// last the last (clamped, not looped). Between keys k and k+1, u = (t - t_k) / (t_k+1 - t_k):
//   STEP         v_k
//   LINEAR       v_k + u (v_k+1 - v_k); rotations by spherical interpolation (shortest arc)
//   CUBICSPLINE  the Hermite spline p(u) = (2u³ - 3u² + 1) v_k + (u³ - 2u² + u) Δt b_k
//                + (-2u³ + 3u²) v_k+1 + (u³ - u²) Δt a_k+1, from each key's (in-tangent a,
//                value v, out-tangent b) triplet; a rotation is normalized afterwards.
// A node given as a matrix is not animated (glTF forbids animating it); a weights channel sets
// the node's morph weights, overriding the node's and the mesh's defaults.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>
#include <string>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

// One sampler's keys: times, and `width` numbers per value (3 translation or scale, 4 rotation,
// the target count for weights); cubic splines store (in-tangent, value, out-tangent) per key.
struct Track {
  std::vector<float> times;
  std::vector<float> values;
  std::size_t width = 0;
  bool cubic = false;
  bool step = false;

  // Part 0 in-tangent, 1 value, 2 out-tangent (only the value without cubic splines).
  const float* at(std::size_t key, int part) const {
    const std::size_t parts = cubic ? 3 : 1;
    return values.data() + (key * parts + (cubic ? part : 0)) * width;
  }
};

std::vector<float> sample(const Track& track, double time, bool rotation) {
  const std::size_t keys = track.times.size();
  const std::size_t w = track.width;
  std::vector<float> out(w);
  const float t = static_cast<float>(time);
  if (keys == 1 || t <= track.times.front() || t >= track.times.back()) {
    const float* v = track.at(t <= track.times.front() ? 0 : keys - 1, 1);
    std::copy(v, v + w, out.begin());
    return out;
  }
  // The last key at or before t (times are increasing, glTF 2.0 §3.11: upper_bound finds the
  // first after).
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(track.times.begin(), track.times.end(), t) -
                               track.times.begin()) -
      1;
  const float dt = track.times[k + 1] - track.times[k];
  const float u = dt > 0.0f ? (t - track.times[k]) / dt : 0.0f;
  const float* a = track.at(k, 1);
  const float* b = track.at(k + 1, 1);
  if (track.step) {
    std::copy(a, a + w, out.begin());
  } else if (track.cubic) {
    const float* out_tangent = track.at(k, 2);
    const float* in_tangent = track.at(k + 1, 0);
    const float u2 = u * u, u3 = u2 * u;
    for (std::size_t i = 0; i < w; ++i)
      out[i] = (2 * u3 - 3 * u2 + 1) * a[i] + (u3 - 2 * u2 + u) * dt * out_tangent[i] +
               (-2 * u3 + 3 * u2) * b[i] + (u3 - u2) * dt * in_tangent[i];
  } else if (rotation) {
    const glm::quat qa(a[3], a[0], a[1], a[2]), qb(b[3], b[0], b[1], b[2]);
    const glm::quat q = glm::slerp(qa, glm::dot(qa, qb) < 0.0f ? -qb : qb, u);
    out = {q.x, q.y, q.z, q.w};
  } else {
    for (std::size_t i = 0; i < w; ++i) out[i] = a[i] + u * (b[i] - a[i]);
  }
  return out;
}

class Poser {
 public:
  Poser(const GltfFile& file, const GltfAccessors& data, const ImportOptions& options)
      : file_(file), model_(file.model), data_(data), options_(options) {}

  GltfPose pose() {
    const std::size_t n = model_.nodes.size();
    trs_.assign(model_.nodes.begin(), model_.nodes.end());
    pose_.weights.resize(n);
    for (std::size_t i = 0; i < n; ++i) pose_.weights[i] = default_weights(model_.nodes[i]);
    if (options_.time) animate(*options_.time);
    pose_.local.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      pose_.local[i] = gltf_node_transform(trs_[i], where(static_cast<int>(i)));
    place();
    return std::move(pose_);
  }

 private:
  std::string where(int node) const { return file_.path + ": node " + std::to_string(node); }

  // The node's weights, else its mesh's, else zeros; one per morph target of the mesh.
  std::vector<float> default_weights(const tinygltf::Node& node) const {
    if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model_.meshes.size()) return {};
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
    std::size_t targets = 0;
    for (const tinygltf::Primitive& p : mesh.primitives)
      targets = std::max(targets, p.targets.size());
    if (targets == 0) return {};
    const std::vector<double>& given = !node.weights.empty() ? node.weights : mesh.weights;
    std::vector<float> out(targets, 0.0f);
    for (std::size_t t = 0; t < targets && t < given.size(); ++t)
      out[t] = std::isfinite(given[t]) ? static_cast<float>(given[t]) : 0.0f;
    return out;
  }

  void animate(double time) {
    if (!std::isfinite(time)) throw Error(file_.path + ": the animation time is not finite");
    const int count = static_cast<int>(model_.animations.size());
    const int chosen = options_.animation;
    if (count == 0 && chosen == 0) return;  // nothing moves: the rest pose
    if (chosen < 0 || chosen >= count)
      throw Error(file_.path + ": animation " + std::to_string(chosen) + " does not exist; " +
                  (count == 0 ? std::string("the file has no animations")
                              : "the file has " + std::to_string(count) + " (0 to " +
                                    std::to_string(count - 1) + ")"));
    const tinygltf::Animation& animation = model_.animations[static_cast<std::size_t>(chosen)];
    for (std::size_t c = 0; c < animation.channels.size(); ++c)
      apply(animation, animation.channels[c], time,
            file_.path + ": animation " + std::to_string(chosen) + " channel " + std::to_string(c));
  }

  void apply(const tinygltf::Animation& animation, const tinygltf::AnimationChannel& channel,
             double time, const std::string& where) {
    const int node = channel.target_node;
    if (node < 0 || static_cast<std::size_t>(node) >= model_.nodes.size())
      return;  // §5.6: optional
    if (channel.sampler < 0 ||
        static_cast<std::size_t>(channel.sampler) >= animation.samplers.size())
      throw Error(where + ": sampler " + std::to_string(channel.sampler) + " does not exist");
    const tinygltf::AnimationSampler& s =
        animation.samplers[static_cast<std::size_t>(channel.sampler)];
    const std::string& path = channel.target_path;
    tinygltf::Node& out = trs_[static_cast<std::size_t>(node)];
    std::vector<float>& weights = pose_.weights[static_cast<std::size_t>(node)];
    std::size_t width = 0;
    if (path == "translation" || path == "scale") width = 3;
    if (path == "rotation") width = 4;
    if (path == "weights") width = weights.size();
    if (width == 0 || out.matrix.size() == 16) return;  // nothing it can move
    const Track track = read_track(s, width, path == "weights", where);
    const std::vector<float> v = sample(track, time, path == "rotation");
    if (path == "weights") {
      weights = v;
    } else {
      std::vector<double>& target = path == "translation" ? out.translation
                                    : path == "rotation"  ? out.rotation
                                                          : out.scale;
      target.assign(v.begin(), v.end());
    }
  }

  Track read_track(const tinygltf::AnimationSampler& s, std::size_t width, bool weights,
                   const std::string& where) const {
    Track track;
    track.width = width;
    track.cubic = s.interpolation == "CUBICSPLINE";
    track.step = s.interpolation == "STEP";
    int components = 0;
    for (const glm::vec4& t : data_.floats(s.input, components)) track.times.push_back(t.x);
    if (track.times.empty()) throw Error(where + ": the sampler has no keys");
    for (std::size_t k = 0; k < track.times.size(); ++k) {
      if (!std::isfinite(track.times[k]) || (k > 0 && track.times[k] < track.times[k - 1]))
        throw Error(where + ": key times must be finite and increasing (key " + std::to_string(k) +
                    ")");
    }
    const std::vector<glm::vec4> output = data_.floats(s.output, components);
    // Weights are scalars, `width` of them per key (whatever their number, 3 and 4 too); the
    // other paths one vector per key.
    const std::size_t per_element = weights ? 1 : width;
    const std::size_t needed = track.times.size() * (track.cubic ? 3 : 1) * width / per_element;
    if (output.size() < needed || static_cast<std::size_t>(components) < per_element)
      throw Error(where + ": " + std::to_string(output.size()) + " output values for " +
                  std::to_string(track.times.size()) + " keys");
    track.values.reserve(needed * per_element);
    for (std::size_t i = 0; i < needed; ++i) {
      for (std::size_t c = 0; c < per_element; ++c) track.values.push_back(output[i][int(c)]);
    }
    return track;
  }

  // World transforms from the parents' (iteratively: hierarchies may be deep); a node in a
  // cycle keeps its local transform (the scene builder refuses such a file if it draws it).
  void place() {
    const std::size_t n = model_.nodes.size();
    std::vector<int> parent(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
      for (int c : model_.nodes[i].children) {
        if (c >= 0 && static_cast<std::size_t>(c) < n && parent[static_cast<std::size_t>(c)] < 0)
          parent[static_cast<std::size_t>(c)] = static_cast<int>(i);
      }
    }
    pose_.world = pose_.local;
    std::vector<bool> done(n, false);
    std::vector<int> stack;
    for (std::size_t i = 0; i < n; ++i) {
      if (parent[i] >= 0) continue;
      done[i] = true;
      stack.push_back(static_cast<int>(i));
      while (!stack.empty()) {
        const auto node = static_cast<std::size_t>(stack.back());
        stack.pop_back();
        for (int c : model_.nodes[node].children) {
          if (c < 0 || static_cast<std::size_t>(c) >= n || done[static_cast<std::size_t>(c)])
            continue;
          done[static_cast<std::size_t>(c)] = true;
          pose_.world[static_cast<std::size_t>(c)] =
              pose_.world[node] * pose_.local[static_cast<std::size_t>(c)];
          stack.push_back(c);
        }
      }
    }
  }

  const GltfFile& file_;
  const tinygltf::Model& model_;
  const GltfAccessors& data_;
  const ImportOptions& options_;
  std::vector<tinygltf::Node> trs_;  // each node with its animated translation, rotation, scale
  GltfPose pose_;
};

}  // namespace

GltfPose gltf_pose(const GltfFile& file, const GltfAccessors& data, const ImportOptions& options) {
  return Poser(file, data, options).pose();
}

std::vector<glm::mat4> gltf_skin_matrices(const GltfFile& file, const GltfAccessors& data,
                                          const GltfPose& pose, int skin, int node) {
  const std::string where = file.path + ": skin " + std::to_string(skin);
  if (skin < 0 || static_cast<std::size_t>(skin) >= file.model.skins.size())
    throw Error(where + " does not exist");
  const tinygltf::Skin& s = file.model.skins[static_cast<std::size_t>(skin)];
  std::vector<glm::mat4> inverse_bind(s.joints.size(), glm::mat4(1.0f));
  if (s.inverseBindMatrices >= 0) {
    // MAT4 accessors are read column by column as four VEC4s would be: a view of 16 floats.
    const tinygltf::Accessor& a =
        file.model.accessors.at(static_cast<std::size_t>(s.inverseBindMatrices));
    if (a.type != TINYGLTF_TYPE_MAT4 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
        a.count < s.joints.size() || a.bufferView < 0)
      throw Error(where + ": inverseBindMatrices must be float MAT4s, one per joint");
    std::size_t length = 0;
    const std::uint8_t* bytes = data.view_bytes(a.bufferView, length);
    const std::size_t stride = std::max<std::size_t>(
        file.model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride, 64);
    if (a.byteOffset > length ||
        (s.joints.size() > 0 && (length - a.byteOffset < 64 ||
                                 (s.joints.size() - 1) > (length - a.byteOffset - 64) / stride)))
      throw Error(where + ": inverseBindMatrices reach past the end of their buffer view");
    for (std::size_t j = 0; j < s.joints.size(); ++j)
      std::memcpy(&inverse_bind[j][0][0], bytes + a.byteOffset + j * stride, 64);
  }
  // Vertices end up in the drawing node's space: its own transform undone, since a skinned
  // mesh is placed by its joints alone (glTF 2.0 §3.7.3.1).
  const glm::mat4 to_node = glm::inverse(pose.world.at(static_cast<std::size_t>(node)));
  std::vector<glm::mat4> out(s.joints.size());
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    const int joint = s.joints[j];
    if (joint < 0 || static_cast<std::size_t>(joint) >= pose.world.size())
      throw Error(where + ": joint " + std::to_string(j) + " is node " + std::to_string(joint) +
                  ", which does not exist");
    out[j] = to_node * pose.world[static_cast<std::size_t>(joint)] * inverse_bind[j];
  }
  return out;
}

}  // namespace facet::io
