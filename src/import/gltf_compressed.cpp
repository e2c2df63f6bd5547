// Compressed glTF data (gltf_internal.hpp): what tinygltf 2.7 does not read of
// KHR_draco_mesh_compression and EXT_meshopt_compression. Runs once per model at load time.
//
// * Before tinygltf parses the JSON (gltf_json_for_tinygltf): tinygltf refuses an index
//   accessor without a buffer view, which is how a Draco primitive's indices are written (the
//   indices are in the Draco data), and a .gltf buffer without a URI, which is how meshopt's
//   fallback buffers are written (the data is in the compressed views). Such a primitive loses
//   its "indices" and such a buffer gets a three-byte data URI; nothing else changes.
// * After (decode_meshopt_views): each EXT_meshopt_compression buffer view is decoded
//   (meshoptimizer) into a buffer of its own, and the view pointed at it, so that accessors read
//   it as any other. A view that claims more than kMaxDecodedRatio times its compressed size, or
//   more than kMaxDecodedBytes, is refused before anything is allocated.
#include <meshoptimizer.h>

#include <nlohmann/json.hpp>
#include <string>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

// meshopt's codecs store a byte lane of 16 vertices in no less than 2 bits plus block
// headers: no valid stream decodes to more than a few hundred times its size. Far above that,
// the count is a lie.
constexpr std::size_t kMaxDecodedRatio = 1024;
constexpr std::size_t kMaxDecodedBytes = std::size_t(1) << 30;

void put_u32(std::string& out, std::size_t value) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((value >> (8 * i)) & 0xFF);
}

std::uint32_t little_u32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t(u[0]) | std::uint32_t(u[1]) << 8 | std::uint32_t(u[2]) << 16 |
         std::uint32_t(u[3]) << 24;
}

// Returns whether the document changed.
bool adapt(nlohmann::json& doc) {
  bool changed = false;
  if (doc.is_object() && doc.contains("meshes") && doc["meshes"].is_array()) {
    for (auto& mesh : doc["meshes"]) {
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
        continue;
      for (auto& p : mesh["primitives"]) {
        if (p.is_object() && p.contains("extensions") && p["extensions"].is_object() &&
            p["extensions"].contains("KHR_draco_mesh_compression") && p.contains("indices")) {
          p.erase("indices");
          changed = true;
        }
      }
    }
  }
  if (doc.is_object() && doc.contains("buffers") && doc["buffers"].is_array()) {
    for (auto& b : doc["buffers"]) {
      if (b.is_object() && !b.contains("uri") && b.contains("extensions") &&
          b["extensions"].is_object() && b["extensions"].contains("EXT_meshopt_compression")) {
        // Three zero bytes: tinygltf decodes no empty data URI, and the buffer is never read.
        b["uri"] = "data:application/octet-stream;base64,AAAA";
        b["byteLength"] = 3;
        changed = true;
      }
    }
  }
  return changed;
}

}  // namespace

std::string gltf_json_for_tinygltf(std::string_view bytes, bool binary) {
  const bool draco = bytes.find("KHR_draco_mesh_compression") != std::string_view::npos;
  const bool meshopt = bytes.find("EXT_meshopt_compression") != std::string_view::npos;
  if (!draco && !meshopt) return {};
  std::string_view text = bytes;
  std::size_t json_length = 0;
  if (binary) {
    if (bytes.size() < 20) return {};
    json_length = little_u32(bytes.data() + 12);
    if (json_length > bytes.size() - 20) return {};  // tinygltf says what is wrong
    text = bytes.substr(20, json_length);
  }
  nlohmann::json doc = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
  if (doc.is_discarded() || !adapt(doc)) return {};
  std::string json = doc.dump();
  if (!binary) return json;
  // Only the JSON chunk changes: padded to 4 bytes, the chunks after it copied as they are.
  while (json.size() % 4) json += ' ';
  const std::string_view rest = bytes.substr(20 + json_length);
  std::string out(bytes.substr(0, 8));
  put_u32(out, 12 + 8 + json.size() + rest.size());
  put_u32(out, json.size());
  out += "JSON";
  out += json;
  out += rest;
  return out;
}

