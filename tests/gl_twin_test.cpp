// The OpenGL twin (facet::gl) against facet's own renderer: the same scenes, cameras, lights and
// materials drawn by both, compared by PSNR over the color and by the silhouettes (which pixels
// anything covered, from the depth images). The measured numbers are in docs/gl_twin.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>

#include "facet/error.hpp"
#include "facet/gl.hpp"
#include "facet/image_io.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "facet/worlds.hpp"
#include "support/golden.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "view_difference.hpp"

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

// facet's image as the twin draws it: without planar reflections, which the twin lacks (its
// mirrors show the environment alone: docs/gl_twin.md).
RenderSettings twin_settings(int msaa = 1) {
  RenderSettings settings;
  settings.msaa = msaa;
  settings.reflections = false;
  return settings;
}

Framebuffer facet_image(const Scene& scene, const Camera& camera, int msaa = 1) {
  const RenderSettings settings = twin_settings(msaa);
  return test::render_scene_image(scene, camera, kWidth, kHeight, settings);
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

// The PSNR bounds sit 6 dB under what Mesa's llvmpipe reaches (docs/gl_twin.md has the table),
// so that a wrong light or texture fails, and never under the 35 dB the twin is meant to reach on
// any driver.
struct Expected {
  const char* scene;
  double min_psnr;  // dB
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
                         ::testing::Values(Expected{"shapes", 80.0}, Expected{"teapot", 72.0},
                                           Expected{"bunny", 71.0}, Expected{"islands", 48.0}),
                         [](const auto& param) { return std::string(param.param.scene); });

// --- Multisampling: both renderers at 4 samples a pixel (the same standard positions) ---

// A second twin, drawing with 4 samples a pixel (the sample count is fixed at construction).
GlRenderer* shared_gl_msaa4() {
  static std::unique_ptr<GlRenderer> renderer = [] {
    RenderSettings settings;
    settings.msaa = 4;
    return std::make_unique<GlRenderer>(settings);
  }();
  return renderer.get();
}

// The edges are anti-aliased alike, but not identically (docs/gl_twin.md has the PSNRs). Mesa
// puts the standard 4x positions in GL's window coordinates, whose rows run up, so in the image
// as read back its pattern is facet's mirrored top to bottom (GL_SAMPLE_POSITION 0 is at
// (0.375, 0.125), facet's at (0.375, 0.875) from the top left). Edge pixels then differ by up to
// half their contrast, and the depth image's one sample differs along silhouettes (1 %).
class GlTwinMsaa : public ::testing::TestWithParam<Expected> {};

TEST_P(GlTwinMsaa, MatchesFacetAtFourSamples) {
  REQUIRE_GL(gl);
  const Expected expected = GetParam();
  const Views v = scene_named(expected.scene);
  const Framebuffer reference = facet_image(v.scene, v.camera, 4);
  const Framebuffer twin = gl_image(*shared_gl_msaa4(), v.scene, v.camera);
  keep_images(std::string(expected.scene) + "_msaa4", reference, twin);
  const double db = psnr(reference, twin);
  RecordProperty("psnr_db", std::to_string(db));
  std::printf("%s at msaa 4: PSNR %.2f dB, against facet at msaa 1: %.2f dB\n", expected.scene, db,
              psnr(facet_image(v.scene, v.camera, 1), twin));
  EXPECT_GE(db, expected.min_psnr) << expected.scene;
  EXPECT_GE(db, psnr(facet_image(v.scene, v.camera, 1), twin) + 3.0)
      << "closer to facet at 4 samples than at one";
  EXPECT_LT(silhouette_difference(reference, twin), 0.01) << expected.scene;
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlTwinMsaa,
                         ::testing::Values(Expected{"shapes", 40.0}, Expected{"teapot", 32.0}),
                         [](const auto& param) { return std::string(param.param.scene); });

// 4 samples really change the twin's picture, and only along edges: some pixels differ from
// the one-sample picture, few of them, and they take colors between their neighbours'.
TEST(GlTwinMsaa, FourSamplesChangeOnlyTheEdgePixels) {
  REQUIRE_GL(gl);
  const Views v = scene_named("shapes");
  const Framebuffer one = gl_image(*gl, v.scene, v.camera);
  const Framebuffer four = gl_image(*shared_gl_msaa4(), v.scene, v.camera);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < one.rgba8().size(); i += 4) {
    int most = 0;
    for (int c = 0; c < 3; ++c)
      most = std::max(most, std::abs(one.rgba8()[i + c] - four.rgba8()[i + c]));
    changed += most > 8;
  }
  const double share = double(changed) / double(kWidth * kHeight);
  std::printf("msaa 4 changed %zu pixels (%.2f %%)\n", changed, 100.0 * share);
  EXPECT_GT(changed, 200u) << "msaa 4 should soften the edges";
  EXPECT_LT(share, 0.1) << "msaa 4 should change only edge pixels";
}

