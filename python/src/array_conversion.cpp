// Checked conversions between Python values and facet's types (see array_conversion.hpp).
#include "array_conversion.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "facet/color.hpp"
#include "facet/error.hpp"

namespace facet::python {
namespace {

// numpy.asarray(value); what numpy cannot read as an array is the caller's error.
py::array as_array(py::handle value, const Argument& argument) {
  try {
    return py::module_::import("numpy").attr("asarray")(value).cast<py::array>();
  } catch (const py::error_already_set& e) {
    throw Error(argument.text() + ": cannot be read as an array (" + e.what() + ")");
  }
}

bool is_real(const py::array& a) {
  const char kind = a.dtype().kind();
  return kind == 'f' || kind == 'i' || kind == 'u';
}

bool is_integer(const py::array& a) {
  const char kind = a.dtype().kind();
  return kind == 'i' || kind == 'u';
}

bool is_uint8(const py::array& a) { return a.dtype().kind() == 'u' && a.dtype().itemsize() == 1; }

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    text += (i > 0 ? ", " : "") + std::to_string(a.shape(i));
  }
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// "got dtype <U1" when the kind of values is wrong, else "got shape (5, 4)".
std::string got(const py::array& a, bool kind_ok) {
  if (!kind_ok) return "got dtype " + std::string(py::str(a.dtype()));
  return "got shape " + shape_text(a);
}

template <class Values>
std::string values_text(const Values& values, int count) {
  std::ostringstream out;
  out << "(";
  for (int i = 0; i < count; ++i) out << (i > 0 ? ", " : "") << values[i];
  out << ")";
  return out.str();
}

// Values are read as float64 and checked before they become float: a value beyond float's range
// is an error like NaN, not a NumPy overflow warning and an infinity.
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

bool finite_float(double v) {
  return std::isfinite(v) && std::abs(v) <= std::numeric_limits<float>::max();
}

// The rows of an (N, C) real array, finite (N = rows unless rows < 0).
template <int C>
std::vector<glm::vec<C, float>> float_rows(py::handle value, const Argument& argument,
                                           std::ptrdiff_t rows) {
  const py::array a = as_array(value, argument);
  const bool kind_ok = is_real(a);
  if (!kind_ok || a.ndim() != 2 || a.shape(1) != C || (rows >= 0 && a.shape(0) != rows)) {
    std::string want = argument.text() + " must be an (N, " + std::to_string(C) + ") float array";
    if (rows >= 0) want += " with N = " + std::to_string(rows) + " (a row per vertex)";
    throw Error(want + ", " + got(a, kind_ok));
  }
  const DoubleArray d = DoubleArray::ensure(a);
  const double* data = d.data();
  std::vector<glm::vec<C, float>> out(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t row = 0; row < out.size(); ++row) {
    const double* values = data + row * C;
    for (int c = 0; c < C; ++c) {
      if (!finite_float(values[c])) {
        throw Error(argument.text() + "[" + std::to_string(row) +
                    "] is not a finite float32: " + values_text(values, C));
      }
      out[row][c] = static_cast<float>(values[c]);
    }
  }
  return out;
}

template <class Index>
void copy_indices(const py::array& a, const Argument& argument, std::size_t vertex_count,
                  std::vector<std::uint32_t>& out) {
  using IndexArray = py::array_t<Index, py::array::c_style | py::array::forcecast>;
  const IndexArray indices = IndexArray::ensure(a);
  const Index* data = indices.data();
  out.resize(static_cast<std::size_t>(indices.size()));
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Index index = data[i];
    if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count) {
      throw Error(argument.text() + "[" + std::to_string(i / 3) + ", " + std::to_string(i % 3) +
                  "] is " + std::to_string(index) + ", out of range for " +
                  std::to_string(vertex_count) + " vertices");
    }
    out[i] = static_cast<std::uint32_t>(index);
  }
}

}  // namespace

std::vector<glm::vec2> vec2_rows(py::handle value, const Argument& argument, std::ptrdiff_t rows) {
  return float_rows<2>(value, argument, rows);
}

std::vector<glm::vec3> vec3_rows(py::handle value, const Argument& argument, std::ptrdiff_t rows) {
  return float_rows<3>(value, argument, rows);
}

