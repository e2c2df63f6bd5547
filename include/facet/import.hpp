// Model import (facet::import): reads a 3D file into a facet Scene. glTF 2.0 (.gltf/.glb)
// through tinygltf, PLY and the classic course format `.d` through facet's own readers, other
// formats through assimp (OBJ+MTL, STL, 3DS, FBX, COLLADA, OFF, …). Models keep their own
// coordinates: nothing is rescaled or re-centred.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
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
  // Files the model references (textures, glTF buffers, OBJ material libraries, ...) must lie
  // inside the model's folder once symbolic links are resolved: a model from a stranger cannot
  // make the import read /etc/passwd or ~/secret.png. A reference outside is refused with one
  // warning and treated as missing (a texture draws as the checker; a buffer the geometry needs
  // fails the import). true lifts the rule, for models that share a texture folder beside them.
  // Whatever this says, only regular files are read: a directory, named pipe, socket or device
  // (/dev/zero) as a model or a referenced file is refused, saying which it is.
  bool allow_outside_paths = false;
  // glTF: the pose the model is drawn in. Unset: the rest pose (each node's own transform, each
  // morphed mesh at its default weights, skinned meshes as their joints' rest transforms place
  // them). Set: animation number `animation` (0-based) sampled at `time` seconds (clamped to
  // its first and last keys) moves nodes, joints and morph weights; skins and morph targets are
  // applied on the CPU, so the scene holds the posed meshes. A file without animations is
  // drawn at rest whatever the time; an `animation` the file does not have, or a time that is
  // not finite, throws facet::Error. Other formats are always drawn as they are stored.
  std::optional<double> time;
  int animation = 0;

  // The formats read through assimp (OBJ, STL, 3DS, FBX, COLLADA, OFF, ...) are first read by
  // assimp in a child process under these limits; only when that read ends normally (the file
  // read, or assimp's own error) does this process read it for real. A bug inside assimp (an
  // endless loop, a crash, an assertion, a huge allocation) is then one facet::Error naming the
  // file ("assimp crashed (signal 11, Segmentation fault) reading it"), never a hang or a dead
  // caller. Costs a second read of the file by assimp (docs/import.md). facet's own readers
  // (glTF, PLY, STL, .d) are not fenced: they are fuzzed instead.
  bool fence_assimp = true;
  // Wall-clock seconds the fenced read may take (the child's CPU time is held to the same,
  // plus one); a slower read fails with "took longer than N s". <= 0: no time limit.
  double import_time_limit_seconds = 60.0;
  // Address space the fenced read may add, in bytes; 0: half the machine's memory.
  std::uint64_t import_memory_limit_bytes = 0;
};

// Throws facet::Error (file, and line or index where known) if the file cannot be read. Sizes
// a binary header claims (a GLB chunk's length, an OFF file's counts) are checked against the
// file's real size before anything is allocated: a file that lies fails at once, naming the
// field. The
// scene's camera frames the whole model (frame_scene, 16:9, with Scene::framing set so that
// scene_camera frames it again for another aspect); a file without lights gets three
// lights around that view and an ambient term (three_point_lights), so it draws lit as it is.
Scene import_scene(const std::string& path, const ImportOptions& options = {});

// A glTF model read once and posed at any time without reading or decoding it again: what
// import_scene gives with ImportOptions::time set to each time, its materials and textures
// imported once and shared by every pose. For a viewer or a frame sequence of an animated
// model.
class AnimatedModel {
 public:
  // Reads a .gltf or .glb file as import_scene does (same checks and errors); throws
  // facet::Error for another format, or an options.animation the file does not have.
  explicit AnimatedModel(const std::string& path, const ImportOptions& options = {});
  ~AnimatedModel();
  AnimatedModel(AnimatedModel&&) noexcept;
  AnimatedModel& operator=(AnimatedModel&&) noexcept;

  // The number of animations in the file, and the length in seconds of options.animation (its
  // last key's time; 0 without animations).
  int animation_count() const;
  double duration() const;
  // The meshes and nodes of the pose at `seconds` of options.animation (clamped to its keys,
  // as ImportOptions::time), with the materials, lights and cameras of the file (no framing
  // camera or default lights: import_scene's scene has those, and they do not move).
  Scene pose(double seconds) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The `.d` format: optional header `data <vertices> <polygons>`, then one `x y z` line per
// vertex, then one `<n> i1 ... in` line per polygon (1-based indices, convex, fan-triangulated);
// `#` comments and blank lines allowed.
Mesh read_d_file(const std::string& path);
Mesh parse_d(const std::string& text, const std::string& name);  // name used in errors

}  // namespace facet