// --- Each shading model, sampler, blend mode, fog and sky, on small variations of a scene ---

// A 64x64 sRGB texture with detail at every scale: stripes, a checker and a colored gradient,
// so that filtering and mipmaps show.
std::shared_ptr<const Texture> detailed_texture() {
  constexpr int kSize = 64;
  std::vector<std::uint8_t> rgba(kSize * kSize * 4);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      std::uint8_t* p = &rgba[(y * kSize + x) * 4];
      const bool check = ((x / 8) + (y / 8)) % 2 == 0;
      p[0] = static_cast<std::uint8_t>(check ? 230 : 40 + 3 * x);
      p[1] = static_cast<std::uint8_t>((x % 4) < 2 ? 200 : 60);
      p[2] = static_cast<std::uint8_t>(4 * y);
      p[3] = static_cast<std::uint8_t>(x < 32 ? 255 : 90 + 2 * y);
    }
  }
  return Texture::from_rgba8(kSize, kSize, std::move(rgba), true, "detailed");
}

// One float a texel (as a depth image is kept), the same detail at every scale.
std::shared_ptr<const Texture> gray_texture() {
  constexpr int kSize = 64;
  std::vector<float> values(kSize * kSize);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const bool check = ((x / 8) + (y / 8)) % 2 == 0;
      values[y * kSize + x] = (check ? 0.9f : 0.1f) + ((x % 4) < 2 ? 0.05f : 0.0f) + y / 1000.0f;
    }
  }
  return Texture::from_r32f(kSize, kSize, std::move(values), "gray");
}

// A ground plane seen at a grazing angle (every mip level in view), textured with uv running
// past [0, 1] so that the wrap modes show.
Views textured_plane(Filter filter, Wrap wrap,
                     std::shared_ptr<const Texture> texture = detailed_texture()) {
  Views v;
  Mesh plane;
  const float r = 6.0f;
  plane.positions = {{-r, 0, r}, {r, 0, r}, {r, 0, -r}, {-r, 0, -r}};
  plane.normals.assign(4, {0, 1, 0});
  plane.texcoords = {{-1.5f, -1.5f}, {2.5f, -1.5f}, {2.5f, 2.5f}, {-1.5f, 2.5f}};
  plane.indices = {0, 1, 2, 0, 2, 3};
  Material m;
  m.shading = ShadingModel::unlit;
  m.base_color_map.texture = std::move(texture);
  m.base_color_map.sampler = {filter, wrap, wrap};
  v.scene.add_object(std::move(plane), m);
  const float aspect = static_cast<float>(kWidth) / kHeight;
  v.camera = Camera::look_at({0.0f, 1.2f, 6.5f}, {0.0f, 0.0f, -1.0f}, {0, 1, 0}, 60.0f, aspect);
  return v;
}

// The shapes scene with every material set to one model, lit by a sun, a point light and a
// spot light, under linear fog with the sky behind.
Views shapes_with(ShadingModel model) {
  Views v = scene_named("shapes");
  for (Material& m : v.scene.materials) {
    m.shading = model;
    m.specular_color = glm::vec3(0.5f);
    m.roughness = 0.35f;
  }
  Lighting& l = v.scene.lighting;
  l.lights.push_back(Light::point({1.0f, 2.5f, 2.0f}, {1.0f, 0.6f, 0.3f}, 4.0f, 12.0f));
  l.lights.push_back(Light::spot({-2.0f, 4.0f, 2.0f}, {0.4f, -1.0f, -0.3f}, 15.0f, 30.0f,
                                 {0.3f, 0.5f, 1.0f}, 12.0f));
  l.fog.mode = FogMode::linear;
  l.fog.start = 4.0f;
  l.fog.end = 30.0f;
  l.environment.show_as_background = true;
  return v;
}

struct Variant {
  std::string name;
  Views views;
  double min_psnr;
  int msaa = 1;  // 1 or 4
};

