// STL read from a file into a scene to render (import_stl_scene); the parsing is
// stl_format.cpp's, the welding stl_weld.cpp's. The scene is what assimp's STL reader gave
// before facet read STL itself, so models look as they did: one node, one mesh, a white
// Blinn-Phong material with a white highlight (Materialise's header color instead when the file
// has one), faceted where the file's normals can shade it, smooth normals (with the crease
// angle) where they cannot.
//
// A binary file is read in parallel ranges straight from the file (pread), never whole: what
// the import holds is the corners it becomes, the weld's table and the mesh it makes.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "facet/error.hpp"
#include "facet/material.hpp"
#include "facet/mesh_tools.hpp"
#include "facet/scene.hpp"
#include "import/guarded_files.hpp"
#include "import/import_internal.hpp"
#include "import/stl_format.hpp"

namespace facet::io {
namespace {

// The file as a Source: ranges read with pread, from any thread. A read that fails leaves zeros
// and is remembered (`failed`), so no exception has to cross a worker thread.
struct FileSource {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{nullptr, &std::fclose};
  std::shared_ptr<std::atomic<bool>> failed = std::make_shared<std::atomic<bool>>(false);
  stl::Source source;
};

FileSource open_source(const std::string& path) {
  FileSource out;
  std::string problem;
  out.file.reset(open_regular_file(path, problem));
  if (!out.file) {
    throw Error(path + ": " +
                (problem.rfind("is ", 0) == 0 ? problem : "cannot be read (" + problem + ")"));
  }
  const int fd = fileno(out.file.get());
  struct stat status {};
  if (fstat(fd, &status) != 0)
    throw Error(path + ": cannot be read (" + std::strerror(errno) + ")");
  out.source.size = static_cast<std::uint64_t>(status.st_size);
  out.source.read = [fd, failed = out.failed](std::uint64_t offset, std::size_t count, char* to) {
    while (count > 0) {
      const ssize_t got = pread(fd, to, count, static_cast<off_t>(offset));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {  // an error, or the file shrank while read
        std::memset(to, 0, count);
        failed->store(true);
        return;
      }
      to += got, offset += static_cast<std::uint64_t>(got), count -= static_cast<std::size_t>(got);
    }
  };
  return out;
}

// assimp's STL material: diffuse and specular white (or the header's color), no shininess of
// its own, one-sided.
Material stl_material(const stl::Geometry& stl) {
  Material material;
  material.shading = ShadingModel::blinn_phong;
  material.base_color = stl.color.value_or(glm::vec4(1.0f));
  material.specular_color = glm::vec3(material.base_color);
  material.name = "DefaultMaterial";
  return material;
}

}  // namespace

Scene import_stl_scene(const std::string& path, const ImportOptions& options) {
  stl::Geometry stl;
  {
    FileSource file = open_source(path);
    stl = stl::parse(file.source, path);
    if (file.failed->load()) throw Error(path + ": cannot be read (changed while read?)");
  }
  if (stl.non_finite > 0) {
    warn(options, path + ": " + std::to_string(stl.non_finite) +
                      " triangles with a vertex that is not finite left out");
  }
  if (stl.colored_facets > 0) {
    warn(options, path + ": the colors of " + std::to_string(stl.colored_facets) +
                      " facets are not read (the model's color is used)");
  }
  // Faceted shading needs no vertex normals: the renderer's face normals are the file's.
  if (!stl.facet_normals_usable) compute_smooth_normals(stl.mesh, options.crease_angle_degrees);
  Material material = stl_material(stl);
  Scene scene;
  scene.add_object(std::move(stl.mesh), std::move(material), glm::mat4(1.0f),
                   std::filesystem::path(path).filename().string());
  return scene;
}

}  // namespace facet::io