void decode_meshopt_views(GltfFile& file) {
  auto& model = file.model;
  for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
    tinygltf::BufferView& view = model.bufferViews[v];
    auto it = view.extensions.find("EXT_meshopt_compression");
    if (it == view.extensions.end()) continue;
    const tinygltf::Value& e = it->second;
    const std::string where = file.path + ": buffer view " + std::to_string(v) + " (meshopt)";
    auto number = [&](const char* key, double fallback) {
      const tinygltf::Value& n = e.Get(key);
      return n.IsNumber() ? n.GetNumberAsDouble() : fallback;
    };
    const double buffer = number("buffer", -1), offset = number("byteOffset", 0),
                 length = number("byteLength", -1), stride = number("byteStride", -1),
                 count = number("count", -1);
    const std::string mode = e.Get("mode").IsString() ? e.Get("mode").Get<std::string>() : "";
    const std::string filter =
        e.Get("filter").IsString() ? e.Get("filter").Get<std::string>() : "NONE";
    if (!(buffer >= 0 && buffer < static_cast<double>(model.buffers.size())) || !(offset >= 0) ||
        !(length >= 0) || !(stride >= 1 && stride <= 256) || !(count >= 0))
      throw Error(where +
                  ": buffer, byteOffset, byteLength, byteStride or count is missing or "
                  "out of range");
    const auto& source = model.buffers[static_cast<std::size_t>(buffer)].data;
    if (offset + length > static_cast<double>(source.size()))
      throw Error(where + ": its compressed bytes reach past the end of buffer " +
                  std::to_string(static_cast<std::size_t>(buffer)));
    const double decoded = count * stride;
    if (decoded > static_cast<double>(kMaxDecodedBytes) ||
        decoded > length * kMaxDecodedRatio + 65536.0)
      throw Error(where + ": " + std::to_string(static_cast<std::size_t>(count)) + " elements of " +
                  std::to_string(static_cast<int>(stride)) + " bytes from " +
                  std::to_string(static_cast<std::size_t>(length)) +
                  " compressed bytes: more than the codec can hold");
    const auto n = static_cast<std::size_t>(count), size = static_cast<std::size_t>(stride);
    const unsigned char* from = source.data() + static_cast<std::size_t>(offset);
    const auto from_length = static_cast<std::size_t>(length);
    tinygltf::Buffer out;
    out.data.resize(n * size);
    int status = -1;
    if (mode == "ATTRIBUTES") {
      if (size % 4 != 0) throw Error(where + ": ATTRIBUTES need a stride that is a multiple of 4");
      status = meshopt_decodeVertexBuffer(out.data.data(), n, size, from, from_length);
      if (status == 0 && filter == "OCTAHEDRAL" && (size == 4 || size == 8))
        meshopt_decodeFilterOct(out.data.data(), n, size);
      if (status == 0 && filter == "QUATERNION" && size == 8)
        meshopt_decodeFilterQuat(out.data.data(), n, size);
      if (status == 0 && filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data.data(), n, size);
    } else if ((mode == "TRIANGLES" || mode == "INDICES") && (size == 2 || size == 4)) {
      if (mode == "TRIANGLES" && n % 3 != 0) throw Error(where + ": TRIANGLES count not 3N");
      status = mode == "TRIANGLES"
                   ? meshopt_decodeIndexBuffer(out.data.data(), n, size, from, from_length)
                   : meshopt_decodeIndexSequence(out.data.data(), n, size, from, from_length);
    } else {
      throw Error(where + ": unknown mode '" + mode + "' for a stride of " + std::to_string(size));
    }
    if (status != 0) throw Error(where + ": the compressed data is damaged");
    model.buffers.push_back(std::move(out));
    view.buffer = static_cast<int>(model.buffers.size()) - 1;
    view.byteOffset = 0;
    view.byteLength = n * size;
    view.byteStride = mode == "ATTRIBUTES" ? size : 0;
  }
}

}  // namespace facet::io