void expect_twins(const Variant& variant) {
  REQUIRE_GL(gl);
  const Framebuffer reference =
      facet_image(variant.views.scene, variant.views.camera, variant.msaa);
  GlRenderer* twin_renderer = variant.msaa == 4 ? shared_gl_msaa4() : gl;
  const Framebuffer twin = gl_image(*twin_renderer, variant.views.scene, variant.views.camera);
  keep_images(variant.name, reference, twin);
  const double db = psnr(reference, twin);
  const double silhouette = silhouette_difference(reference, twin);
  std::printf("%s: PSNR %.2f dB, silhouettes differ on %.3f %% of pixels\n", variant.name.c_str(),
              db, 100.0 * silhouette);
  EXPECT_GE(db, variant.min_psnr) << variant.name;
  EXPECT_LT(silhouette, 0.005) << variant.name;
}

struct ModelBound {
  ShadingModel model;
  double min_psnr;
};
class GlTwinModels : public ::testing::TestWithParam<ModelBound> {};

TEST_P(GlTwinModels, MatchFacetOnShapes) {
  const ModelBound bound = GetParam();
  expect_twins({std::string("model_") + std::string(to_string(bound.model)),
                shapes_with(bound.model), bound.min_psnr});
}

INSTANTIATE_TEST_SUITE_P(
    Models, GlTwinModels,
    ::testing::Values(ModelBound{ShadingModel::unlit, 84},
                      ModelBound{ShadingModel::vertex_color, 84},
                      ModelBound{ShadingModel::flat, 84}, ModelBound{ShadingModel::lambert, 78},
                      ModelBound{ShadingModel::gouraud, 78}, ModelBound{ShadingModel::phong, 78},
                      ModelBound{ShadingModel::blinn_phong, 77}, ModelBound{ShadingModel::pbr, 76},
                      ModelBound{ShadingModel::depth, 71}, ModelBound{ShadingModel::normals, 82},
                      ModelBound{ShadingModel::texcoords, 73},
                      ModelBound{ShadingModel::wireframe, 40},
                      ModelBound{ShadingModel::wire_overlay, 49}),
    [](const auto& param) { return std::string(to_string(param.param.model)); });

struct SamplerBound {
  Filter filter;
  Wrap wrap;
  const char* name;
  double min_psnr;
};
class GlTwinSamplers : public ::testing::TestWithParam<SamplerBound> {};

TEST_P(GlTwinSamplers, MatchFacetOnATexturedPlane) {
  const SamplerBound bound = GetParam();
  expect_twins({std::string("sampler_") + bound.name, textured_plane(bound.filter, bound.wrap),
                bound.min_psnr});
}

INSTANTIATE_TEST_SUITE_P(
    Samplers, GlTwinSamplers,
    ::testing::Values(SamplerBound{Filter::nearest, Wrap::repeat, "nearest_repeat", 38},
                      SamplerBound{Filter::bilinear, Wrap::repeat, "bilinear_repeat", 53},
                      SamplerBound{Filter::trilinear, Wrap::repeat, "trilinear_repeat", 46},
                      SamplerBound{Filter::bilinear, Wrap::clamp_to_edge, "bilinear_clamp", 59},
                      SamplerBound{Filter::trilinear, Wrap::mirrored_repeat, "trilinear_mirror",
                                   47}),
    [](const auto& param) { return std::string(param.param.name); });

// A one-float texture (what a depth render texture holds) reads as gray in both.
TEST(GlTwin, OneFloatTextureMatchesFacet) {
  expect_twins(
      {"sampler_one_float", textured_plane(Filter::trilinear, Wrap::repeat, gray_texture()), 50});
}

// Cut-out, "over" and additive blending: the shapes in turn masked, blended and added, with a
// texture whose alpha varies.
TEST(GlTwin, AlphaMaskAndBlendingMatchFacet) {
  Views v = shapes_with(ShadingModel::blinn_phong);
  const AlphaMode modes[] = {AlphaMode::mask, AlphaMode::blend, AlphaMode::additive};
  for (std::size_t i = 0; i < v.scene.materials.size(); ++i) {
    Material& m = v.scene.materials[i];
    m.alpha_mode = modes[i % 3];
    m.base_color.a = 0.6f;
    m.base_color_map.texture = detailed_texture();
  }
  expect_twins({"alpha_modes", v, 56});  // 6 dB under docs/gl_twin.md's figure
}

