// parse_gltf(): a .gltf or .glb file's bytes to a tinygltf::Model, with facet's rules on
// everything tinygltf would otherwise do on its own. Runs once per model at load time.
//
// * Files: tinygltf's file callbacks are replaced. A buffer or image URI is read only as
//   guarded_files.hpp allows (regular files, inside the model's folder unless allowed); a
//   refusal is remembered (GltfFile::refused) so that the error or warning can say why. Paths
//   are never expanded (tinygltf's default runs wordexp on them).
// * Images: not decoded here. The callback keeps the encoded bytes (facet decodes the ones a
//   material uses, with its own loader), after checking that an image's buffer view lies in its
//   buffer (tinygltf 2.7 does not).
// * The JSON text is scanned first: nesting deeper than kMaxJsonDepth and data URIs longer than
//   kMaxDataUriBytes are refused before tinygltf parses or decodes anything. The sizes a GLB
//   header claims were checked against the file before it was read (precheck_model), and
//   tinygltf checks each buffer's byteLength against the bytes it has.
#include <sys/stat.h>

#include <cstring>
#include <exception>
#include <filesystem>
#include <string>

#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

namespace fs = std::filesystem;

struct FileAccess {
  const ReferenceRules* rules = nullptr;  // null: no external file may be read
  std::string base_dir;
  std::map<std::string, std::string>* refused = nullptr;
};

// The model's folder as tinygltf joins a URI to it (its JoinPath); empty for the working
// directory.
std::string folder_prefix(const FileAccess& access) {
  const std::string& dir = access.base_dir;
  return dir.empty() || dir.back() == '/' ? dir : dir + "/";
}

// The URI as the model wrote it, relative to the model's folder (tinygltf joins the two).
std::string as_referenced(const std::string& path, const FileAccess& access) {
  const std::string prefix = folder_prefix(access);
  return !prefix.empty() && path.rfind(prefix, 0) == 0 ? path.substr(prefix.size()) : path;
}

bool file_exists(const std::string& path, void* user) {
  const auto& access = *static_cast<const FileAccess*>(user);
  // tinygltf looks for a URI beside the model, then in the working directory: only the first is
  // the file the model means.
  const std::string prefix = folder_prefix(access);
  if (!prefix.empty() && path.rfind(prefix, 0) != 0) return false;
  struct stat st {};
  // A refused file "exists", so that reading it fails with the reason rather than "not found".
  return access.rules && ::stat(path.c_str(), &st) == 0;
}

std::string expand_nothing(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  auto& access = *static_cast<FileAccess*>(user);
  std::string problem = access.rules ? access.rules->refusal(path) : "is not read here";
  if (problem.empty()) {
    try {
      const std::string bytes = read_regular_file(path);
      out->assign(bytes.begin(), bytes.end());
      return true;
    } catch (const Error& e) {
      problem = e.what();
      if (problem.rfind(path + ": ", 0) == 0) problem.erase(0, path.size() + 2);
    }
  }
  access.refused->emplace(as_referenced(path, access), problem);
  if (err) *err += problem;
  return false;
}

bool write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

struct ImageAccess {
  const tinygltf::Model* model = nullptr;
};

// Keeps an image's encoded bytes for facet's decoder; checks an embedded image's buffer view.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
  const tinygltf::Model& model = *static_cast<ImageAccess*>(user)->model;
  if (image->bufferView >= 0) {
    const auto& view = model.bufferViews.at(static_cast<std::size_t>(image->bufferView));
    const auto& buffer = model.buffers.at(static_cast<std::size_t>(view.buffer));
    if (view.byteOffset > buffer.data.size() ||
        view.byteLength > buffer.data.size() - view.byteOffset ||
        view.byteLength > static_cast<std::size_t>(INT32_MAX)) {
      return true;  // no bytes: the texture is reported missing where it is used
    }
  }
  if (bytes && size > 0) image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// Nesting depth and data URI lengths, strings and escapes skipped as JSON has them.
void scan_json(std::string_view json, const std::string& path) {
  int depth = 0;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth)
        throw Error(path + ": cannot import: the JSON nests more than " +
                    std::to_string(kMaxJsonDepth) + " levels deep (byte " + std::to_string(i) +
                    ")");
    } else if (c == '}' || c == ']') {
      --depth;
    } else if (c == '"') {
      const std::size_t start = ++i;
      while (i < json.size() && json[i] != '"') i += json[i] == '\\' ? 2 : 1;
      const std::size_t length = std::min(i, json.size()) - start;
      if (length > kMaxDataUriBytes && json.compare(start, 5, "data:") == 0)
        throw Error(path + ": cannot import: a data URI of " + std::to_string(length) +
                    " bytes at byte " + std::to_string(start) + ", over the limit of " +
                    std::to_string(kMaxDataUriBytes >> 20) +
                    " MiB: keep the buffer in a file beside the model");
    }
  }
}

std::uint32_t little_u32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t(u[0]) | std::uint32_t(u[1]) << 8 | std::uint32_t(u[2]) << 16 |
         std::uint32_t(u[3]) << 24;
}

// A GLB's JSON chunk (the first), or the whole text of a .gltf.
std::string_view json_text(std::string_view bytes, bool binary) {
  if (!binary || bytes.size() < 20) return binary ? std::string_view() : bytes;
  const std::size_t length = little_u32(bytes.data() + 12);
  return bytes.substr(20, std::min(length, bytes.size() - 20));
}

std::string first_line(std::string text) {
  const std::size_t end = text.find('\n');
  if (end != std::string::npos) text.erase(end);
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "unknown error" : text;
}

}  // namespace

GltfFile parse_gltf(std::string_view bytes, const std::string& path, const ReferenceRules* rules) {
  GltfFile file;
  file.path = path;
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  scan_json(json_text(bytes, binary), path);

  FileAccess access;
  access.rules = rules;
  access.base_dir = fs::path(path).parent_path().string();
  access.refused = &file.refused;
  ImageAccess images{&file.model};
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&file_exists, &expand_nothing, &read_whole_file, &write_nothing, &access});
  loader.SetImageLoader(&keep_image_bytes, &images);
  std::string error, warning;
  bool loaded = false;
  try {
    // What tinygltf would refuse of compressed models, adapted first (gltf_compressed.cpp).
    const std::string adapted = gltf_json_for_tinygltf(bytes, binary);
    if (!adapted.empty()) bytes = adapted;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    if (bytes.size() > UINT32_MAX) throw Error(path + ": cannot import: over 4 GiB");
    loaded = binary
                 ? loader.LoadBinaryFromMemory(&file.model, &error, &warning, data,
                                               static_cast<unsigned>(bytes.size()), access.base_dir)
                 : loader.LoadASCIIFromString(&file.model, &error, &warning, bytes.data(),
                                              static_cast<unsigned>(bytes.size()), access.base_dir);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {  // nlohmann's and std::vector::at's, on damaged files
    throw Error(path + ": cannot import: " + first_line(e.what()));
  }
  if (!loaded) {
    // A referenced file that was refused is the reason: say that rather than tinygltf's words.
    for (const auto& [uri, problem] : file.refused) {
      if (error.find(uri) != std::string::npos)
        throw Error(path + ": referenced file " + uri + " " + problem);
    }
    throw Error(path + ": cannot import: " + first_line(error));
  }
  decode_meshopt_views(file);
  return file;
}

}  // namespace facet::io
