// Uploads of meshes, textures and sampler states (see gpu_resources.hpp).
#include "gl/gpu_resources.hpp"

#include <algorithm>
#include <vector>

namespace facet::gl {
namespace {

GLenum mode_of(Topology topology) {
  switch (topology) {
    case Topology::triangle_strip:
      return GL_TRIANGLE_STRIP;  // odd triangles wound as facet's: GL 4.6 §10.1.7
    case Topology::lines:
      return GL_LINES;
    case Topology::points:
      return GL_POINTS;
    default:
      return GL_TRIANGLES;
  }
}

// One attribute array at `location`; none where the mesh has no such attribute (a disabled
// array reads the current generic attribute: GpuMesh::bind sets it).
template <class T>
void attribute(GLuint location, GLint components, const std::vector<T>& data, GLuint& buffer) {
  if (data.empty()) {
    glDisableVertexAttribArray(location);
    return;
  }
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
}

GLint gl_wrap(Wrap wrap) {
  switch (wrap) {
    case Wrap::clamp_to_edge:
      return GL_CLAMP_TO_EDGE;
    case Wrap::mirrored_repeat:
      return GL_MIRRORED_REPEAT;
    default:
      return GL_REPEAT;
  }
}

}  // namespace

void GpuMesh::bind() const {
  glBindVertexArray(vertex_array);
  // The values facet's vertex stage gives a missing attribute (pipeline/geometry/vertex.cpp).
  // They are the context's, not the vertex array's, so they are set for every draw.
  const float missing[5][4] = {
      {0, 0, 0, 1}, {0, 0, 0, 0}, {0, 0, 0, 1}, {1, 1, 1, 1}, {0, 0, 0, 0}};
  for (GLuint a = 0; a < 5; ++a) {
    if (buffers[a] == 0) glVertexAttrib4fv(a, missing[a]);
  }
}

void GpuMesh::draw() const {
  if (indexed) {
    glDrawElements(mode, count, GL_UNSIGNED_INT, nullptr);
  } else {
    glDrawArrays(mode, 0, count);
  }
}

GpuResources::~GpuResources() { clear(); }

void GpuResources::free_unused() {
  for (auto it = meshes_.begin(); it != meshes_.end();) {
    if (it->second.used + kKeepFrames >= frame_) {
      ++it;
      continue;
    }
    glDeleteVertexArrays(1, &it->second.gpu.vertex_array);
    glDeleteBuffers(6, it->second.gpu.buffers);
    it = meshes_.erase(it);
  }
  for (auto it = textures_.begin(); it != textures_.end();) {
    if (it->second.used + kKeepFrames >= frame_) {
      ++it;
      continue;
    }
    glDeleteTextures(1, &it->second.id);
    it = textures_.erase(it);
  }
}

void GpuResources::clear() {
  for (auto& [key, entry] : meshes_) {
    glDeleteVertexArrays(1, &entry.gpu.vertex_array);
    glDeleteBuffers(6, entry.gpu.buffers);
  }
  for (auto& [key, entry] : textures_) glDeleteTextures(1, &entry.id);
  for (auto& [key, id] : samplers_) glDeleteSamplers(1, &id);
  meshes_.clear();
  textures_.clear();
  samplers_.clear();
}

const GpuMesh& GpuResources::mesh(const std::shared_ptr<const Mesh>& mesh) {
  auto found = meshes_.find(mesh.get());
  if (found != meshes_.end()) {
    found->second.used = frame_;
    return found->second.gpu;
  }
  GpuMesh gpu;
  glGenVertexArrays(1, &gpu.vertex_array);
  glBindVertexArray(gpu.vertex_array);
  attribute(0, 3, mesh->positions, gpu.buffers[0]);
  attribute(1, 3, mesh->normals, gpu.buffers[1]);
  attribute(2, 2, mesh->texcoords, gpu.buffers[2]);
  attribute(3, 4, mesh->colors, gpu.buffers[3]);
  attribute(4, 4, mesh->tangents, gpu.buffers[4]);
  gpu.indexed = !mesh->indices.empty();
  if (gpu.indexed) {
    glGenBuffers(1, &gpu.buffers[5]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.buffers[5]);  // recorded in the vertex array
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh->indices.size() * sizeof(std::uint32_t)),
                 mesh->indices.data(), GL_STATIC_DRAW);
  }
  glBindVertexArray(0);
  gpu.mode = mode_of(mesh->topology);
  gpu.count = static_cast<GLsizei>(mesh->element_count());
  gpu.has_normals = !mesh->normals.empty();
  return meshes_.emplace(mesh.get(), MeshEntry{mesh, gpu, frame_}).first->second.gpu;
}

