// The renderer's API guards: what it refuses to compile, and the errors that say how to call it.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"

namespace facet::test {
namespace {

// A mesh the renderer would read after the statement that made it: drawing a temporary must not
// compile (the mesh is referenced until finish()).
template <class M>
concept DrawableTemporary = requires(Renderer& r, const Material& m) {
  r.draw(M{}, m);
};
static_assert(!DrawableTemporary<Mesh>);
// A named mesh and a shared pointer still do.
static_assert(requires(Renderer & r, const Mesh& mesh, const Material& m) { r.draw(mesh, m); });
static_assert(requires(Renderer & r, std::shared_ptr<const Mesh> mesh, const Material& m) {
  r.draw(mesh, m);
});

std::string error_of(const auto& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(RendererApi, CallsOutOfOrderSayWhatToDo) {
  Renderer renderer(RenderSettings{.threads = 1});
  Framebuffer image(8, 8);
  const Mesh mesh = cube();
  EXPECT_EQ(error_of([&] { renderer.finish(image); }),
            "renderer: finish() called before begin_frame()");
  renderer.begin_frame(Camera{});
  renderer.draw(mesh, Material{});
  renderer.finish(image);
  EXPECT_EQ(error_of([&] { renderer.finish(image); }),
            "renderer: finish() called after finish(); begin_frame() starts the next frame");
  EXPECT_EQ(error_of([&] { renderer.draw(mesh, Material{}); }),
            "renderer: draw() called after finish(); begin_frame() starts the next frame");
}

TEST(RendererApi, ThreadCountsBeyondTheLimitAreRefused) {
  RenderSettings settings;
  settings.threads = 100000;
  EXPECT_EQ(error_of([&] { Renderer renderer(settings); }),
            "renderer: threads must be 0 (all cores) or 1 to 256, got 100000");
  settings.threads = RenderSettings::kMaxThreads;
  EXPECT_EQ(error_of([&] { Renderer renderer(settings); }), "");
}

}  // namespace
}  // namespace facet::test
