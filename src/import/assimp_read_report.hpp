// Internal to the assimp importer (import_assimp.cpp): what its fenced read hands back from the
// child process (assimp_fence.hpp). The scene travels in assimp's own binary dump ("assbin",
// which assimp's exporter writes and its importer reads), so no serializer of facet's has to
// follow assimp's scene; beside it, the few fields assimp 5.2's dump leaves out that the
// conversion reads, and what the import has to say about the read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet::io {

struct AssimpReadReport {
  std::string error;                  // why assimp's read failed; empty: it succeeded
  std::vector<std::string> refusals;  // files facet's rules refused it (GuardedIOSystem)
  std::uint64_t dropped_points = 0;   // points left out for a non-finite position
  std::string_view dump;              // the scene, assbin; empty when the read failed
  // What the dump leaves out, by index: each embedded texture's file name (aiTexture::mFilename,
  // by which materials name them) and each camera's orthographic half width
  // (aiCamera::mOrthographicWidth, 0 for a perspective camera).
  std::vector<std::string> texture_names;
  std::vector<float> orthographic_widths;
};

// Writes `report` to the file descriptor; false if a write failed (what was written then does
// not read back as a report: every part is preceded by its length).
[[nodiscard]] bool write_read_report(int fd, const AssimpReadReport& report);

// The report in `bytes` (its dump a view into them), or nothing when they are not a whole one.
std::optional<AssimpReadReport> parse_read_report(std::string_view bytes);

}  // namespace facet::io
