// The compiled part of `import facet` (facet._facet; python/facet/__init__.py re-exports it):
// facet.Error, then each part of the API from its own file (bindings.hpp).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "facet/error.hpp"
#include "facet/version.hpp"

PYBIND11_MODULE(_facet, m) {
  namespace py = pybind11;
  m.doc() = "facet: a CPU software rasterizer (the compiled part of the facet package)";
  // Every facet::Error, the library's and the bindings' own argument checks, arrives as
  // facet.Error with the library's one-line message.
  py::register_exception<facet::Error>(m, "Error");
  m.attr("__version__") = facet::version();
  facet::python::bind_materials_and_lights(m);
  facet::python::bind_camera(m);
  facet::python::bind_scene(m);
  facet::python::bind_animation(m);
  facet::python::bind_render_texture(m);
  facet::python::bind_render(m);
}
