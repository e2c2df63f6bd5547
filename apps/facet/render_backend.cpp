// The choice of renderer (see render_backend.hpp).
#include "render_backend.hpp"

#include "facet/error.hpp"

namespace facet::cli {

Backend parse_backend(const std::string& flag, const std::string& text) {
  if (text == "facet") return Backend::facet;
  if (text == "gl") return Backend::gl;
  throw Error(flag + ": expected facet or gl, got '" + text + "'");
}

const char* backend_name(Backend backend) { return backend == Backend::gl ? "gl" : "facet"; }

}  // namespace facet::cli
