// GltfAccessors (gltf_internal.hpp): reads glTF accessors into floats and indices, every range
// checked against the buffer before a byte is read. Runs once per primitive at load time.
//
// Component types and normalization follow glTF 2.0 §3.11: a normalized signed byte c is
// max(c / 127, -1), an unsigned byte c / 255, and so on; unnormalized integers are their
// values (KHR_mesh_quantization's positions). Sparse accessors (§3.6.2.3) are applied on top.
#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;  // matrices: no vertex attribute facet reads is one
  }
}

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

template <class T>
T load(const std::uint8_t* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

float component(const std::uint8_t* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = load<std::int8_t>(p);
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const float v = load<std::uint8_t>(p);
      return normalized ? v / 255.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = load<std::int16_t>(p);
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float v = load<std::uint16_t>(p);
      return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return static_cast<float>(load<std::uint32_t>(p));
    default:
      return load<float>(p);
  }
}

std::uint32_t index_at(const std::uint8_t* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return load<std::uint16_t>(p);
    default:
      return load<std::uint32_t>(p);
  }
}

}  // namespace

void GltfAccessors::fail(int index, const std::string& what) const {
  throw Error(file_.path + ": accessor " + std::to_string(index) + ": " + what);
}

const tinygltf::Accessor& GltfAccessors::accessor(int index) const {
  if (index < 0 || static_cast<std::size_t>(index) >= file_.model.accessors.size())
    throw Error(file_.path + ": accessor " + std::to_string(index) + " does not exist");
  return file_.model.accessors[static_cast<std::size_t>(index)];
}

std::size_t GltfAccessors::count(int index) const { return accessor(index).count; }

const std::uint8_t* GltfAccessors::view_bytes(int view, std::size_t& length) const {
  const auto& views = file_.model.bufferViews;
  if (view < 0 || static_cast<std::size_t>(view) >= views.size())
    throw Error(file_.path + ": buffer view " + std::to_string(view) + " does not exist");
  const tinygltf::BufferView& v = views[static_cast<std::size_t>(view)];
  const auto& buffers = file_.model.buffers;
  if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= buffers.size())
    throw Error(file_.path + ": buffer view " + std::to_string(view) + ": buffer " +
                std::to_string(v.buffer) + " does not exist");
  const std::vector<unsigned char>& data = buffers[static_cast<std::size_t>(v.buffer)].data;
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
    throw Error(file_.path + ": buffer view " + std::to_string(view) + " (bytes " +
                std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) +
                ") reaches past the end of buffer " + std::to_string(v.buffer) + " (" +
                std::to_string(data.size()) + " bytes)");
  length = v.byteLength;
  return data.data() + v.byteOffset;
}

std::vector<glm::vec4> GltfAccessors::floats(int index, int& components) const {
  const tinygltf::Accessor& a = accessor(index);
  components = component_count(a.type);
  const int size = component_size(a.componentType);
  if (components == 0 || size == 0) fail(index, "not a scalar or vector of numbers");
  const std::size_t element = static_cast<std::size_t>(components) * size;
  std::vector<glm::vec4> out;
  const glm::vec4 zero(0.0f, 0.0f, 0.0f, 1.0f);
  auto read_element = [&](const std::uint8_t* p) {
    glm::vec4 v = zero;
    for (int c = 0; c < components; ++c)
      v[c] = component(p + c * size, a.componentType, a.normalized);
    return v;
  };
  if (a.bufferView < 0) {
    // No data: zeros (a sparse accessor fills some in). The count is not backed by any bytes, so
    // it is held to the sparse count's scale before allocating.
    if (!a.sparse.isSparse && a.count > 0) fail(index, "has no buffer view and is not sparse");
    if (a.count > (std::size_t(1) << 26))
      fail(index, "a count of " + std::to_string(a.count) + " without data behind it");
    out.assign(a.count, zero);
  } else {
    std::size_t length = 0;
    const std::uint8_t* bytes = view_bytes(a.bufferView, length);
    const std::size_t declared_stride =
        file_.model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride;
    const std::size_t stride = declared_stride ? declared_stride : element;
    if (stride < element) fail(index, "the buffer view's stride is shorter than one element");
    // offset + stride (count - 1) + element <= length, without overflow.
    if (a.count > 0 && (a.byteOffset > length || element > length - a.byteOffset ||
                        (a.count - 1) > (length - a.byteOffset - element) / stride))
      fail(index, std::to_string(a.count) + " elements of " + std::to_string(element) +
                      " bytes from byte " + std::to_string(a.byteOffset) +
                      " reach past the end of buffer view " + std::to_string(a.bufferView) + " (" +
                      std::to_string(length) + " bytes)");
    out.resize(a.count);
    for (std::size_t i = 0; i < a.count; ++i)
      out[i] = read_element(bytes + a.byteOffset + i * stride);
  }
  if (a.sparse.isSparse && a.sparse.count > 0) {
    const std::size_t n = static_cast<std::size_t>(a.sparse.count);
    const int index_size = component_size(a.sparse.indices.componentType);
    const int index_type = a.sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      fail(index, "sparse indices are not unsigned integers");
    std::size_t index_length = 0, value_length = 0;
    const std::uint8_t* indices = view_bytes(a.sparse.indices.bufferView, index_length);
    const std::uint8_t* values = view_bytes(a.sparse.values.bufferView, value_length);
    const auto index_offset = static_cast<std::size_t>(std::max(a.sparse.indices.byteOffset, 0));
    const auto value_offset = static_cast<std::size_t>(std::max(a.sparse.values.byteOffset, 0));
    if (index_offset > index_length || n > (index_length - index_offset) / index_size ||
        value_offset > value_length || n > (value_length - value_offset) / element)
      fail(index, "its sparse indices or values reach past their buffer views");
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t at =
          index_at(indices + index_offset + i * index_size, a.sparse.indices.componentType);
      if (at >= out.size()) fail(index, "sparse index " + std::to_string(at) + " is out of range");
      out[at] = read_element(values + value_offset + i * element);
    }
  }
  return out;
}

std::vector<std::uint32_t> GltfAccessors::indices(int index, std::size_t vertex_count) const {
  const tinygltf::Accessor& a = accessor(index);
  const int type = a.componentType;
  if (a.type != TINYGLTF_TYPE_SCALAR || (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                         type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                         type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    fail(index, "indices must be unsigned byte, short or int scalars");
  std::vector<std::uint32_t> out;
  if (a.bufferView < 0 || a.sparse.isSparse) {
    // Rare: read as numbers (exact up to 2^24 indices).
    int components = 0;
    for (const glm::vec4& v : floats(index, components))
      out.push_back(static_cast<std::uint32_t>(v.x));
  } else {
    std::size_t length = 0;
    const std::uint8_t* bytes = view_bytes(a.bufferView, length);
    const std::size_t size = static_cast<std::size_t>(component_size(type));
    if (a.count > 0 && (a.byteOffset > length || a.count > (length - a.byteOffset) / size))
      fail(index, std::to_string(a.count) + " indices from byte " + std::to_string(a.byteOffset) +
                      " reach past the end of buffer view " + std::to_string(a.bufferView) + " (" +
                      std::to_string(length) + " bytes)");
    out.resize(a.count);
    for (std::size_t i = 0; i < a.count; ++i)
      out[i] = index_at(bytes + a.byteOffset + i * size, type);
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i] >= vertex_count)
      fail(index, "index " + std::to_string(i) + " is " + std::to_string(out[i]) +
                      ", but there are " + std::to_string(vertex_count) + " vertices");
  }
  return out;
}

}  // namespace facet::io
