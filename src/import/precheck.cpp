// Checks made before a model file is handed to a reader: sizes a header claims, held against
// the file's real size. Readers (assimp's among them) allocate what a header claims before
// they read a byte of it, so a header that lies costs gigabytes and seconds before the read
// fails; here it costs a few bytes read and one clear line naming the field. Each check reads
// only the header, never the whole file.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>

#include "facet/error.hpp"
#include "import/guarded_files.hpp"
#include "import/import_internal.hpp"

namespace facet::io {
namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

// Up to `count` bytes from `offset` on.
std::string read_at(std::FILE* file, std::uint64_t offset, std::size_t count) {
  std::string bytes(count, '\0');
  if (::fseeko(file, static_cast<off_t>(offset), SEEK_SET) != 0) return {};
  bytes.resize(std::fread(bytes.data(), 1, count, file));
  return bytes;
}

std::uint32_t little_u32(const unsigned char* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
         std::uint32_t(p[3]) << 24;
}

std::string chunk_name(const unsigned char* type) {
  if (little_u32(type) == 0x4E4F534Au) return "JSON";
  if (little_u32(type) == 0x004E4942u) return "BIN";
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%08x", little_u32(type));
  return hex;
}

// assimp 5.2's OFF reader allocates whatever the header declares before reading a vertex:
// invalid/OutOfMemory.off (309 bytes) declares 353535235358 vertices, and assimp claims
// gigabytes of memory before it fails. A vertex needs at least 6 bytes ("0 0 0\n") and a face
// 2, so a header the file cannot hold is refused here instead.
void check_off_header(const std::string& path, std::FILE* file, std::uint64_t size) {
  // The header is at the start; never read a big binary file.
  std::istringstream in(read_at(file, 0, 4096));
  std::string keyword, line;
  while (in >> keyword && keyword[0] == '#') std::getline(in, line);
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) return;
  unsigned long long vertices = 0, faces = 0;
  if (!(in >> vertices >> faces)) return;  // binary OFF or garbage: assimp will say
  if (vertices > size / 6 || faces > size / 2 || vertices * 6 + faces * 2 > size) {
    throw Error(path + ": cannot import: the OFF header declares " + std::to_string(vertices) +
                " vertices and " + std::to_string(faces) + " faces, more than a file of " +
                std::to_string(size) + " bytes can hold");
  }
}

// Binary glTF (GLB), whatever the file's extension (readers recognise it by its magic): a
// 12-byte header (magic "glTF", version, total length), then for version 2 chunks of
// (length, type, data), for version 1 a content length and format (the JSON scene) at bytes
// 12..19. assimp reads a JSON chunk into a buffer of the claimed size, zero-filled, before it
// reads the chunk: a claim of 4 GiB is 4 GiB of memory touched.
void check_glb_header(const std::string& path, std::FILE* file, std::uint64_t size) {
  const std::string head = read_at(file, 0, 20);
  const auto* header = reinterpret_cast<const unsigned char*>(head.data());
  const std::size_t got = head.size();
  if (got < 4 || little_u32(header) != 0x46546C67u) return;  // "glTF": not binary glTF
  auto fail = [&](const std::string& what) {
    throw Error(path + ": cannot import: " + what + " (the file has " + std::to_string(size) +
                " bytes)");
  };
  if (got < 12) fail("the GLB header is cut short");
  const std::uint32_t version = little_u32(header + 4);
  const std::uint32_t length = little_u32(header + 8);
  if (length > size) fail("the GLB header claims a length of " + std::to_string(length) + " bytes");
  if (version == 1) {
    if (got < 20) fail("the GLB version 1 header is cut short");
    const std::uint64_t content = little_u32(header + 12);
    if (20 + content > length)
      fail("the GLB scene (JSON) claims " + std::to_string(content) +
           " bytes, more than the header's length of " + std::to_string(length) + " holds");
    return;
  }
  // The JSON chunk and the BIN chunk after it, each within the header's length (itself within
  // the file). Readers read these two; the specification has them skip any further chunk, and
  // walking those (a file may hold millions of empty ones) would cost more than it protects.
  std::uint64_t offset = 12;
  for (int chunk = 0; chunk < 2 && offset < length; ++chunk) {
    const std::string bytes = read_at(file, offset, 8);
    const auto* chunk_head = reinterpret_cast<const unsigned char*>(bytes.data());
    if (offset + 8 > length || bytes.size() != 8)
      fail("GLB chunk " + std::to_string(chunk) + "'s header is cut short at byte " +
           std::to_string(offset));
    const std::uint64_t claimed = little_u32(chunk_head);
    if (offset + 8 + claimed > length) {
      fail("GLB chunk " + std::to_string(chunk) + " (" + chunk_name(chunk_head + 4) + ") claims " +
           std::to_string(claimed) + " bytes, but only " + std::to_string(length - offset - 8) +
           " follow it within the header's length of " + std::to_string(length));
    }
    offset += 8 + claimed;
  }
}

}  // namespace

void precheck_model(const std::string& path) {
  std::string problem;
  const File file(open_regular_file(path, problem), std::fclose);
  if (!file) return;  // the reader will say what is wrong
  if (::fseeko(file.get(), 0, SEEK_END) != 0) return;
  const auto size = static_cast<std::uint64_t>(::ftello(file.get()));
  check_off_header(path, file.get(), size);
  check_glb_header(path, file.get(), size);
}

}  // namespace facet::io