// Cut-outs at 4 samples a pixel: alpha to coverage, the same samples kept as facet keeps.
TEST(GlTwinMsaa, AlphaToCoverageMatchesFacet) {
  Views v = shapes_with(ShadingModel::blinn_phong);
  for (Material& m : v.scene.materials) {
    m.alpha_mode = AlphaMode::mask;
    m.base_color_map.texture = detailed_texture();
  }
  expect_twins({"alpha_to_coverage", v, 40.0, 4});  // measured 46.8 dB
}

// Image-based light: PBR reflecting an equirectangular environment that is also the background,
// and an exponential fog.
TEST(GlTwin, EnvironmentAndExponentialFogMatchFacet) {
  Views v = shapes_with(ShadingModel::pbr);
  constexpr int kW = 64, kH = 32;
  std::vector<float> sky(kW * kH * 4);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      float* p = &sky[(y * kW + x) * 4];
      p[0] = 0.2f + 0.8f * float(x) / kW, p[1] = 0.3f + 0.7f * float(y) / kH;
      p[2] = ((x / 4 + y / 4) % 2) ? 1.5f : 0.3f, p[3] = 1.0f;
    }
  }
  Environment& env = v.scene.lighting.environment;
  env.image = Texture::from_rgba32f(kW, kH, std::move(sky), "sky");
  env.reflections = true;
  for (Material& m : v.scene.materials) m.metallic = 0.7f;
  v.scene.lighting.fog.mode = FogMode::exponential;
  v.scene.lighting.fog.density = 0.05f;
  expect_twins({"environment", v, 73});  // 6 dB under docs/gl_twin.md's figure
}

// Tone mapped, 1.5 stops brighter, with fog: the twin maps its read-back colors and fogs toward
// the same inverse of the fog color, so the two stay as close as without a curve.
TEST(GlTwin, ToneMappingMatchesFacet) {
  REQUIRE_GL(gl);
  Views v = shapes_with(ShadingModel::phong);
  v.scene.lighting.fog.mode = FogMode::linear;
  v.scene.lighting.fog.start = 5.0f;
  v.scene.lighting.fog.end = 25.0f;
  for (ToneMapping curve : {ToneMapping::pbr_neutral, ToneMapping::aces}) {
    RenderSettings settings;
    settings.tone_mapping = curve;
    settings.exposure = 1.5f;
    const Framebuffer reference =
        test::render_scene_image(v.scene, v.camera, kWidth, kHeight, settings);
    GlRenderer twin_renderer(settings);
    const Framebuffer twin = gl_image(twin_renderer, v.scene, v.camera);
    RenderSettings unmapped = settings;
    unmapped.tone_mapping = ToneMapping::none;
    const double db = psnr(reference, twin);
    std::printf("tone mapping %d: PSNR %.2f dB\n", static_cast<int>(curve), db);
    EXPECT_GE(db, 60.0);
    EXPECT_LT(psnr(test::render_scene_image(v.scene, v.camera, kWidth, kHeight, unmapped), twin),
              40.0)
        << "the curve changes the image";
  }
}

// --- `facet render --backend gl` -----------------------------------------------------------

double psnr(const test::Rgba8Image& a, const test::Rgba8Image& b) {
  double squared = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.pixels[i]) - double(b.pixels[i]);
    squared += d * d, ++count;
  }
  return squared == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / (squared / double(count)));
}

TEST(GlTwinCli, RenderBackendGlDrawsWhatFacetDraws) {
  REQUIRE_GL(gl);
  const auto dir = test::fresh_test_dir("facet_gl_twin_", "cli");
  // One sample a pixel: at 4 the two sample patterns are mirrored (see GlTwinMsaa), and the
  // edges' difference would hide a wrong light. No shadows: the twin draws none.
  const std::string common =
      std::string(FACET_CLI) + " render --scene teapot --size 160x90 --msaa 1 --shadows off -o ";
  const test::CommandResult twin =
      test::run_command(common + (dir / "gl.png").string() + " --backend gl");
  ASSERT_EQ(twin.exit_code, 0) << twin.stderr_text;
  // The summary says which renderer drew the frame.
  EXPECT_NE(twin.stdout_text.find("drawn by OpenGL (" + gl->renderer_name()), std::string::npos)
      << twin.stdout_text;
  ASSERT_EQ(test::run_command(common + (dir / "facet.png").string()).exit_code, 0);
  const test::Rgba8Image a = test::read_png((dir / "gl.png").string());
  const test::Rgba8Image b = test::read_png((dir / "facet.png").string());
  ASSERT_EQ(a.width, 160);
  EXPECT_GE(psnr(a, b), 50.0);  // 6 dB under docs/gl_twin.md's figure
}

