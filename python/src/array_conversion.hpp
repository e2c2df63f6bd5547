// Arguments from Python, checked, and arrays back to it (python/src). Every binding reads its
// array and vector arguments through these: anything numpy.asarray takes, of the shape and kind
// the argument needs, or one facet::Error that names the function and the argument
// ("add_mesh: faces must be an (M, 3) integer array, got shape (5, 4)"). Results go back as
// NumPy arrays that take over a std::vector's buffer, without a copy.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "facet/texture.hpp"

namespace facet::python {

namespace py = pybind11;

// Where a value comes from, for messages: {"add_mesh", "faces"} reads "add_mesh: faces".
struct Argument {
  const char* function;
  const char* name;
  std::string text() const { return std::string(function) + ": " + name; }
};

// Per-vertex attributes (vertices, normals, uvs): the N rows of an (N, C) array of real numbers
// (float or integer dtype), each a finite float32. rows < 0 takes any N; otherwise N must be
// rows (a row per vertex).
std::vector<glm::vec2> vec2_rows(py::handle value, const Argument& argument, std::ptrdiff_t rows);
std::vector<glm::vec3> vec3_rows(py::handle value, const Argument& argument, std::ptrdiff_t rows);

// Triangles as indices from an (M, 3) integer array, each in [0, vertex_count).
std::vector<std::uint32_t> triangle_indices(py::handle value, const Argument& argument,
                                            std::size_t vertex_count);

// Vertex colors as linear RGBA from an (N, 3) or (N, 4) array: float in [0, 1] is linear (as
// every float color in facet), uint8 is sRGB-encoded (as 8-bit images are; decoded here). A
// missing alpha is 1; alpha is linear either way.
std::vector<glm::vec4> vertex_colors(py::handle value, const Argument& argument, std::size_t rows);

// A texture from an (H, W, 3) or (H, W, 4) uint8 image, row 0 at the top, sRGB-encoded color.
std::shared_ptr<const Texture> texture_image(py::handle value, const Argument& argument);

// An RGBA8 image, row-major, top row first, from an (H, W, 3) or (H, W, 4) uint8 array.
struct Rgba8Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};
Rgba8Image rgba8_image(py::handle value, const Argument& argument);

// A 3x3 or 4x4 matrix (row-major as written on paper: m[row][column]), finite.
glm::mat3 matrix3(py::handle value, const Argument& argument);
glm::mat4 matrix4(py::handle value, const Argument& argument);

// Small vectors: a sequence of 3 finite numbers; a color of 3 or 4 (alpha 1 when missing).
glm::vec3 vec3(py::handle value, const Argument& argument);
glm::vec4 rgba(py::handle value, const Argument& argument);
// A finite float; a whole number.
float number(py::handle value, const Argument& argument);
int integer(py::handle value, const Argument& argument);

// "(1, 0.5, 0)", for messages and reprs.
std::string to_text(glm::vec3 v);
std::string to_text(glm::vec4 v);

// A float as the shortest decimal that reads back as it (0.6f is 0.6, not 0.6000000238...).
py::float_ to_python(float v);
py::tuple to_tuple(glm::vec3 v);
py::tuple to_tuple(glm::vec4 v);
// A 4x4 float64 array, row-major (m[row][column]).
py::array_t<double> to_numpy(const glm::mat4& m);

// An array over the vector's buffer, which it takes over (freed with the array): no copy.
template <class T>
py::array_t<T> adopt(std::vector<T>&& data, std::vector<py::ssize_t> shape) {
  auto owned = std::make_unique<std::vector<T>>(std::move(data));
  T* pointer = owned->data();
  py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<T>*>(p); });
  owned.release();  // the capsule owns it now
  return py::array_t<T>(std::move(shape), pointer, owner);
}

}  // namespace facet::python
