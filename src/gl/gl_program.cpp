// GLSL programs (see gl_program.hpp).
#include "gl/gl_program.hpp"

#include <vector>

#include "facet/error.hpp"

namespace facet::gl {
namespace {

GLuint compile(GLenum stage, const std::string& defines, const std::string& source) {
  const std::string text = "#version 330 core\n" + defines + source;
  GLuint shader = glCreateShader(stage);
  const char* pointer = text.c_str();
  glShaderSource(shader, 1, &pointer, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1);
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    const char* name = stage == GL_VERTEX_SHADER     ? "vertex"
                       : stage == GL_GEOMETRY_SHADER ? "geometry"
                                                     : "fragment";
    throw Error(std::string("OpenGL backend: the ") + name + " shader does not compile (" +
                defines + "): " + log.data());
  }
  return shader;
}

}  // namespace

Program::Program(const std::string& defines, const std::string& vertex, const std::string& geometry,
                 const std::string& fragment) {
  std::vector<GLuint> shaders;
  shaders.push_back(compile(GL_VERTEX_SHADER, defines, vertex));
  if (!geometry.empty()) shaders.push_back(compile(GL_GEOMETRY_SHADER, defines, geometry));
  shaders.push_back(compile(GL_FRAGMENT_SHADER, defines, fragment));
  id_ = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(id_, s);
  glLinkProgram(id_);
  for (GLuint s : shaders) glDeleteShader(s);  // freed with the program
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1);
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    glDeleteProgram(id_);
    throw Error("OpenGL backend: the program does not link (" + defines + "): " + log.data());
  }
}

Program::~Program() { glDeleteProgram(id_); }

GLint Program::uniform(const char* name) {
  auto found = locations_.find(name);
  if (found != locations_.end()) return found->second;
  const GLint location = glGetUniformLocation(id_, name);
  locations_.emplace(name, location);
  return location;
}

}  // namespace facet::gl
