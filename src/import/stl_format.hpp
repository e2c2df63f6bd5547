// Internal to the STL reader: the bytes of a file as stl_format.cpp reads them (binary or ASCII),
// the welding that makes its triangle soup an indexed mesh (stl_weld.cpp), and what
// stl_import.cpp makes a scene of. Nothing here opens a file: a source hands out byte ranges, so
// the fuzz target and the tests feed bytes from memory and the importer reads a file in parallel
// chunks without holding the whole of it.
//
// The format (3D Systems, "StereoLithography Interface Specification", 1989):
//   binary: an 80-byte header, a little-endian uint32 triangle count n, then n records of 50
//           bytes: normal, three vertices (12 little-endian floats), a uint16 attribute. The
//           file is 84 + 50 n bytes. The header may start with "solid" (SolidWorks writes it).
//   ASCII:  solid NAME / facet normal nx ny nz / outer loop / vertex x y z (three) / endloop /
//           endfacet / ... / endsolid NAME, possibly several solids one after the other.
// Materialise's extension: "COLOR=" and four bytes in the header give the model's color.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <optional>
#include <string>
#include <vector>

#include "facet/mesh.hpp"

namespace facet::io::stl {

// Bytes [offset, offset + count) of the file into `out`; the reader never asks past `size`.
// Called from several threads at once (different ranges).
struct Source {
  std::uint64_t size = 0;
  std::function<void(std::uint64_t offset, std::size_t count, char* out)> read;
};

// More triangles than this cannot be indexed with 32-bit indices and welded in a table of
// 32-bit slots (stl_weld.cpp: 3 corners a triangle, a table of 2^31 slots at most).
constexpr std::uint64_t kMaxTriangles = 400'000'000;

struct Geometry {
  // Welded: every distinct position once (-0 and +0 alike), indexed triangles, no normals.
  Mesh mesh;
  // The file's facet normals can shade the model: every one finite and non-zero, and not all
  // the same (the rule assimp's FindInvalidData step applies, so images stay as they were).
  // Faceted shading then needs no normals at all: the renderer's face normals are the same.
  bool facet_normals_usable = false;
  std::size_t non_finite = 0;      // triangles left out for a vertex that is not finite
  std::size_t colored_facets = 0;  // binary facets whose attribute carries a color (not read)
  std::optional<glm::vec4> color;  // Materialise "COLOR=" in a binary header, linear
  bool binary = false;
};

// True when the bytes are a binary STL: exactly 84 + 50 n bytes, or not starting with "solid".
bool is_binary(const Source& source, const std::string& name);

// Reads the file; throws facet::Error "<name>: <what>" (binary: the triangle or count at fault;
// ASCII: "(line N)").
Geometry parse(const Source& source, const std::string& name);

// The corners (three a triangle, in order) welded into an indexed triangle mesh: identical
// positions become one vertex, numbered in order of first use, whatever the thread count.
// Taken by value and released before returning: the caller moves the corners in.
Mesh weld(std::vector<glm::vec3> corners);

// Runs body(task) for every task in [0, count) on all cores, one task per index, so the unit of
// work, never the schedule, decides what each writes (the core's parallel_tasks is internal to
// facet::core; the import layer calls oneTBB directly, as the worlds do).
template <class Body>
void parallel_tasks(int count, const Body& body) {
  tbb::parallel_for(
      tbb::blocked_range<int>(0, count, 1),
      [&](const tbb::blocked_range<int>& range) {
        for (int i = range.begin(); i < range.end(); ++i) body(i);
      },
      tbb::simple_partitioner());
}

// A source over bytes in memory (tests, the fuzz target); the bytes must outlive it.
Source memory_source(const char* data, std::size_t size);

}  // namespace facet::io::stl
