// import_scene(): picks the reader for a model file and finishes every imported scene the same
// way (every mesh validated, something to draw, a default camera). Runs once per model at load
// time; the Scene it returns is what the renderer reads.
#include "facet/import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "facet/error.hpp"
#include "import/guarded_files.hpp"
#include "import/import_internal.hpp"

namespace facet {
namespace io {

std::string lower_case(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

void warn(const ImportOptions& options, const std::string& message) {
  if (options.warn) {
    options.warn(message);
  } else {
    std::fprintf(stderr, "facet: warning: %s\n", message.c_str());
  }
}

std::string read_whole_file(const std::string& path) {
  check_model_file(path);
  return read_regular_file(path);
}

}  // namespace io

namespace {

// Throws "<path>: mesh N: ..." for the first mesh the renderer could not draw safely.
void validate_meshes(const Scene& scene, const std::string& path) {
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    try {
      scene.meshes[i]->validate();
    } catch (const Error& e) {
      std::string what = e.what();
      if (what.rfind("mesh: ", 0) == 0) what.erase(0, 6);
      throw Error(path + ": mesh " + std::to_string(i) + ": " + what);
    }
  }
}

bool has_primitives(const Scene& scene) {
  for (const SceneNode& node : scene.nodes) {
    for (const MeshInstance& instance : node.instances) {
      if (scene.meshes[instance.mesh]->primitive_count() > 0) return true;
    }
  }
  return false;
}

}  // namespace

Scene import_scene(const std::string& path, const ImportOptions& options) {
  io::check_model_file(path);
  const std::string extension = io::lower_case(std::filesystem::path(path).extension().string());
  // facet's own readers where it has one (PLY: assimp 5.2's hangs and crashes on damaged files;
  // STL: assimp's takes 460 bytes a triangle and one thread; OBJ of plain geometry, read
  // without assimp's fenced child, other OBJ by assimp; glTF through tinygltf, a reader made for
  // it: gltf_scene.cpp).
  Scene scene = extension == ".d"     ? io::import_d_scene(path, options)
                : extension == ".ply" ? io::import_ply_scene(path, options)
                : extension == ".stl" ? io::import_stl_scene(path, options)
                : extension == ".obj" ? io::import_obj_scene(path, options)
                : extension == ".gltf" || extension == ".glb"
                    ? io::import_gltf_scene(path, options)
                    : io::import_assimp_scene(path, options);
  validate_meshes(scene, path);
  // Line-only models (a wireframe OBJ) and point clouds still draw; a file of nothing does not.
  if (!has_primitives(scene)) throw Error(path + ": no triangles to draw");
  // Positions near the float limit (garbage read from a damaged binary file) give no camera that
  // can frame them: say so rather than fail later on a camera made of infinities.
  const Bounds bounds = scene.bounds();
  const glm::vec3 size = bounds.max - bounds.min;
  char span[96];
  std::snprintf(span, sizeof span, "(%g, %g, %g) to (%g, %g, %g)", bounds.min.x, bounds.min.y,
                bounds.min.z, bounds.max.x, bounds.max.y, bounds.max.z);
  if (!std::isfinite(size.x) || !std::isfinite(size.y) || !std::isfinite(size.z)) {
    throw Error(path + ": positions span more than a float can hold, " + span +
                ": a damaged file?");
  }
  // Framed for 16:9 here; a renderer of another aspect frames it again (scene_camera).
  scene.framing = Framing{};
  scene.camera = frame_scene(scene, 16.0f / 9.0f, *scene.framing);
  // A finite span can still be too wide to frame (1e35 apart: the far plane overflows).
  try {
    scene.camera.validate();
  } catch (const Error& e) {
    throw Error(path + ": positions span " + span + ", too far apart for a camera to frame (" +
                e.what() + "): a damaged file?");
  }
  if (!scene.has_file_lights) {
    // A file without lights would draw as a grey silhouette: light it as a photographer lights
    // a product, from the framing view (the lights a program that moves the camera may set
    // again for its own view).
    scene.lighting.lights = three_point_lights(scene.camera.forward(), scene.camera.right());
    scene.lighting.ambient = glm::vec3(0.12f);
  }
  return scene;
}

}  // namespace facet
