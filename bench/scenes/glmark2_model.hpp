// glmark2's .3ds and .obj models as glmark2 loads them (GLMARK2_SCENES.md §1.4): positions, faces
// and texcoords read as stored, normals generated glmark2's way. Used by glmark2_scenes.cpp.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "facet/mesh.hpp"

namespace facet::bench {

struct Glmark2Model {
  std::vector<glm::vec3> positions;    // as stored: no axis swap, no scaling
  std::vector<glm::vec2> texcoords;    // from chunk 0x4140; empty when the file has none
  std::vector<std::uint32_t> indices;  // 3 per face, in file order (the winding is CCW)
  glm::vec3 bbox_min{0.0f};
  glm::vec3 bbox_max{0.0f};
};

// Reads a .3ds file: 0x4D4D/0x3D3D/0x4100 are containers, 0x4000 an object (name of at most
// 20 bytes, then sub-chunks), 0x4110 vertices, 0x4120 faces, 0x4140 texcoords; every other
// chunk is skipped by its length. Throws facet::Error (naming the file and offset) on a
// missing, truncated or inconsistent file.
Glmark2Model load_3ds(const std::string& path);

// Reads an .obj file as glmark2 does (bunny.obj): `v x y z` lines are positions, `f a b c`
// lines faces by 1-based index; every other line is skipped. Throws facet::Error (naming the
// file and line) on a missing or malformed file.
Glmark2Model load_obj(const std::string& path);

// glmark2's generated normals: each face's unit normal normalize(cross(b - a, c - a)) is added
// to the accumulators of its three FILE indices, then each accumulator is normalized. An
// unweighted average of face normals; vertices the file duplicates are not merged.
std::vector<glm::vec3> glmark2_normals(const Glmark2Model& model);

// What a benchmark draws. glmark2 de-indexes the model into a plain triangle list
// (glDrawArrays, 3 vertex-shader runs per face); deindex = true does the same, so facet does
// the same vertex work. Normals and texcoords only when asked for (and, for texcoords,
// present in the file).
struct Glmark2MeshOptions {
  bool normals = false;
  bool texcoords = false;
  bool deindex = true;
};
Mesh glmark2_mesh(const Glmark2Model& model, const Glmark2MeshOptions& options);

}  // namespace facet::bench
