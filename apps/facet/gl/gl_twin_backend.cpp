// The OpenGL module (modules.hpp): GlBackend (render_backend.hpp) over the OpenGL twin,
// facet::gl's GlRenderer. The only file of the program that links EGL and OpenGL.
#include "facet/gl.hpp"
#include "modules.hpp"
#include "render_backend.hpp"

namespace facet::cli {
namespace {

class GlTwinBackend final : public GlBackend {
 public:
  explicit GlTwinBackend(const RenderSettings& settings) : renderer_(settings) {}

  std::string description() const override {
    return renderer_.renderer_name() + ", OpenGL " + renderer_.version();
  }
  const std::string& renderer_name() const override { return renderer_.renderer_name(); }
  void render(const Scene& scene, const Camera& camera, Framebuffer& target) override {
    renderer_.render(scene, camera, target);
  }
  void draw(const Scene& scene, const Camera& camera, Framebuffer& target) override {
    renderer_.draw(scene, camera, target);
  }
  double last_frame_ms() const override { return renderer_.last_frame_ms(); }

 private:
  GlRenderer renderer_;
};

}  // namespace
}  // namespace facet::cli

extern "C" facet::cli::GlBackend* facet_gl_backend_new(const facet::RenderSettings& settings) {
  return new facet::cli::GlTwinBackend(settings);
}