// `facet bench --backend gl` times the scenes the twin can draw, says which OpenGL it is, and
// leaves out the glmark2 equivalents under `all` (their shading is facet's own).
TEST(GlTwinCli, BenchTimesTheScenesTheTwinCanDraw) {
  REQUIRE_GL(gl);
  const std::string bench =
      std::string(FACET_CLI) + " bench --backend gl --size 64x36 --frames 2 --warmup 1 --threads 2";
  const test::CommandResult r = test::run_command(bench + " --scene shapes,overdraw");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stdout_text.rfind("OpenGL: " + gl->renderer_name(), 0), 0u) << r.stdout_text;
  std::istringstream rows(r.stdout_text);
  std::vector<std::string> names;
  for (std::string line; std::getline(rows, line);) {
    std::istringstream words(line);
    std::string name, median;
    words >> name >> median;
    if (!median.empty() && std::isdigit(static_cast<unsigned char>(median[0]))) {
      names.push_back(name);
      EXPECT_GT(std::stod(median), 0.0) << line;
    }
  }
  EXPECT_EQ(names, (std::vector<std::string>{"shapes", "overdraw"})) << r.stdout_text;
  const test::CommandResult glmark2 = test::run_command(bench + " --scene build:use-vbo=true");
  EXPECT_EQ(glmark2.exit_code, 2);
  EXPECT_NE(glmark2.stderr_text.find("--scene build:use-vbo=true: a glmark2 scene"),
            std::string::npos)
      << glmark2.stderr_text;
}

// `--gl-readback off` times the twin's frames as glmark2 times llvmpipe's (GlRenderer::draw), and
// says so in the JSON; it asks for the twin.
TEST(GlTwinCli, BenchWithoutReadbackTimesTheDrawAlone) {
  REQUIRE_GL(gl);
  const auto dir = std::filesystem::temp_directory_path() / "facet_gl_twin";
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "draw_only.json").string();
  const std::string bench = std::string(FACET_CLI) +
                            " bench --size 64x36 --frames 2 --warmup 1 --threads 2 "
                            "--scene bunny-close --gl-readback off";
  const test::CommandResult r = test::run_command(bench + " --backend gl --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("bunny-close"), std::string::npos) << r.stdout_text;
  std::ifstream file(json);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"gl_readback\": \"off\""), std::string::npos) << text;
  const test::CommandResult facet = test::run_command(bench);
  EXPECT_EQ(facet.exit_code, 2);
  EXPECT_NE(facet.stderr_text.find("--gl-readback off: only with --backend gl"), std::string::npos)
      << facet.stderr_text;
}

// The frame GlRenderer::draw times is render()'s, drawn into 8-bit sRGB that OpenGL encodes:
// read back, facet's image without tone mapping (which draw leaves out), but for the two
// encoders' roundings.
TEST(GlTwin, DrawnFrameIsTheRenderedOneEncodedByOpenGL) {
  REQUIRE_GL(gl);
  FACET_REQUIRE_PACKAGE(std::filesystem::exists(kBunny), "the bunny needs glmark2-data");
  // 6 dB under llvmpipe's: its sRGB encode rounds some values the other way.
  for (const Expected expected : {Expected{"bunny", 60.0}, Expected{"shapes", 49.0}}) {
    const std::string name = expected.scene;
    const Views v = scene_named(name);
    RenderSettings settings = twin_settings();
    settings.tone_mapping = ToneMapping::none;
    const Framebuffer reference =
        test::render_scene_image(v.scene, v.camera, kWidth, kHeight, settings);
    Framebuffer drawn(kWidth, kHeight);
    gl->draw(v.scene, v.camera, drawn, true);
    keep_images(name + "_drawn", reference, drawn);
    const double db = psnr(reference, drawn);
    std::printf("%s drawn into 8-bit sRGB: PSNR %.2f dB\n", name.c_str(), db);
    EXPECT_GE(db, expected.min_psnr) << name;
  }
  Framebuffer floats(kWidth, kHeight, ColorFormat::rgba32f, DepthImage::none);
  const Views v = scene_named("shapes");
  EXPECT_THROW(gl->draw(v.scene, v.camera, floats), Error);
}

