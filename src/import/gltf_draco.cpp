// decode_draco_primitive() (gltf_internal.hpp): a KHR_draco_mesh_compression primitive's
// Draco data to attribute values and triangle corners. Runs once per compressed primitive at
// load time; gltf_meshes.cpp reads the result as it reads accessors.
#include <draco/compression/decode.h>

#include <algorithm>
#include <string>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {

DracoPrimitive decode_draco_primitive(const GltfAccessors& data, const tinygltf::Value& extension,
                                      const std::string& where) {
  const tinygltf::Value& view = extension.Get("bufferView");
  if (!view.IsInt()) throw Error(where + ": KHR_draco_mesh_compression has no bufferView");
  std::size_t length = 0;
  const std::uint8_t* bytes = data.view_bytes(view.GetNumberAsInt(), length);
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(bytes), length);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok() || !decoded.value())
    throw Error(where + ": the Draco data cannot be decoded (" +
                decoded.status().error_msg_string() + ")");
  const draco::Mesh& mesh = *decoded.value();
  DracoPrimitive out;
  const std::size_t points = mesh.num_points();
  out.indices.reserve(static_cast<std::size_t>(mesh.num_faces()) * 3);
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) out.indices.push_back(mesh.face(f)[c].value());
  }
  for (std::uint32_t index : out.indices) {
    if (index >= points) throw Error(where + ": the Draco data names a point it does not have");
  }
  const tinygltf::Value& attributes = extension.Get("attributes");
  if (!attributes.IsObject()) return out;
  for (const std::string& name : attributes.Keys()) {
    const tinygltf::Value& id = attributes.Get(name);
    if (!id.IsInt()) continue;
    const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id.GetNumberAsInt());
    if (!attribute) throw Error(where + ": Draco attribute " + name + " is missing");
    const int components = std::clamp<int>(attribute->num_components(), 1, 4);
    std::vector<glm::vec4>& values = out.attributes[name];
    values.assign(points, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    float value[4] = {0, 0, 0, 1};
    for (draco::PointIndex p(0); p < static_cast<std::uint32_t>(points); ++p) {
      if (attribute->mapped_index(p).value() >= attribute->size())
        throw Error(where + ": Draco attribute " + name + " names a value it does not have");
      if (!attribute->ConvertValue<float>(attribute->mapped_index(p),
                                          static_cast<std::int8_t>(components), value))
        throw Error(where + ": Draco attribute " + name + " cannot be read as numbers");
      for (int c = 0; c < components; ++c) values[p.value()][c] = value[c];
    }
    out.components[name] = components;
  }
  return out;
}

}  // namespace facet::io
