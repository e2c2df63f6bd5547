// Internal to model import (src/import/): the pieces import_scene() is
// built from. import.cpp dispatches on the file type and finishes every scene the same way.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "facet/import.hpp"
#include "facet/material.hpp"

namespace facet::io {

// The whole file as bytes; throws facet::Error "<path>: no such file" (or cannot be read).
std::string read_whole_file(const std::string& path);

// `.d` text to positions and triangle indices, no normals (parse_d adds them). Errors are
// "<name>:<line>: <what>".
Mesh parse_d_geometry(std::string_view text, const std::string& name);
// One node with one blinn-phong material drawing the `.d` model.
Scene import_d_scene(const std::string& path, const ImportOptions& options);

// PLY, ASCII or binary, to one mesh (ply_format.cpp): triangles fanned from the faces, or
// Topology::points when the file has none; no normals computed; colors linear. Errors are
// "<name>: <what> (line N)", or "(byte N)" in a binary body.
struct PlyGeometry {
  Mesh mesh;
  // Points: those left out for a position that is not finite. Triangles: used vertices whose
  // position is not finite, made NaN (the pipeline skips their triangles).
  std::size_t non_finite = 0;
  std::string texture_file;  // `comment TextureFile NAME`; empty: none
};
PlyGeometry parse_ply_geometry(std::string_view bytes, const std::string& name);
// One node drawing the PLY model, in the material assimp's reader gave it (ply_import.cpp).
Scene import_ply_scene(const std::string& path, const ImportOptions& options);

// STL, binary or ASCII, welded into one indexed mesh (stl_*.cpp), in the material assimp's
// reader gave it.
Scene import_stl_scene(const std::string& path, const ImportOptions& options);

// OBJ text of plain geometry (obj_plain.cpp says which) as one triangle mesh, a vertex per face
// corner in face order with the corners' normals and texture coordinates, as assimp's reader
// makes it; nothing when the file holds anything else, or anything assimp would change after
// reading: assimp's reader then reads the whole file.
std::optional<Mesh> read_plain_obj(std::string_view text);
// OBJ: plain geometry read by read_plain_obj, in the scene assimp's reader gave it
// (obj_import.cpp); every other file by assimp's reader.
Scene import_obj_scene(const std::string& path, const ImportOptions& options);

// glTF 2.0, .gltf and .glb, through tinygltf (gltf_*.cpp). The scene has meshes, materials,
// nodes, lights and cameras, but no default camera yet (import_scene frames it).
Scene import_gltf_scene(const std::string& path, const ImportOptions& options);

// Every format assimp reads. The scene has meshes, materials, nodes, lights and cameras, but no
// default camera yet (import_scene frames it).
Scene import_assimp_scene(const std::string& path, const ImportOptions& options);

// Sizes the file's header claims, checked against its real size before any reader allocates
// them (precheck.cpp: GLB chunks, OFF counts); throws facet::Error naming the field.
void precheck_model(const std::string& path);

// What every imported mesh goes through before it enters a Scene (mesh_finish.cpp): validated
// (errors "<where>: <what>"), non-finite positions reported, other bad attributes repaired,
// smooth normals (options.crease_angle_degrees) where it has none, identical vertices joined,
// tangents where `material` has a normal map. Lines and points are only validated and repaired.
void finish_mesh(Mesh& mesh, const Material& material, const ImportOptions& options,
                 const std::string& where);

// KHR_materials_pbrSpecularGlossiness factors to metallic-roughness (specular_glossiness.cpp):
// sets out.base_color, metallic and roughness.
void convert_specular_glossiness(glm::vec4 diffuse, glm::vec3 specular, float glossiness,
                                 Material& out);

// options.warn, or one "facet: warning:" line on stderr when it is not set.
void warn(const ImportOptions& options, const std::string& message);

// Lower-case ASCII copy (file extensions, case-insensitive file names).
std::string lower_case(std::string_view text);

}  // namespace facet::io
