// The choice of renderer (see render_backend.hpp).
#include "render_backend.hpp"

#include "facet/error.hpp"
#if FACET_HAS_GL
#include "facet/gl.hpp"
#endif

namespace facet::cli {

Backend parse_backend(const std::string& flag, const std::string& text) {
  if (text == "facet") return Backend::facet;
  if (text == "gl") return Backend::gl;
  throw Error(flag + ": expected facet or gl, got '" + text + "'");
}

const char* backend_name(Backend backend) { return backend == Backend::gl ? "gl" : "facet"; }

#if FACET_HAS_GL

struct GlBackend::Impl {
  explicit Impl(const RenderSettings& settings) : renderer(settings) {}
  GlRenderer renderer;
};

GlBackend::GlBackend(const RenderSettings& settings) : impl_(std::make_unique<Impl>(settings)) {}

std::string GlBackend::description() const {
  return impl_->renderer.renderer_name() + ", OpenGL " + impl_->renderer.version();
}

const std::string& GlBackend::renderer_name() const { return impl_->renderer.renderer_name(); }

void GlBackend::render(const Scene& scene, const Camera& camera, Framebuffer& target) {
  impl_->renderer.render(scene, camera, target);
}

void GlBackend::draw(const Scene& scene, const Camera& camera, Framebuffer& target) {
  impl_->renderer.draw(scene, camera, target);
}

double GlBackend::last_frame_ms() const { return impl_->renderer.last_frame_ms(); }

#else

struct GlBackend::Impl {};

GlBackend::GlBackend(const RenderSettings&) {
  throw Error("--backend gl: this facet was built without the OpenGL backend (FACET_BUILD_GL=OFF)");
}
std::string GlBackend::description() const { return {}; }
const std::string& GlBackend::renderer_name() const {
  static const std::string none;
  return none;
}
void GlBackend::render(const Scene&, const Camera&, Framebuffer&) {}
void GlBackend::draw(const Scene&, const Camera&, Framebuffer&) {}
double GlBackend::last_frame_ms() const { return 0.0; }

#endif

GlBackend::~GlBackend() = default;

}  // namespace facet::cli
