// Texture files referenced by an imported model: found next to the model (case-insensitively,
// Windows paths too) or embedded in it, each file decoded once; a file outside the model's
// folder or one that is not a regular file is refused (guarded_files.hpp) and draws the checker.
// Runs at load time; the textures end up in Scene::textures and the materials' maps.
#include <assimp/scene.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "import/import_assimp.hpp"

namespace facet::io {
namespace {

namespace fs = std::filesystem;

bool path_exists(const fs::path& p) {
  std::error_code error;
  return fs::exists(p, error);
}

// The entry of dir whose name matches name ignoring case, or an empty path.
fs::path find_ignoring_case(const fs::path& dir, const std::string& name) {
  std::error_code error;
  const std::string wanted = lower_case(name);
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    if (lower_case(it->path().filename().string()) == wanted) return it->path();
  }
  return {};
}

// base/relative, walking each component case-insensitively (models made on Windows or macOS
// often spell "Textures/Wood.PNG" what is stored as "textures/wood.png").
fs::path resolve_ignoring_case(const fs::path& base, const fs::path& relative) {
  if (relative.empty()) return {};
  fs::path current = base.empty() ? fs::path(".") : base;
  for (const fs::path& part : relative) {
    if (part == "." || part.empty()) continue;
    if (part == "..") {
      current /= part;
      continue;
    }
    fs::path exact = current / part;
    std::error_code error;
    if (fs::exists(exact, error)) {
      current = exact;
      continue;
    }
    fs::path match = find_ignoring_case(current, part.string());
    if (match.empty()) return {};
    current = match;
  }
  // Whatever it is: a special file is reported as what it is (ReferenceRules), not as missing.
  std::error_code error;
  return fs::exists(current, error) ? current : fs::path();
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(c | 0x20);
  return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

// glTF image URIs are percent-encoded ("my%20texture.png").
std::string percent_decoded(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex_value(text[i + 1]) >= 0 &&
        hex_value(text[i + 2]) >= 0) {
      out += static_cast<char>(hex_value(text[i + 1]) * 16 + hex_value(text[i + 2]));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

std::string file_name_of(const std::string& reference) {
  std::string slashed = reference;
  std::replace(slashed.begin(), slashed.end(), '\\', '/');
  return fs::path(slashed).filename().string();
}

}  // namespace

TextureLoader::TextureLoader(const aiScene& scene, const std::string& model_path,
                             const ImportOptions& options)
    : scene_(scene),
      model_path_(model_path),
      model_dir_(fs::path(model_path).parent_path().string()),
      options_(options),
      rules_(model_path, options) {}

std::string TextureLoader::resolve(const std::string& reference, std::string& refusal) const {
  std::string slashed = reference;
  std::replace(slashed.begin(), slashed.end(), '\\', '/');
  const fs::path base(model_dir_);
  // A file found is used only if the rules allow it; the first refusal is kept to say why a
  // reference that found nothing else is missing.
  auto allowed = [&](const fs::path& found) {
    if (found.empty()) return false;
    const std::string why = rules_.refusal(found);
    if (why.empty()) return true;
    if (refusal.empty()) refusal = why;
    return false;
  };
  for (const std::string& candidate : {slashed, percent_decoded(slashed)}) {
    fs::path p(candidate);
    if (p.is_absolute() && path_exists(p) && allowed(p)) return p.string();
    if (p.is_absolute()) p = p.relative_path();
    fs::path found = resolve_ignoring_case(base, p);
    if (allowed(found)) return found.string();
    // An absolute path from another machine ("C:/work/tex/wood.png"): try the file name alone.
    found = resolve_ignoring_case(base, p.filename());
    if (allowed(found)) return found.string();
  }
  return {};
}

int TextureLoader::embedded_index(const std::string& reference) const {
  if (!scene_.mTextures) return -1;
  if (!reference.empty() && reference[0] == '*') {
    long index = -1;
    try {
      index = std::stol(reference.substr(1));
    } catch (const std::exception&) {
      return -1;
    }
    return index >= 0 && index < static_cast<long>(scene_.mNumTextures) ? static_cast<int>(index)
                                                                        : -1;
  }
  const std::string name = lower_case(file_name_of(reference));
  for (unsigned i = 0; i < scene_.mNumTextures; ++i) {
    const aiTexture* t = scene_.mTextures[i];
    if (t && !name.empty() && lower_case(file_name_of(t->mFilename.C_Str())) == name) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

std::shared_ptr<const Texture> TextureLoader::decode_embedded(int index, bool srgb) const {
  const aiTexture& t = *scene_.mTextures[index];
  const std::string name = "embedded:" + std::to_string(index);
  if (!t.pcData) throw Error(name + ": no data");
  if (t.mHeight == 0) {  // compressed: mWidth is the size in bytes of a PNG/JPEG/... file
    return load_texture_from_memory(reinterpret_cast<const std::uint8_t*>(t.pcData), t.mWidth, srgb,
                                    name);
  }
  // Uncompressed texels are stored as BGRA.
  const std::size_t count = static_cast<std::size_t>(t.mWidth) * t.mHeight;
  std::vector<std::uint8_t> rgba(count * 4);
  for (std::size_t i = 0; i < count; ++i) {
    const aiTexel& texel = t.pcData[i];
    rgba[i * 4 + 0] = texel.r;
    rgba[i * 4 + 1] = texel.g;
    rgba[i * 4 + 2] = texel.b;
    rgba[i * 4 + 3] = texel.a;
  }
  return Texture::from_rgba8(static_cast<int>(t.mWidth), static_cast<int>(t.mHeight),
                             std::move(rgba), srgb, name);
}

std::shared_ptr<const Texture> TextureLoader::load(const std::string& reference, bool srgb) {
  const int embedded = embedded_index(reference);
  auto [where, first_time] = resolved_.try_emplace(reference);
  if (first_time) {
    std::string refusal;
    where->second =
        embedded >= 0 ? std::to_string(embedded).insert(0, 1, '*') : resolve(reference, refusal);
    if (where->second.empty() && !refusal.empty()) warn_once(reference, refusal);
  }
  const std::string& key = where->second;
  if (key.empty()) {
    warn_once(reference, "is missing");
    return nullptr;
  }
  auto [it, added] = cache_.try_emplace({key, srgb});
  if (!added) return it->second;
  try {
    if (embedded >= 0) {
      it->second = decode_embedded(embedded, srgb);
    } else {
      // Read as the rules allow (a regular file, opened without blocking), then decoded.
      const std::string bytes = read_regular_file(key);
      it->second = load_texture_from_memory(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                            bytes.size(), srgb, key);
    }
  } catch (const Error& e) {
    warn_once(reference, std::string("cannot be read (") + e.what() + ")");
  }
  return it->second;
}

void TextureLoader::warn_once(const std::string& reference, const std::string& problem) {
  if (!warned_.insert(reference).second) return;
  warn(options_, model_path_ + ": texture " + reference + " " + problem + "; drawing a checker");
}

}  // namespace facet::io