std::vector<std::uint32_t> triangle_indices(py::handle value, const Argument& argument,
                                            std::size_t vertex_count) {
  const py::array a = as_array(value, argument);
  const bool kind_ok = is_integer(a);
  if (!kind_ok || a.ndim() != 2 || a.shape(1) != 3) {
    throw Error(argument.text() + " must be an (M, 3) integer array, " + got(a, kind_ok));
  }
  if (vertex_count > std::numeric_limits<std::uint32_t>::max()) {
    throw Error(argument.function + std::string(": more than 2^32 - 1 vertices"));
  }
  std::vector<std::uint32_t> out;
  if (a.dtype().kind() == 'u') {
    copy_indices<std::uint64_t>(a, argument, vertex_count, out);
  } else {
    copy_indices<std::int64_t>(a, argument, vertex_count, out);
  }
  return out;
}

std::vector<glm::vec4> vertex_colors(py::handle value, const Argument& argument, std::size_t rows) {
  const py::array a = as_array(value, argument);
  const bool kind_ok = a.dtype().kind() == 'f' || is_uint8(a);
  if (!kind_ok || a.ndim() != 2 || (a.shape(1) != 3 && a.shape(1) != 4) ||
      static_cast<std::size_t>(a.shape(0)) != rows) {
    throw Error(argument.text() + " must be an (N, 3) or (N, 4) array of float in [0, 1] or of " +
                "uint8, with N = " + std::to_string(rows) + " (a row per vertex), " +
                got(a, kind_ok));
  }
  const int channels = static_cast<int>(a.shape(1));
  std::vector<glm::vec4> out(rows, glm::vec4(1.0f));
  if (is_uint8(a)) {
    std::array<float, 256> linear{};  // sRGB code -> linear, once per call
    for (int code = 0; code < 256; ++code)
      linear[code] = srgb_to_linear(glm::vec3(code / 255.0f)).x;
    using Uint8Array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;
    const Uint8Array bytes = Uint8Array::ensure(a);
    const std::uint8_t* data = bytes.data();
    for (std::size_t row = 0; row < rows; ++row) {
      const std::uint8_t* values = data + row * channels;
      out[row] = {linear[values[0]], linear[values[1]], linear[values[2]],
                  channels == 4 ? values[3] / 255.0f : 1.0f};
    }
    return out;
  }
  const DoubleArray d = DoubleArray::ensure(a);
  const double* data = d.data();
  for (std::size_t row = 0; row < rows; ++row) {
    const double* values = data + row * channels;
    for (int c = 0; c < channels; ++c) {
      if (!(values[c] >= 0.0 && values[c] <= 1.0)) {
        throw Error(argument.text() + "[" + std::to_string(row) +
                    "] is outside [0, 1]: " + values_text(values, channels));
      }
      out[row][c] = static_cast<float>(values[c]);
    }
  }
  return out;
}

Rgba8Image rgba8_image(py::handle value, const Argument& argument) {
  const py::array a = as_array(value, argument);
  const bool kind_ok = is_uint8(a);
  if (!kind_ok || a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4) || a.shape(0) < 1 ||
      a.shape(1) < 1) {
    throw Error(argument.text() + " must be an (H, W, 3) or (H, W, 4) uint8 image, " +
                got(a, kind_ok));
  }
  if (a.shape(0) > std::numeric_limits<int>::max() ||
      a.shape(1) > std::numeric_limits<int>::max()) {
    throw Error(argument.text() + ": the image is too large, " + got(a, true));
  }
  using Uint8Array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;
  const Uint8Array bytes = Uint8Array::ensure(a);
  Rgba8Image image;
  image.height = static_cast<int>(a.shape(0));
  image.width = static_cast<int>(a.shape(1));
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  const int channels = static_cast<int>(a.shape(2));
  const std::uint8_t* data = bytes.data();
  image.rgba.resize(pixels * 4);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (int c = 0; c < 3; ++c) image.rgba[i * 4 + c] = data[i * channels + c];
    image.rgba[i * 4 + 3] = channels == 4 ? data[i * channels + 3] : 255;
  }
  return image;
}

std::shared_ptr<const Texture> texture_image(py::handle value, const Argument& argument) {
  Rgba8Image image = rgba8_image(value, argument);
  try {
    return Texture::from_rgba8(image.width, image.height, std::move(image.rgba), /*srgb=*/true,
                               argument.name);
  } catch (const Error& e) {
    throw Error(std::string(argument.function) + ": " + e.what());
  }
}

