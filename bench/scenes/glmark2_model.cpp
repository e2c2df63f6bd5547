// The .3ds and .obj readers and glmark2's normal generation (see glmark2_model.hpp).
#include "scenes/glmark2_model.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>

#include "facet/error.hpp"

namespace facet::bench {
namespace {

// Little-endian reads from the file image, with the offset for error messages.
class ChunkReader {
 public:
  ChunkReader(std::string path, std::vector<char> bytes)
      : path_(std::move(path)), bytes_(std::move(bytes)) {}

  bool at_end() const { return offset_ >= bytes_.size(); }
  std::size_t offset() const { return offset_; }
  void seek(std::size_t offset) { offset_ = offset; }

  template <class T>
  T read() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + offset_, sizeof(T));  // the files and x86 are LE
    offset_ += sizeof(T);
    return value;
  }
  glm::vec3 read_vec3() {
    float x = read<float>(), y = read<float>(), z = read<float>();
    return {x, y, z};
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(path_ + ": offset " + std::to_string(offset_) + ": " + what);
  }

 private:
  void need(std::size_t n) const {
    if (bytes_.size() - std::min(offset_, bytes_.size()) < n) fail("truncated .3ds file");
  }
  std::string path_;
  std::vector<char> bytes_;
  std::size_t offset_ = 0;
};

std::string hex(std::uint16_t id) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%04X", static_cast<unsigned>(id));
  return text;
}

std::vector<char> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open (install the Debian package glmark2-data)");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every face index names a vertex (else fail(what)); then the model's bounding box.
template <class Fail>
void check_faces_and_bound(Glmark2Model& model, const Fail& fail) {
  for (std::size_t i = 0; i < model.indices.size(); ++i) {
    if (model.indices[i] >= model.positions.size()) {
      fail("face " + std::to_string(i / 3) + " uses vertex " + std::to_string(model.indices[i]) +
           " of " + std::to_string(model.positions.size()));
    }
  }
  model.bbox_min = model.bbox_max = model.positions[0];
  for (const glm::vec3& p : model.positions) {
    model.bbox_min = glm::min(model.bbox_min, p);
    model.bbox_max = glm::max(model.bbox_max, p);
  }
}

}  // namespace

Glmark2Model load_3ds(const std::string& path) {
  ChunkReader in(path, read_file(path));
  Glmark2Model model;
  // glmark2 walks the file as a flat sequence of chunk headers: a container chunk is
  // "entered" simply by reading on past its 6-byte header.
  while (!in.at_end()) {
    const std::size_t start = in.offset();
    const auto id = in.read<std::uint16_t>();
    const auto length = in.read<std::uint32_t>();
    switch (id) {
      case 0x4D4D:  // main
      case 0x3D3D:  // editor
      case 0x4100:  // trimesh
        break;
      case 0x4000: {  // object: a null-terminated name of at most 20 bytes, then sub-chunks
        for (int i = 0; i < 20 && in.read<char>() != '\0'; ++i) {
        }
        break;
      }
      case 0x4110: {  // vertex list
        const auto count = in.read<std::uint16_t>();
        model.positions.resize(count);
        for (glm::vec3& p : model.positions) p = in.read_vec3();
        break;
      }
      case 0x4120: {  // face list: a, b, c, flags (ignored)
        const auto count = in.read<std::uint16_t>();
        model.indices.resize(std::size_t{count} * 3);
        for (std::size_t f = 0; f < count; ++f) {
          for (int k = 0; k < 3; ++k) model.indices[f * 3 + k] = in.read<std::uint16_t>();
          in.read<std::uint16_t>();
        }
        break;
      }
      case 0x4140: {  // texcoords (u, v), one per vertex
        const auto count = in.read<std::uint16_t>();
        model.texcoords.resize(count);
        for (glm::vec2& t : model.texcoords) {
          t.x = in.read<float>();
          t.y = in.read<float>();
        }
        break;
      }
      default:
        if (length < 6) in.fail("chunk " + hex(id) + " shorter than its header");
        in.seek(start + length);
    }
  }
  if (model.positions.empty() || model.indices.empty()) in.fail("no vertices or no faces");
  if (!model.texcoords.empty() && model.texcoords.size() != model.positions.size()) {
    in.fail(std::to_string(model.texcoords.size()) + " texcoords for " +
            std::to_string(model.positions.size()) + " vertices");
  }
  check_faces_and_bound(model, [&](const std::string& what) { in.fail(what); });
  return model;
}

Glmark2Model load_obj(const std::string& path) {
  const std::vector<char> bytes = read_file(path);
  std::istringstream text(std::string(bytes.begin(), bytes.end()));
  Glmark2Model model;
  std::string line;
  int line_number = 0;
  auto fail = [&](const std::string& what) {
    throw Error(path + ": line " + std::to_string(line_number) + ": " + what);
  };
  while (std::getline(text, line)) {
    ++line_number;
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "v") {
      glm::vec3 p;
      if (!(fields >> p.x >> p.y >> p.z)) fail("a vertex needs x y z");
      model.positions.push_back(p);
    } else if (kind == "f") {
      for (int k = 0; k < 3; ++k) {
        long index = 0;
        if (!(fields >> index) || index < 1) fail("a face needs three 1-based vertex indices");
        model.indices.push_back(static_cast<std::uint32_t>(index - 1));
      }
    }
  }
  if (model.positions.empty() || model.indices.empty()) {
    throw Error(path + ": no vertices or no faces");
  }
  check_faces_and_bound(model, [&](const std::string& what) { throw Error(path + ": " + what); });
  return model;
}

std::vector<glm::vec3> glmark2_normals(const Glmark2Model& model) {
  std::vector<glm::vec3> normals(model.positions.size(), glm::vec3(0.0f));
  for (std::size_t f = 0; f + 2 < model.indices.size(); f += 3) {
    const std::uint32_t a = model.indices[f], b = model.indices[f + 1], c = model.indices[f + 2];
    const glm::vec3& pa = model.positions[a];
    const glm::vec3 n =
        glm::normalize(glm::cross(model.positions[b] - pa, model.positions[c] - pa));
    normals[a] += n;
    normals[b] += n;
    normals[c] += n;
  }
  for (glm::vec3& n : normals) n = glm::normalize(n);
  return normals;
}

Mesh glmark2_mesh(const Glmark2Model& model, const Glmark2MeshOptions& options) {
  Mesh mesh;
  std::vector<glm::vec3> normals;
  if (options.normals) normals = glmark2_normals(model);
  const bool texcoords = options.texcoords && !model.texcoords.empty();
  if (!options.deindex) {
    mesh.positions = model.positions;
    mesh.normals = std::move(normals);
    if (texcoords) mesh.texcoords = model.texcoords;
    mesh.indices = model.indices;
    return mesh;
  }
  // glmark2's Model::convert_to_mesh: vertex i of the triangle list is file vertex indices[i].
  const std::size_t n = model.indices.size();
  mesh.positions.reserve(n);
  if (options.normals) mesh.normals.reserve(n);
  if (texcoords) mesh.texcoords.reserve(n);
  for (std::uint32_t i : model.indices) {
    mesh.positions.push_back(model.positions[i]);
    if (options.normals) mesh.normals.push_back(normals[i]);
    if (texcoords) mesh.texcoords.push_back(model.texcoords[i]);
  }
  return mesh;
}

}  // namespace facet::bench
