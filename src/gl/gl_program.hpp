// GLSL programs: compiled from the shader sources (glsl_sources.hpp) with a list of #defines
// that choose the shading model and the per-draw options, as facet's raster loop is specialised
// per draw state. Each distinct list is compiled once and kept.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "gl/gl_api.hpp"

namespace facet::gl {

class Program {
 public:
  // Compiles and links; throws facet::Error with the driver's log on a GLSL error (a bug in
  // facet, not in the user's input). geometry may be empty: no geometry stage.
  Program(const std::string& defines, const std::string& vertex, const std::string& geometry,
          const std::string& fragment);
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  GLuint id() const { return id_; }
  // The location of a uniform, or -1 if the program does not use it (setting -1 is a no-op).
  GLint uniform(const char* name);

  // The frame whose constants the program holds (draw_uniforms.hpp's set_frame_uniforms sets
  // them once per frame, not per draw: a program keeps its uniforms between uses).
  std::uint64_t frame = 0;

 private:
  GLuint id_ = 0;
  std::map<std::string, GLint, std::less<>> locations_;
};

}  // namespace facet::gl
