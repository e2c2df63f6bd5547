// The OpenGL twin (facet::gl) against facet's own renderer: the same scenes, cameras, lights and
// materials drawn by both, compared by PSNR over the color and by the silhouettes (which pixels
// anything covered, from the depth images). The measured numbers are in docs/gl_twin.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "facet/gl.hpp"
#include "facet/image_io.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "facet/worlds.hpp"
#include "support/required_package.hpp"

namespace facet {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;
const char* const kBunny = "/usr/share/glmark2/models/bunny.obj";  // Debian's glmark2-data

// One context for the whole test program: making one costs llvmpipe tens of milliseconds. Null,
// with the reason in `why`, when EGL cannot make one; the Makefile's PACKAGES installs Mesa's
// EGL and drivers, so that is a broken set-up and the tests fail rather than skip.
GlRenderer* shared_gl(std::string& why) {
  static std::unique_ptr<GlRenderer> renderer;
  static std::string error;
  static bool tried = false;
  if (!tried) {
    tried = true;
    try {
      renderer = std::make_unique<GlRenderer>();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  why = error;
  return renderer.get();
}

#define REQUIRE_GL(gl)                                                   \
  std::string why_no_gl;                                                 \
  GlRenderer* gl = shared_gl(why_no_gl);                                 \
  FACET_REQUIRE_PACKAGE(gl != nullptr, "no OpenGL context through EGL: " \
                                           << why_no_gl                  \
                                           << "; needs libegl-mesa0 and libgl1-mesa-dri")

struct Views {
  Scene scene;
  Camera camera;
};

Views scene_named(const std::string& name) {
  Views v;
  if (name == "bunny") {
    ImportOptions options;
    options.warn = [](const std::string&) {};
    v.scene = import_scene(kBunny, options);
  } else {
    v.scene = make_builtin_scene(name);
  }
  const float aspect = static_cast<float>(kWidth) / kHeight;
  v.camera = scene_camera(v.scene, aspect);
  v.camera.aspect = aspect;
  return v;
}

Framebuffer facet_image(const Scene& scene, const Camera& camera) {
  Renderer renderer;
  Framebuffer image(kWidth, kHeight);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(image);
  return image;
}

Framebuffer gl_image(GlRenderer& gl, const Scene& scene, const Camera& camera) {
  Framebuffer image(kWidth, kHeight);
  gl.render(scene, camera, image);
  return image;
}

// Peak signal-to-noise ratio of the 8-bit sRGB color channels, in dB (infinite when equal).
double psnr(const Framebuffer& a, const Framebuffer& b) {
  double squared = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.rgba8().size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.rgba8()[i]) - double(b.rgba8()[i]);
    squared += d * d, ++count;
  }
  if (squared == 0.0) return INFINITY;
  return 10.0 * std::log10(255.0 * 255.0 / (squared / double(count)));
}

// The share of pixels that one image covers (depth below the clear depth 1) and the other not.
double silhouette_difference(const Framebuffer& a, const Framebuffer& b) {
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.depth().size(); ++i) {
    differ += (a.depth()[i] < 1.0f) != (b.depth()[i] < 1.0f);
  }
  return double(differ) / double(a.depth().size());
}

double covered(const Framebuffer& a) {
  std::size_t n = 0;
  for (float d : a.depth()) n += d < 1.0f;
  return double(n) / double(a.depth().size());
}

// Writes both images where a person can look at them side by side.
void keep_images(const std::string& name, const Framebuffer& facet, const Framebuffer& gl) {
  const auto dir = std::filesystem::temp_directory_path() / "facet_gl_twin";
  std::filesystem::create_directories(dir);
  write_image(facet, (dir / (name + "_facet.png")).string());
  write_image(gl, (dir / (name + "_gl.png")).string());
}

struct Expected {
  const char* scene;
  double min_psnr;  // dB; the measured value is a few dB above (docs/gl_twin.md)
};

class GlTwinScenes : public ::testing::TestWithParam<Expected> {};

// The twin draws what facet draws: the same picture to within the PSNR bound, the same
// silhouette to within 0.5 % of the pixels (the two fill rules differ along edges).
TEST_P(GlTwinScenes, MatchesFacet) {
  REQUIRE_GL(gl);
  const Expected expected = GetParam();
  if (std::string(expected.scene) == "bunny") {
    FACET_REQUIRE_PACKAGE(std::filesystem::exists(kBunny), "the bunny needs glmark2-data");
  }
  const Views v = scene_named(expected.scene);
  const Framebuffer reference = facet_image(v.scene, v.camera);
  const Framebuffer twin = gl_image(*gl, v.scene, v.camera);
  keep_images(expected.scene, reference, twin);
  const double db = psnr(reference, twin);
  const double silhouette = silhouette_difference(reference, twin);
  RecordProperty("psnr_db", std::to_string(db));
  std::printf("%s: PSNR %.2f dB, silhouettes differ on %.3f %% of pixels (covered %.1f %%)\n",
              expected.scene, db, 100.0 * silhouette, 100.0 * covered(reference));
  EXPECT_GE(db, expected.min_psnr) << expected.scene;
  EXPECT_LT(silhouette, 0.005) << expected.scene;
  EXPECT_GT(covered(reference), 0.05) << "the scene should fill part of the picture";
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlTwinScenes,
                         ::testing::Values(Expected{"shapes", 35.0}, Expected{"teapot", 35.0},
                                           Expected{"bunny", 35.0}, Expected{"islands", 35.0}),
                         [](const auto& info) { return std::string(info.param.scene); });

}  // namespace
}  // namespace facet