// facet's own mipmap chain is uploaded level by level rather than made by glGenerateMipmap, so
// trilinear filtering blends the very texels facet blends. facet stores rows top first with
// v = 0 at the bottom (texture.hpp); GL's first row is at t = 0, so rows go up reversed.
GLuint GpuResources::texture(const std::shared_ptr<const Texture>& texture) {
  auto found = textures_.find(texture.get());
  if (found != textures_.end()) {
    found->second.used = frame_;
    return found->second.id;
  }
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const bool floats = texture->format() == Texture::Format::rgba32f;
  const bool one_float = texture->format() == Texture::Format::r32f;
  // sRGB textures are decoded to linear before filtering, as facet samples them.
  const GLint internal = one_float         ? GL_R32F
                         : floats          ? GL_RGBA32F
                         : texture->srgb() ? GL_SRGB8_ALPHA8
                                           : GL_RGBA8;
  if (one_float) {  // read as (v, v, v, 1), as facet reads it
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, GL_RED);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, GL_RED);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_A, GL_ONE);
  }
  for (int l = 0; l < texture->level_count(); ++l) {
    const Texture::Level& level = texture->level(l);
    const std::size_t row = static_cast<std::size_t>(level.width) * (one_float ? 1 : 4);
    if (one_float) {
      std::vector<float> flipped(row * level.height);
      for (int y = 0; y < level.height; ++y) {
        std::copy_n(level.r32f.data() + (level.height - 1 - y) * row, row,
                    flipped.data() + y * row);
      }
      glTexImage2D(GL_TEXTURE_2D, l, internal, level.width, level.height, 0, GL_RED, GL_FLOAT,
                   flipped.data());
    } else if (floats) {
      std::vector<float> flipped(row * level.height);
      for (int y = 0; y < level.height; ++y) {
        std::copy_n(level.rgba32f.data() + (level.height - 1 - y) * row, row,
                    flipped.data() + y * row);
      }
      glTexImage2D(GL_TEXTURE_2D, l, internal, level.width, level.height, 0, GL_RGBA, GL_FLOAT,
                   flipped.data());
    } else {
      std::vector<std::uint8_t> flipped(row * level.height);
      for (int y = 0; y < level.height; ++y) {
        std::copy_n(level.rgba8.data() + (level.height - 1 - y) * row, row,
                    flipped.data() + y * row);
      }
      glTexImage2D(GL_TEXTURE_2D, l, internal, level.width, level.height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, flipped.data());
    }
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, texture->level_count() - 1);
  textures_.emplace(texture.get(), TextureEntry{texture, id, frame_});
  return id;
}

// Nearest and bilinear read the base level only (texture.hpp): GL's non-mipmapped minifying
// filters do the same. Trilinear is GL's LINEAR_MIPMAP_LINEAR.
GLuint GpuResources::sampler(const Sampler& s) {
  const auto key = std::make_tuple(s.filter, s.wrap_u, s.wrap_v);
  auto found = samplers_.find(key);
  if (found != samplers_.end()) return found->second;
  GLuint id = 0;
  glGenSamplers(1, &id);
  const GLint min = s.filter == Filter::nearest    ? GL_NEAREST
                    : s.filter == Filter::bilinear ? GL_LINEAR
                                                   : GL_LINEAR_MIPMAP_LINEAR;
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, min);
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER,
                      s.filter == Filter::nearest ? GL_NEAREST : GL_LINEAR);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, gl_wrap(s.wrap_u));
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, gl_wrap(s.wrap_v));
  samplers_.emplace(key, id);
  return id;
}

}  // namespace facet::gl
