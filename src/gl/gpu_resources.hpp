// What the GL twin keeps on the GPU between frames: each mesh's vertex arrays, each texture with
// facet's own mipmap chain, and one sampler object per (filter, wrap) combination. Meshes and
// textures do not change once in a scene (scene.hpp), so each is uploaded the first time it is
// drawn and found again by its address; the shared pointer held keeps the address from being
// reused by another mesh while the entry lives. Entries no frame has used for kKeepFrames frames
// are freed, so that a long session over changing scenes does not keep every one it saw.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <tuple>

#include "facet/mesh.hpp"
#include "facet/texture.hpp"
#include "gl/gl_api.hpp"

namespace facet::gl {

struct GpuMesh {
  GLuint vertex_array = 0;
  GLuint buffers[6] = {};  // positions, normals, texcoords, colors, tangents, indices
  GLenum mode = GL_TRIANGLES;
  GLsizei count = 0;  // vertices or indices drawn
  bool indexed = false;
  bool has_normals = false;

  void bind() const;  // the vertex array and the constants of missing attributes
  void draw() const;
};

class GpuResources {
 public:
  GpuResources() = default;
  ~GpuResources();
  GpuResources(const GpuResources&) = delete;
  GpuResources& operator=(const GpuResources&) = delete;

  // Frames an unused entry is kept: a level of detail that comes back a moment later (the
  // viewer moving to and fro) is not uploaded again.
  static constexpr std::uint64_t kKeepFrames = 60;

  // Starts a frame: what is used from now on counts as used in it.
  void begin_frame(std::uint64_t frame) { frame_ = frame; }
  // Frees what no frame has used for kKeepFrames frames.
  void free_unused();

  const GpuMesh& mesh(const std::shared_ptr<const Mesh>& mesh);
  GLuint texture(const std::shared_ptr<const Texture>& texture);
  GLuint sampler(const Sampler& sampler);
  // Forgets everything (the scene is gone): frees the GPU copies.
  void clear();

 private:
  struct MeshEntry {
    std::shared_ptr<const Mesh> owner;
    GpuMesh gpu;
    std::uint64_t used = 0;  // the last frame that drew it
  };
  struct TextureEntry {
    std::shared_ptr<const Texture> owner;
    GLuint id = 0;
    std::uint64_t used = 0;
  };
  std::uint64_t frame_ = 0;
  std::map<const Mesh*, MeshEntry> meshes_;
  std::map<const Texture*, TextureEntry> textures_;
  std::map<std::tuple<Filter, Wrap, Wrap>, GLuint> samplers_;
};

}  // namespace facet::gl
