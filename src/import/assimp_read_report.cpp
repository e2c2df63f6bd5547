// The fenced assimp read's report (see assimp_read_report.hpp): a tag, then the points left out,
// the error, the refusals, the texture names, the orthographic widths and the dump, each text or
// blob as its length then its bytes, in the byte order of the process that wrote it, which is the
// one that reads it (a fork of it).
#include "import/assimp_read_report.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace facet::io {
namespace {

constexpr std::string_view kTag = "facet assimp read report 1\n";

bool write_all(int fd, const void* data, std::size_t size) {
  const char* from = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, from, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    from += written, size -= static_cast<std::size_t>(written);
  }
  return true;
}

bool write_u64(int fd, std::uint64_t value) { return write_all(fd, &value, sizeof value); }

bool write_bytes(int fd, std::string_view bytes) {
  return write_u64(fd, bytes.size()) && write_all(fd, bytes.data(), bytes.size());
}

// Reads from the front of `bytes`, which it consumes; false when they run out.
bool read_u64(std::string_view& bytes, std::uint64_t& value) {
  if (bytes.size() < sizeof value) return false;
  std::memcpy(&value, bytes.data(), sizeof value);
  bytes.remove_prefix(sizeof value);
  return true;
}

bool read_bytes(std::string_view& bytes, std::string_view& out) {
  std::uint64_t size = 0;
  if (!read_u64(bytes, size) || size > bytes.size()) return false;
  out = bytes.substr(0, static_cast<std::size_t>(size));
  bytes.remove_prefix(static_cast<std::size_t>(size));
  return true;
}

}  // namespace

bool write_read_report(int fd, const AssimpReadReport& report) {
  if (!write_all(fd, kTag.data(), kTag.size()) || !write_u64(fd, report.dropped_points) ||
      !write_bytes(fd, report.error) || !write_u64(fd, report.refusals.size())) {
    return false;
  }
  for (const std::string& refusal : report.refusals) {
    if (!write_bytes(fd, refusal)) return false;
  }
  if (!write_u64(fd, report.texture_names.size())) return false;
  for (const std::string& name : report.texture_names) {
    if (!write_bytes(fd, name)) return false;
  }
  const std::vector<float>& widths = report.orthographic_widths;
  return write_bytes(
             fd, {reinterpret_cast<const char*>(widths.data()), widths.size() * sizeof(float)}) &&
         write_bytes(fd, report.dump);
}

std::optional<AssimpReadReport> parse_read_report(std::string_view bytes) {
  if (bytes.substr(0, kTag.size()) != kTag) return std::nullopt;
  bytes.remove_prefix(kTag.size());
  AssimpReadReport report;
  std::string_view text;
  std::uint64_t refusals = 0, names = 0;
  if (!read_u64(bytes, report.dropped_points) || !read_bytes(bytes, text) ||
      !read_u64(bytes, refusals)) {
    return std::nullopt;
  }
  report.error = text;
  for (std::uint64_t i = 0; i < refusals; ++i) {
    if (!read_bytes(bytes, text)) return std::nullopt;
    report.refusals.emplace_back(text);
  }
  if (!read_u64(bytes, names)) return std::nullopt;
  for (std::uint64_t i = 0; i < names; ++i) {
    if (!read_bytes(bytes, text)) return std::nullopt;
    report.texture_names.emplace_back(text);
  }
  if (!read_bytes(bytes, text) || text.size() % sizeof(float) != 0) return std::nullopt;
  report.orthographic_widths.resize(text.size() / sizeof(float));
  if (!text.empty()) std::memcpy(report.orthographic_widths.data(), text.data(), text.size());
  if (!read_bytes(bytes, report.dump) || !bytes.empty()) return std::nullopt;
  return report;
}

}  // namespace facet::io