namespace {

// An N x N matrix (row-major as written on paper), finite.
template <int N>
glm::mat<N, N, float> square_matrix(py::handle value, const Argument& argument) {
  const py::array a = as_array(value, argument);
  const bool kind_ok = is_real(a);
  if (!kind_ok || a.ndim() != 2 || a.shape(0) != N || a.shape(1) != N) {
    throw Error(argument.text() + " must be a " + std::to_string(N) + "x" + std::to_string(N) +
                " float matrix, " + got(a, kind_ok));
  }
  const DoubleArray d = DoubleArray::ensure(a);
  const double* data = d.data();
  glm::mat<N, N, float> m;
  for (int row = 0; row < N; ++row) {
    for (int column = 0; column < N; ++column) {
      const double v = data[row * N + column];
      if (!finite_float(v)) throw Error(argument.text() + " must be finite");
      m[column][row] = static_cast<float>(v);  // glm is column-major
    }
  }
  return m;
}

}  // namespace

glm::mat3 matrix3(py::handle value, const Argument& argument) {
  return square_matrix<3>(value, argument);
}

glm::mat4 matrix4(py::handle value, const Argument& argument) {
  return square_matrix<4>(value, argument);
}

namespace {

// 3 (or, for colors, 3 or 4) finite numbers.
std::vector<float> small_vector(py::handle value, const Argument& argument, bool color) {
  const py::array a = as_array(value, argument);
  const bool kind_ok = is_real(a);
  const bool size_ok = a.ndim() == 1 && (a.shape(0) == 3 || (color && a.shape(0) == 4));
  if (!kind_ok || !size_ok) {
    throw Error(
        argument.text() +
        (color ? " must be 3 or 4 numbers (RGB or RGBA), " : " must be 3 numbers (x, y, z), ") +
        got(a, kind_ok));
  }
  const DoubleArray d = DoubleArray::ensure(a);
  const std::vector<double> values(d.data(), d.data() + d.size());
  for (double v : values) {
    if (!finite_float(v)) {
      throw Error(argument.text() + " must be finite, got " +
                  values_text(values, static_cast<int>(values.size())));
    }
  }
  return std::vector<float>(values.begin(), values.end());
}

}  // namespace

glm::vec3 vec3(py::handle value, const Argument& argument) {
  const std::vector<float> v = small_vector(value, argument, false);
  return {v[0], v[1], v[2]};
}

glm::vec4 rgba(py::handle value, const Argument& argument) {
  const std::vector<float> v = small_vector(value, argument, true);
  return {v[0], v[1], v[2], v.size() == 4 ? v[3] : 1.0f};
}

float number(py::handle value, const Argument& argument) {
  double v = 0.0;
  try {
    v = value.cast<double>();
  } catch (const py::cast_error&) {
    throw Error(argument.text() + " must be a number, got " +
                std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  if (!finite_float(v)) {
    throw Error(argument.text() + " must be a finite number, got " + std::to_string(v));
  }
  return static_cast<float>(v);
}

int integer(py::handle value, const Argument& argument) {
  const float v = number(value, argument);
  if (v != std::floor(v) || std::abs(v) > 1e9f) {
    throw Error(argument.text() + " must be a whole number, got " + std::to_string(v));
  }
  return static_cast<int>(v);
}

std::string to_text(glm::vec3 v) { return values_text(v, 3); }
std::string to_text(glm::vec4 v) { return values_text(v, 4); }

py::float_ to_python(float v) {
  std::array<char, 32> digits{};
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), v).ptr;
  return py::float_(std::strtod(std::string(digits.data(), end).c_str(), nullptr));
}

py::tuple to_tuple(glm::vec3 v) {
  return py::make_tuple(to_python(v.x), to_python(v.y), to_python(v.z));
}
py::tuple to_tuple(glm::vec4 v) {
  return py::make_tuple(to_python(v.x), to_python(v.y), to_python(v.z), to_python(v.w));
}

py::array_t<double> to_numpy(const glm::mat4& m) {
  py::array_t<double> out({4, 4});
  auto r = out.mutable_unchecked<2>();
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) r(row, column) = m[column][row];
  }
  return out;
}

}  // namespace facet::python
