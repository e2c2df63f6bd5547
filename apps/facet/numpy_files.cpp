// NumPy .npy and .npz files (see numpy_files.hpp). The formats: numpy.lib.format (NEP 1) for
// .npy; PKWARE's APPNOTE.TXT 6.3 (local file header 4.3.7, central directory 4.3.12, end of
// central directory 4.3.16) for the zip around them.
#include "numpy_files.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

#include "facet/error.hpp"

namespace facet::cli {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the arrays are written as they lie in memory and declared little-endian");

// The .npy header: magic, version 1.0, its length, then a Python dict literal padded with
// spaces to a newline so that the values start on a 64-byte boundary (what NumPy writes).
std::string npy_header(const NumpyArray& array) {
  std::string shape;
  for (std::size_t extent : array.shape) {
    shape += (shape.empty() ? "" : ", ") + std::to_string(extent);
  }
  if (array.shape.size() == 1) shape += ',';  // a Python tuple of one: "(5,)"
  std::string dict =
      "{'descr': '" + array.dtype + "', 'fortran_order': False, 'shape': (" + shape + "), }";
  constexpr std::size_t kPrefix = 10;  // magic (6), version (2), header length (2)
  std::size_t length = kPrefix + dict.size() + 1;
  dict.append((64 - length % 64) % 64, ' ');
  dict += '\n';
  std::string header = "\x93NUMPY";
  header += '\x01';
  header += '\x00';
  header += static_cast<char>(dict.size() & 0xff);
  header += static_cast<char>(dict.size() >> 8);
  return header + dict;
}

void put16(std::string& out, std::uint32_t v) {
  out += static_cast<char>(v & 0xff);
  out += static_cast<char>((v >> 8) & 0xff);
}
void put32(std::string& out, std::uint32_t v) {
  put16(out, v & 0xffff);
  put16(out, v >> 16);
}

// One member's header fields: stored (method 0), no flags, a fixed date (1980-01-01) so the
// same arrays always give the same bytes.
struct Member {
  std::string name;
  std::uint32_t crc = 0;
  std::uint32_t size = 0;
  std::uint32_t offset = 0;  // of its local header
};

void put_common(std::string& out, const Member& m) {
  put16(out, 20);      // version needed to extract: 2.0
  put16(out, 0);       // flags
  put16(out, 0);       // method: stored
  put16(out, 0);       // time 00:00
  put16(out, 0x0021);  // date 1980-01-01
  put32(out, m.crc);
  put32(out, m.size);  // compressed
  put32(out, m.size);  // uncompressed
  put16(out, static_cast<std::uint32_t>(m.name.size()));
  put16(out, 0);  // extra field length
}

std::uint32_t crc_of(std::uint32_t crc, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const Bytef*>(data);
  while (bytes > 0) {  // zlib takes at most a uInt at a time
    uInt chunk = static_cast<uInt>(std::min<std::size_t>(bytes, 1u << 30));
    crc = static_cast<std::uint32_t>(crc32(crc, p, chunk));
    p += chunk, bytes -= chunk;
  }
  return crc;
}

}  // namespace

void write_npy(std::FILE* file, const NumpyArray& array) {
  std::string header = npy_header(array);
  std::fwrite(header.data(), 1, header.size(), file);
  std::fwrite(array.data, 1, array.bytes, file);
}

void write_npz(std::FILE* file, const std::vector<NumpyArray>& arrays, const std::string& name) {
  // Offsets and sizes are 32-bit without ZIP64: checked before anything is written.
  constexpr std::uint64_t kZipLimit = std::numeric_limits<std::uint32_t>::max();
  constexpr std::uint64_t kLocalHeader = 30, kDirectoryEntry = 46, kEnd = 22;
  std::uint64_t total = kEnd;
  for (const NumpyArray& array : arrays) {
    std::uint64_t name_size = array.name.size() + 4;
    total +=
        kLocalHeader + kDirectoryEntry + 2 * name_size + npy_header(array).size() + array.bytes;
  }
  if (total > kZipLimit) {
    throw Error(name + ": " + std::to_string(total >> 20) +
                " MiB of arrays is more than an .npz without ZIP64 holds (4 GiB); write .npy " +
                "files instead");
  }
  std::vector<Member> members;
  std::uint32_t offset = 0;
  for (const NumpyArray& array : arrays) {
    std::string header = npy_header(array);
    Member m;
    m.name = array.name + ".npy";
    m.size = static_cast<std::uint32_t>(header.size() + array.bytes);
    m.offset = offset;
    m.crc = crc_of(crc_of(0, header.data(), header.size()), array.data, array.bytes);
    std::string local;
    put32(local, 0x04034b50);
    put_common(local, m);
    local += m.name;
    std::fwrite(local.data(), 1, local.size(), file);
    std::fwrite(header.data(), 1, header.size(), file);
    std::fwrite(array.data, 1, array.bytes, file);
    offset += static_cast<std::uint32_t>(local.size()) + m.size;
    members.push_back(m);
  }
  std::string directory;
  for (const Member& m : members) {
    put32(directory, 0x02014b50);
    put16(directory, 20);  // version made by: 2.0, MS-DOS attributes
    put_common(directory, m);
    put16(directory, 0);  // comment length
    put16(directory, 0);  // disk number
    put16(directory, 0);  // internal attributes
    put32(directory, 0);  // external attributes
    put32(directory, m.offset);
    directory += m.name;
  }
  std::string end;
  put32(end, 0x06054b50);
  put16(end, 0);  // this disk
  put16(end, 0);  // the disk the directory starts on
  put16(end, static_cast<std::uint32_t>(members.size()));
  put16(end, static_cast<std::uint32_t>(members.size()));
  put32(end, static_cast<std::uint32_t>(directory.size()));
  put32(end, offset);
  put16(end, 0);  // comment length
  std::fwrite(directory.data(), 1, directory.size(), file);
  std::fwrite(end.data(), 1, end.size(), file);
}

}  // namespace facet::cli