// `facet render --compare facet,gl`: facet's image and the twin's side by side, the right panel
// the twin's own image but for its label.
TEST(GlTwinCli, CompareDrawsFacetAndTheTwinSideBySide) {
  REQUIRE_GL(gl);
  const auto dir = test::fresh_test_dir("facet_gl_twin_", "compare");
  const std::string common = std::string(FACET_CLI) + " render --scene teapot --size 96x54 -o ";
  const test::CommandResult both =
      test::run_command(common + (dir / "both.png").string() + " --compare facet,gl");
  ASSERT_EQ(both.exit_code, 0) << both.stderr_text;
  ASSERT_EQ(test::run_command(common + (dir / "gl.png").string() + " --backend gl").exit_code, 0);
  const test::Rgba8Image picture = test::read_png((dir / "both.png").string());
  const test::Rgba8Image twin = test::read_png((dir / "gl.png").string());
  ASSERT_EQ(picture.width, 2 * 96);
  int differing = 0;
  for (int y = 28; y < 54; ++y) {  // below the label
    for (int x = 0; x < 96; ++x) {
      const std::uint8_t* a = &picture.pixels[(y * picture.width + 96 + x) * 4];
      const std::uint8_t* b = &twin.pixels[(y * 96 + x) * 4];
      differing += !std::equal(a, a + 4, b);
    }
  }
  EXPECT_EQ(differing, 0);
}

// No usable OpenGL (glvnd pointed at no EGL vendor): one line saying what is missing, exit code
// 2, no file; facet's own backend is unaffected.
TEST(GlTwinCli, NoOpenGLIsOneLineAndExitCodeTwo) {
  const auto dir = test::fresh_test_dir("facet_gl_twin_", "no_gl");
  const std::string out = (dir / "out.png").string();
  const std::string command = std::string("__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json ") +
                              FACET_CLI + " render --scene shapes --size 64x36 -o " + out;
  const test::CommandResult result = test::run_command(command + " --backend gl");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.stderr_text.find("facet: error: OpenGL backend: no EGL display"), 0u)
      << result.stderr_text;
  EXPECT_EQ(std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n'), 1)
      << result.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(test::run_command(command).exit_code, 0);
}

TEST(GlTwinCli, UnknownBackendIsAUsageError) {
  const auto dir = test::fresh_test_dir("facet_gl_twin_", "bad_backend");
  const test::CommandResult result =
      test::run_command(std::string(FACET_CLI) + " render --scene shapes --backend vulkan -o " +
                        (dir / "out.png").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.stderr_text.find("--backend: expected facet or gl, got 'vulkan'"),
            std::string::npos)
      << result.stderr_text;
}

// The twin frees the GPU copies of meshes and textures no frame has used for a while (60
// frames): a scene drawn again after that is uploaded again and drawn the same.
TEST(GlTwin, SceneDrawnAgainAfterItsCopiesWereFreed) {
  REQUIRE_GL(gl);
  const Views shapes = scene_named("shapes");
  const Framebuffer first = gl_image(*gl, shapes.scene, shapes.camera);
  Scene other;
  Mesh triangle;
  triangle.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  other.add_object(std::move(triangle), Material{});
  Framebuffer small(8, 8);
  for (int frame = 0; frame < 62; ++frame) gl->render(other, Camera{}, small);
  const Framebuffer again = gl_image(*gl, shapes.scene, shapes.camera);
  EXPECT_EQ(first.rgba8(), again.rgba8());
}

TEST(GlTwin, ADepthOnlyFramebufferIsRefused) {
  REQUIRE_GL(gl);
  const Views shapes = scene_named("shapes");
  Framebuffer depth = Framebuffer::depth_only(8, 8);
  EXPECT_THROW(gl->render(shapes.scene, shapes.camera, depth), Error);
}

// --- The fill rule, where an edge runs exactly through pixel centres ------------------------

