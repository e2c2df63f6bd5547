// gltf_primitive_mesh() (gltf_internal.hpp): one glTF mesh primitive to a facet Mesh. Runs once
// per (primitive, material's texture coordinate set, mirrored or not) at load time.
//
// Every glTF primitive mode is drawn: TRIANGLES as they are, TRIANGLE_STRIP and TRIANGLE_FAN as
// the triangles glTF 2.0 §3.7.2.1 lists for them; LINES, LINE_STRIP and LINE_LOOP as line
// segments; POINTS as points. Quantized attributes (KHR_mesh_quantization: byte and short
// positions, normals, tangents and texture coordinates, normalized or not) are read as the
// accessors say; the node's transform carries the dequantization scale.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <string>

#include "facet/error.hpp"
#include "facet/mesh_tools.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

constexpr int kPoints = 0, kLines = 1, kLineLoop = 2, kLineStrip = 3, kTriangles = 4,
              kTriangleStrip = 5, kTriangleFan = 6;

int attribute(const tinygltf::Primitive& p, const std::string& name) {
  auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

// The vertex order the mode walks, as a list for facet's triangles, lines or points.
std::vector<std::uint32_t> as_list(const std::vector<std::uint32_t>& v, int mode) {
  std::vector<std::uint32_t> out;
  const std::size_t n = v.size();
  switch (mode) {
    case kTriangles:
      out.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
      break;
    case kTriangleStrip:
      for (std::size_t i = 0; i + 2 < n; ++i) {
        const bool odd = i % 2 == 1;  // every other triangle turns the other way
        out.insert(out.end(), {v[i], v[i + (odd ? 2 : 1)], v[i + (odd ? 1 : 2)]});
      }
      break;
    case kTriangleFan:
      for (std::size_t i = 1; i + 1 < n; ++i) out.insert(out.end(), {v[i], v[i + 1], v[0]});
      break;
    case kLines:
      out.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n - n % 2));
      break;
    case kLineStrip:
    case kLineLoop:
      for (std::size_t i = 0; i + 1 < n; ++i) out.insert(out.end(), {v[i], v[i + 1]});
      if (mode == kLineLoop && n > 2) out.insert(out.end(), {v[n - 1], v[0]});
      break;
    default:  // points
      out = v;
  }
  return out;
}

Topology topology_of(int mode) {
  if (mode == kPoints) return Topology::points;
  if (mode == kLines || mode == kLineLoop || mode == kLineStrip) return Topology::lines;
  return Topology::triangles;
}

std::vector<glm::vec3> vec3s(const std::vector<glm::vec4>& in) {
  std::vector<glm::vec3> out(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) out[i] = glm::vec3(in[i]);
  return out;
}

}  // namespace

std::shared_ptr<const Mesh> gltf_primitive_mesh(const GltfFile& file, const GltfAccessors& data,
                                                int mesh_index, int primitive_index,
                                                int texcoord_set, const Material& material,
                                                bool flip_winding, const MeshPose& pose,
                                                const ImportOptions& options) {
  const tinygltf::Primitive& p = file.model.meshes[static_cast<std::size_t>(mesh_index)]
                                     .primitives[static_cast<std::size_t>(primitive_index)];
  const std::string where = file.path + ": mesh " + std::to_string(mesh_index) + " primitive " +
                            std::to_string(primitive_index);
  if (p.mode < kPoints || p.mode > kTriangleFan)
    throw Error(where + ": unknown mode " + std::to_string(p.mode));
  const int position = attribute(p, "POSITION");
  if (position < 0) return nullptr;  // glTF allows it; there is nothing to draw
  // KHR_draco_mesh_compression: the attributes and indices are in the Draco data, the accessors
  // only describe them.
  std::optional<DracoPrimitive> draco;
  auto compressed = p.extensions.find("KHR_draco_mesh_compression");
  if (compressed != p.extensions.end())
    draco = decode_draco_primitive(data, compressed->second, where);
  int components = 0;
  auto values_of = [&](const std::string& name, int accessor) -> std::vector<glm::vec4> {
    if (draco) {
      auto it = draco->attributes.find(name);
      if (it != draco->attributes.end()) {
        components = draco->components[name];
        return it->second;
      }
    }
    return data.floats(accessor, components);
  };
  Mesh mesh;
  mesh.topology = draco ? Topology::triangles : topology_of(p.mode);
  mesh.positions = vec3s(values_of("POSITION", position));
  const std::size_t n = mesh.positions.size();
  auto read = [&](const std::string& name, int want) -> std::vector<glm::vec4> {
    const int a = attribute(p, name);
    if (a < 0) return {};
    std::vector<glm::vec4> values = values_of(name, a);
    if (values.size() != n)
      throw Error(where + ": " + name + " has " + std::to_string(values.size()) + " elements for " +
                  std::to_string(n) + " positions");
    if (want > 0 && components < want)
      throw Error(where + ": " + name + " has " + std::to_string(components) + " components");
    return values;
  };
  mesh.normals = vec3s(read("NORMAL", 3));
  for (const glm::vec4& t : read("TANGENT", 4)) mesh.tangents.push_back(t);
  // glTF's v runs down the image from its top; facet's runs up from the bottom.
  for (const glm::vec4& uv : read("TEXCOORD_" + std::to_string(texcoord_set), 2))
    mesh.texcoords.emplace_back(uv.x, 1.0f - uv.y);
  // Skins and morph targets (gltf_deform.cpp), before finish_mesh makes normals for a mesh
  // without: those must be the posed surface's. (Draco data has its attributes inside the
  // compressed stream, which facet does not pose: it is drawn at rest.)
  if (!draco && (!pose.weights.empty() || !pose.joints.empty()))
    deform_primitive(data, p, pose, mesh.positions, mesh.normals, mesh.tangents, where);
  const std::vector<glm::vec4> colors = read("COLOR_0", 3);
  mesh.colors.reserve(colors.size());
  // An opaque material ignores alpha (glTF 2.0 §3.9.4), the vertex colors' too.
  const bool keep_alpha = components == 4 && material.alpha_mode != AlphaMode::opaque;
  for (glm::vec4 c : colors) mesh.colors.push_back(keep_alpha ? c : glm::vec4(glm::vec3(c), 1));

  std::vector<std::uint32_t> order;
  if (draco) {
    order = std::move(draco->indices);
    for (std::uint32_t i : order) {
      if (i >= n) throw Error(where + ": the Draco data names vertex " + std::to_string(i));
    }
  } else if (p.indices >= 0) {
    order = data.indices(p.indices, n);
  } else {
    order.resize(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  }
  mesh.indices = as_list(order, draco ? kTriangles : p.mode);  // Draco decodes to a list
  if (mesh.indices.empty()) return nullptr;
  // A point is drawn once for each time it is named, without indices (Topology::points).
  if (mesh.topology == Topology::points) expand_indices(mesh);
  finish_mesh(mesh, material, options, where);
  // A mirrored node's front faces are clockwise (glTF 2.0 §3.7.2.1): reversed, they are
  // counter-clockwise once mirrored, as the renderer expects. After finish_mesh, so that
  // normals it computes face out of the unmirrored mesh, as the node's normal matrix expects.
  if (flip_winding && mesh.topology == Topology::triangles) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  }
  return std::make_shared<const Mesh>(std::move(mesh));
}

}  // namespace facet::io
