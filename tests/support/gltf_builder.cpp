// GltfBuilder (gltf_builder.hpp): glTF files written by the tests, and the glTF tests' helpers.
#include "support/gltf_builder.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/error.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = std::uint32_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) chunk |= std::uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) chunk |= bytes[i + 2];
    out += kDigits[(chunk >> 18) & 63];
    out += kDigits[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[chunk & 63] : '=';
  }
  return out;
}

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
}

template <class T>
int float_accessor(GltfBuilder& b, const std::vector<T>& values, const char* type) {
  const int view = b.view(values.data(), values.size() * sizeof(T));
  return b.accessor(view, kGlFloat, values.size(), type);
}

}  // namespace

GltfBuilder::GltfBuilder() {
  json = {{"asset", {{"version", "2.0"}}},
          {"scene", 0},
          {"scenes", {{{"nodes", nlohmann::json::array()}}}},
          {"nodes", nlohmann::json::array()},
          {"meshes", nlohmann::json::array()},
          {"accessors", nlohmann::json::array()},
          {"bufferViews", nlohmann::json::array()}};
}

int GltfBuilder::view(const void* data, std::size_t size, int stride) {
  while (buffer.size() % 4) buffer.push_back(0);
  nlohmann::json v = {{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", size}};
  if (stride) v["byteStride"] = stride;
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  buffer.insert(buffer.end(), bytes, bytes + size);
  json["bufferViews"].push_back(v);
  return static_cast<int>(json["bufferViews"].size()) - 1;
}

int GltfBuilder::accessor(int view, int component_type, std::size_t count, const std::string& type,
                          bool normalized) {
  nlohmann::json a = {
      {"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
  if (normalized) a["normalized"] = true;
  json["accessors"].push_back(a);
  return static_cast<int>(json["accessors"].size()) - 1;
}

int GltfBuilder::positions(const std::vector<glm::vec3>& values) {
  const int a = float_accessor(*this, values, "VEC3");
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : values) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  json["accessors"][a]["min"] = {lo.x, lo.y, lo.z};
  json["accessors"][a]["max"] = {hi.x, hi.y, hi.z};
  return a;
}

int GltfBuilder::vec2s(const std::vector<glm::vec2>& values) {
  return float_accessor(*this, values, "VEC2");
}
int GltfBuilder::vec3s(const std::vector<glm::vec3>& values) {
  return float_accessor(*this, values, "VEC3");
}
int GltfBuilder::vec4s(const std::vector<glm::vec4>& values) {
  return float_accessor(*this, values, "VEC4");
}

int GltfBuilder::indices(const std::vector<std::uint16_t>& values) {
  const int view = this->view(values.data(), values.size() * 2);
  return accessor(view, kGlUnsignedShort, values.size(), "SCALAR");
}

int GltfBuilder::scalars(const std::vector<float>& values) {
  return float_accessor(*this, values, "SCALAR");
}

int GltfBuilder::mat4s(const std::vector<glm::mat4>& values) {
  return float_accessor(*this, values, "MAT4");
}

void GltfBuilder::animate(int node, const std::string& path, const std::vector<float>& times,
                          const std::vector<float>& values, const std::string& interpolation,
                          int animation) {
  if (!json.contains("animations")) json["animations"] = nlohmann::json::array();
  while (static_cast<int>(json["animations"].size()) <= animation)
    json["animations"].push_back(
        {{"channels", nlohmann::json::array()}, {"samplers", nlohmann::json::array()}});
  const int input = scalars(times);
  json["accessors"][input]["min"] = {times.front()};
  json["accessors"][input]["max"] = {times.back()};
  const int width = path == "rotation" ? 4 : path == "weights" ? 1 : 3;
  const int view = this->view(values.data(), values.size() * sizeof(float));
  const char* type = width == 4 ? "VEC4" : width == 3 ? "VEC3" : "SCALAR";
  const int output = accessor(view, kGlFloat, values.size() / width, type);
  nlohmann::json& a = json["animations"][animation];
  a["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
  a["channels"].push_back(
      {{"sampler", a["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
}

int GltfBuilder::add_mesh_node(const nlohmann::json& primitive, const nlohmann::json& node_fields) {
  json["meshes"].push_back({{"primitives", {primitive}}});
  nlohmann::json node = node_fields.is_null() ? nlohmann::json::object() : node_fields;
  node["mesh"] = json["meshes"].size() - 1;
  json["nodes"].push_back(node);
  const int index = static_cast<int>(json["nodes"].size()) - 1;
  json["scenes"][0]["nodes"].push_back(index);
  return index;
}

std::string GltfBuilder::gltf_text() const {
  nlohmann::json doc = json;
  if (!doc.contains("buffers")) doc["buffers"] = {nullptr};
  doc["buffers"][0] = {{"byteLength", buffer.size()},
                       {"uri", "data:application/octet-stream;base64," + base64(buffer)}};
  return doc.dump();
}

std::string GltfBuilder::glb_bytes() const {
  nlohmann::json doc = json;
  if (!doc.contains("buffers")) doc["buffers"] = {nullptr};
  doc["buffers"][0] = {{"byteLength", buffer.size()}};
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';
  std::string bin(buffer.begin(), buffer.end());
  while (bin.size() % 4) bin += '\0';
  std::string out = "glTF";
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  put_u32(out, static_cast<std::uint32_t>(text.size()));
  out += "JSON" + text;
  put_u32(out, static_cast<std::uint32_t>(bin.size()));
  out += std::string("BIN\0", 4) + bin;
  return out;
}

std::filesystem::path GltfBuilder::write_gltf(const std::filesystem::path& path) const {
  std::ofstream(path, std::ios::binary) << gltf_text();
  return path;
}

std::filesystem::path GltfBuilder::write_glb(const std::filesystem::path& path) const {
  std::ofstream(path, std::ios::binary) << glb_bytes();
  return path;
}

nlohmann::json unit_quad(GltfBuilder& b) {
  const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const int n = b.vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
  const int uv = b.vec2s({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
  const int i = b.indices({0, 1, 2, 0, 2, 3});
  return {{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", uv}}}, {"indices", i}};
}

// The two-bone bar (gltf_builder.hpp says what each pose puts where).
int add_skinned_bar(GltfBuilder& b) {
  const int p = b.positions(
      {{-0.1f, 0, 0}, {0.1f, 0, 0}, {-0.1f, 1, 0}, {0.1f, 1, 0}, {-0.1f, 2, 0}, {0.1f, 2, 0}});
  const std::vector<std::uint8_t> joints = {0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0,
                                            0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0};
  const std::vector<std::uint8_t> weights = {255, 0,   0, 0, 255, 0,   0, 0, 128, 127, 0, 0,
                                             128, 127, 0, 0, 0,   255, 0, 0, 0,   255, 0, 0};
  const int j = b.accessor(b.view(joints.data(), joints.size()), kGlUnsignedByte, 6, "VEC4");
  const int w =
      b.accessor(b.view(weights.data(), weights.size()), kGlUnsignedByte, 6, "VEC4", true);
  const int i = b.indices({0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4});
  const int mesh_node = b.add_mesh_node(
      {{"attributes", {{"POSITION", p}, {"JOINTS_0", j}, {"WEIGHTS_0", w}}}, {"indices", i}},
      {{"skin", 0}, {"translation", {0, 0, 5}}});
  const int parent = mesh_node + 1, joint0 = mesh_node + 2, joint1 = mesh_node + 3;
  b.json["nodes"].push_back({{"translation", {10, 0, 0}}, {"children", {joint0}}});
  b.json["nodes"].push_back({{"children", {joint1}}});
  b.json["nodes"].push_back({{"translation", {0, 1, 0}}});
  b.json["scenes"][0]["nodes"].push_back(parent);
  const int ibm = b.mat4s({glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0))});
  b.json["skins"] = {{{"joints", {joint0, joint1}}, {"inverseBindMatrices", ibm}}};
  const float h = std::sqrt(0.5f);
  b.animate(joint1, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, h, h});
  return mesh_node;
}

ImportedGltf import_gltf(const std::filesystem::path& path, bool allow_outside) {
  ImportedGltf out;
  ImportOptions options;
  options.allow_outside_paths = allow_outside;
  options.warn = [&](const std::string& w) { out.warnings.push_back(w); };
  out.scene = import_scene(path.string(), options);
  return out;
}

ImportedGltf import_gltf(const std::filesystem::path& path, ImportOptions options) {
  ImportedGltf out;
  options.warn = [&](const std::string& w) { out.warnings.push_back(w); };
  out.scene = import_scene(path.string(), options);
  return out;
}

std::filesystem::path gltf_test_dir(const std::string& name) {
  return fresh_test_dir("facet_gltf_", name);
}

std::string ppm_2x2() {
  std::string bytes = "P6\n2 2\n255\n";
  for (unsigned char c : {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255})
    bytes += static_cast<char>(c);
  return bytes;
}

int add_embedded_image(GltfBuilder& b) {
  const std::string image = ppm_2x2();
  const int view = b.view(image.data(), image.size());
  b.json["images"].push_back({{"bufferView", view}, {"mimeType", "image/png"}});
  b.json["textures"].push_back({{"source", b.json["images"].size() - 1}});
  return static_cast<int>(b.json["textures"].size()) - 1;
}

const Material& material_of(const Scene& scene, int node) {
  for (const SceneNode& n : scene.nodes) {
    if (!n.instances.empty() && node < 0) return scene.materials.at(n.instances[0].material);
  }
  return scene.materials.at(scene.nodes.at(node).instances.at(0).material);
}

const Mesh& mesh_of(const Scene& scene) {
  for (const SceneNode& n : scene.nodes) {
    if (!n.instances.empty()) return *scene.meshes.at(n.instances[0].mesh);
  }
  throw Error("no mesh");
}

}  // namespace facet::test