// Two unlit quads, red above (or left of) blue, sharing an edge through the centres of row 3 (or
// column 4) of an 8x8 image: which one each renderer gives those pixels. Returns the image's
// middle column (horizontal edge) or middle row (vertical edge) as 'r' and 'b'.
std::string shared_edge_owner(GlRenderer* gl, bool horizontal) {
  Scene scene;
  auto quad = [&](glm::vec2 low, glm::vec2 high, glm::vec4 color) {
    Mesh m;
    m.positions = {{low.x, low.y, 0}, {high.x, low.y, 0}, {high.x, high.y, 0}, {low.x, high.y, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    Material material;
    material.shading = ShadingModel::unlit;
    material.base_color = color;
    scene.add_object(std::move(m), material);
  };
  // One unit per pixel: pixel centres at -3.5 ... 3.5; row 3's and column 4's at 0.5.
  if (horizontal) {
    quad({-4, 0.5f}, {4, 4}, {1, 0, 0, 1});
    quad({-4, -4}, {4, 0.5f}, {0, 0, 1, 1});
  } else {
    quad({-4, -4}, {0.5f, 4}, {1, 0, 0, 1});
    quad({0.5f, -4}, {4, 4}, {0, 0, 1, 1});
  }
  const Camera camera = Camera::orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 8.0f, 1.0f, 1, 10);
  Framebuffer image(8, 8);
  if (gl) {
    gl->render(scene, camera, image);
  } else {
    image = test::render_scene_image(scene, camera, 8, 8);
  }
  std::string line;
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = horizontal ? image.pixel(4, i) : image.pixel(i, 4);
    line += c.r > 0.5f ? 'r' : c.b > 0.5f ? 'b' : '.';
  }
  return line;
}

// Both renderers cover each pixel of a shared edge once. facet's top-left rule gives a
// horizontal edge's pixels to the triangle below it (the edge is that one's top edge) and a
// vertical edge's to the one on its right (its left edge). llvmpipe agrees on vertical edges
// and gives horizontal ones to the triangle above, in the image as read back (rows top first).
// docs/gl_twin.md, "Fill rule".
TEST(GlTwin, FillRuleOnEdgesThroughPixelCentres) {
  REQUIRE_GL(gl);
  EXPECT_EQ(shared_edge_owner(nullptr, true), "rrrbbbbb");   // row 3 is blue's (below)
  EXPECT_EQ(shared_edge_owner(nullptr, false), "rrrrbbbb");  // column 4 is blue's (right)
  EXPECT_EQ(shared_edge_owner(gl, true), "rrrrbbbb");        // row 3 is red's (above)
  EXPECT_EQ(shared_edge_owner(gl, false), "rrrrbbbb");
}

// docs/gl_twin.md's picture: the islands by facet, by the twin, and their difference x8 (the
// viewer's B key view), side by side. A golden: it fails when either renderer's image moves.
TEST(GlTwinDocs, IslandsSideBySide) {
  REQUIRE_GL(gl);
  constexpr int kPanelWidth = 240, kPanelHeight = 135;
  Views v = scene_named("islands");
  v.camera.aspect = static_cast<float>(kPanelWidth) / kPanelHeight;
  const Framebuffer reference =
      test::render_scene_image(v.scene, v.camera, kPanelWidth, kPanelHeight, twin_settings());
  Framebuffer twin(kPanelWidth, kPanelHeight);
  gl->render(v.scene, v.camera, twin);
  Framebuffer difference = reference;
  cli::show_difference(difference, twin);
  Framebuffer picture(3 * kPanelWidth, kPanelHeight);
  const Framebuffer* panels[] = {&reference, &twin, &difference};
  for (int p = 0; p < 3; ++p) {
    for (int y = 0; y < kPanelHeight; ++y) {
      std::copy_n(panels[p]->rgba8().data() + y * kPanelWidth * 4, kPanelWidth * 4,
                  picture.rgba8().data() + (y * 3 * kPanelWidth + p * kPanelWidth) * 4);
    }
  }
  const auto path = test::fresh_test_dir("facet_gl_twin_", "docs") / "islands.png";
  write_image(picture, path.string());
  test::expect_matches_golden_in(FACET_GL_TWIN_PICTURE_DIR, path.string(),
                                 "islands_facet_gl_difference");
}

// The viewer's difference view amplifies each channel's difference and is opaque.
TEST(GlTwinView, DifferenceIsAmplifiedPerChannel) {
  Framebuffer a(2, 1), b(2, 1);
  a.rgba8() = {10, 20, 30, 0, 200, 200, 200, 255};
  b.rgba8() = {13, 20, 28, 255, 0, 200, 201, 255};
  cli::show_difference(a, b);
  const std::vector<std::uint8_t> expected = {24, 0, 16, 255, 255, 0, 8, 255};
  EXPECT_EQ(a.rgba8(), expected);
}

}  // namespace
}  // namespace facet
