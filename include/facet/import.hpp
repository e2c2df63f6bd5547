// Model import (facet::import): reads a 3D file into a facet Scene. Formats through assimp
// (OBJ+MTL, glTF 2.0 .gltf/.glb, STL, 3DS, FBX, COLLADA, OFF, …) and facet's own readers for PLY
// and the classic course format `.d`. Models keep their own coordinates: nothing is rescaled or
// re-centred.
#pragma once

#include <functional>
#include <string>

#include "facet/mesh_tools.hpp"  // normals and tangents for meshes that come without
#include "facet/scene.hpp"

namespace facet {

struct ImportOptions {
  // Meshes without normals get smooth vertex normals, split where faces meet at more than
  // this angle (area-weighted).
  float crease_angle_degrees = 80.0f;
  // Called once per problem that does not stop the import (a missing texture, replaced by a
  // visible checker). Default: print one line to stderr.
  std::function<void(const std::string&)> warn;
};

// Throws facet::Error (file, and line or index where known) if the file cannot be read. The
// scene's camera frames the whole model (frame_scene, 16:9, with Scene::framing set so that
// scene_camera frames it again for another aspect); a file without lights gets three
// lights around that view and an ambient term (three_point_lights), so it draws lit as it is.
Scene import_scene(const std::string& path, const ImportOptions& options = {});

// The `.d` format: optional header `data <vertices> <polygons>`, then one `x y z` line per
// vertex, then one `<n> i1 ... in` line per polygon (1-based indices, convex, fan-triangulated);
// `#` comments and blank lines allowed.
Mesh read_d_file(const std::string& path);
Mesh parse_d(const std::string& text, const std::string& name);  // name used in errors

}  // namespace facet
