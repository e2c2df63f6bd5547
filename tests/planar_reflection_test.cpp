// Planar reflections (Material::reflects_scene, RenderSettings::reflections): a mirror floor
// shows what a render of the scene mirrored through it shows, what lies behind the plane is cut
// away, rougher surfaces blur it, the images are the same for any thread count, tile size and
// SIMD target, and the plane of a mirror draw is found (or refused) as mirror.hpp says.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/procedural.hpp"
#include "pipeline/geometry/clip.hpp"
#include "pipeline/reflection/mirror.hpp"
#include "support/forced_target.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr float kFloor = 20.0f;  // the mirror's side, centred on the origin at y = 0

Camera view_camera() {
  return Camera::look_at({0.0f, 2.0f, 6.0f}, {0.0f, 0.5f, 0.0f}, {0, 1, 0}, 50.0f,
                         static_cast<float>(kWidth) / kHeight, 0.5f, 40.0f);
}

Material unlit(glm::vec3 color) {
  Material m;
  m.shading = ShadingModel::unlit;
  m.base_color = glm::vec4(color, 1.0f);
  m.cull = CullMode::none;  // also drawn mirrored, which reverses the winding
  return m;
}

// A metallic white PBR mirror of the given roughness: it shows what it reflects, dimmed as it
// roughens.
Material pbr_mirror(float roughness) {
  Material m;
  m.shading = ShadingModel::pbr;
  m.metallic = 1.0f;
  m.roughness = roughness;
  m.reflects_scene = true;
  return m;
}

// Above the plane: a red box on the left, a green one on the right, so that a reflection
// flipped left to right or upside down shows. `mirror` places them mirrored through y = 0;
// `mask` draws them black (floor_pixels).
void add_boxes(Scene& scene, bool mirror, bool mask = false) {
  const glm::mat4 flip = glm::scale(glm::mat4(1.0f), {1.0f, mirror ? -1.0f : 1.0f, 1.0f});
  const Material black = unlit(glm::vec3(0.0f));
  scene.add_object(box({1.0f, 1.0f, 1.0f}), mask ? black : unlit({0.9f, 0.1f, 0.1f}),
                   flip * glm::translate(glm::mat4(1.0f), {-1.2f, 0.8f, 0.0f}));
  scene.add_object(box({0.8f, 1.6f, 0.8f}), mask ? black : unlit({0.1f, 0.8f, 0.2f}),
                   flip * glm::translate(glm::mat4(1.0f), {1.0f, 1.1f, -1.0f}));
}

Scene mirror_scene(const Material& floor, const Fog& fog = {}) {
  Scene scene;
  scene.add_object(plane(kFloor, kFloor), floor);
  add_boxes(scene, false);
  scene.lighting.ambient = glm::vec3(0.0f);
  scene.lighting.fog = fog;
  return scene;
}

RenderSettings full_size_reflections() {
  RenderSettings settings;
  settings.clear_color = {0.1f, 0.2f, 0.6f, 1.0f};
  settings.reflection_scale = 1.0f;  // texel for pixel: the reflection as sharp as the view
  return settings;
}

// What a perfect mirror floor should show: a render of the boxes and their mirror images,
// without the floor, under the same fog.
Framebuffer mirrored_reference(const Camera& camera, const Fog& fog = {}) {
  Scene mirrored;
  add_boxes(mirrored, false);
  add_boxes(mirrored, true);
  mirrored.lighting.fog = fog;
  return render_scene_image(mirrored, camera, kWidth, kHeight, full_size_reflections());
}

// The floor's pixels the boxes leave in view, less a pixel along their outlines: where only
// the mirror is seen.
std::vector<bool> floor_pixels(const Camera& camera) {
  Scene scene;
  scene.add_object(plane(kFloor, kFloor), unlit(glm::vec3(1.0f)));
  add_boxes(scene, false, true);
  RenderSettings settings;
  settings.clear_color = {0.0f, 0.0f, 0.0f, 1.0f};
  const Framebuffer fb = render_scene_image(scene, camera, kWidth, kHeight, settings);
  std::vector<bool> inside(static_cast<std::size_t>(kWidth) * kHeight, false);
  const auto white = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < kWidth && y < kHeight &&
           fb.rgba8()[(static_cast<std::size_t>(y) * kWidth + x) * 4] == 255;
  };
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      inside[static_cast<std::size_t>(y) * kWidth + x] =
          white(x, y) && white(x - 1, y) && white(x + 1, y) && white(x, y - 1) && white(x, y + 1);
    }
  }
  return inside;
}

// How many of the floor's pixels differ from the reference by more than `tolerance` codes in a
// channel, and how many show the red or the green box.
struct MirrorCompare {
  int floor = 0, differing = 0, red = 0, green = 0;
};
MirrorCompare compare_floor(const Framebuffer& image, const Framebuffer& reference,
                            const std::vector<bool>& floor, int tolerance) {
  MirrorCompare c;
  for (std::size_t i = 0; i < floor.size(); ++i) {
    if (!floor[i]) continue;
    ++c.floor;
    const std::uint8_t* a = &image.rgba8()[i * 4];
    const std::uint8_t* b = &reference.rgba8()[i * 4];
    bool differs = false;
    for (int k = 0; k < 3; ++k) differs |= std::abs(int(a[k]) - int(b[k])) > tolerance;
    c.differing += differs;
    c.red += a[0] > 150 && a[1] < 120;
    c.green += a[1] > 150 && a[0] < 120;
  }
  return c;
}

// The cameras the mirror is seen through: the test's, one with its lens shifted, and an
// orthographic one.
std::vector<Camera> mirror_cameras() {
  Camera shifted = view_camera();
  shifted.lens_shift = {0.15f, -0.1f};
  const Camera parallel =
      Camera::orthographic({0.0f, 2.0f, 6.0f}, {0.0f, 0.5f, 0.0f}, {0, 1, 0}, 5.0f,
                           static_cast<float>(kWidth) / kHeight, 0.5f, 40.0f);
  return {view_camera(), shifted, parallel};
}

// The mirror shows, pixel for pixel, what a render of the boxes and their mirror images shows
// there (edges aside: the two renders rasterize mirrored edges), through each camera; under
// fog too, which fogs what the mirror shows over the whole path from the eye, once.
TEST(PlanarReflection, ShowsTheSceneMirroredThroughThePlane) {
  Fog fog;
  fog.mode = FogMode::exponential;
  fog.density = 0.15f;
  fog.color = {0.5f, 0.5f, 0.45f};
  for (const Fog& f : {Fog{}, fog}) {
    int view = 0;
    for (const Camera& camera : mirror_cameras()) {
      const Framebuffer image = render_scene_image(mirror_scene(phong_mirror(), f), camera, kWidth,
                                                   kHeight, full_size_reflections());
      const Framebuffer reference = mirrored_reference(camera, f);
      const MirrorCompare c = compare_floor(image, reference, floor_pixels(camera), 24);
      const std::string where =
          "camera " + std::to_string(view++) + (f.mode == FogMode::none ? "" : ", fog");
      ASSERT_GT(c.floor, kWidth * kHeight / 5) << where;
      if (f.mode == FogMode::none) {  // (fogged, they are no longer pure red and green)
        EXPECT_GT(c.red, 100) << where << ": the red box's reflection";
        EXPECT_GT(c.green, 100) << where << ": the green box's reflection";
      }
      EXPECT_LT(c.differing, c.floor / 50)
          << where << ": " << c.differing << " of " << c.floor << " floor pixels";
    }
  }
}

// A box shaded by the texcoords view (display values: what the screen shows, not light) is
// mirrored as it is shown, not as if its values were light.
TEST(PlanarReflection, ShowsDisplayValuesAsTheyAreShown) {
  const Camera camera = view_camera();
  Material uvs = unlit(glm::vec3(1.0f));
  uvs.shading = ShadingModel::texcoords;
  const glm::mat4 place = glm::translate(glm::mat4(1.0f), {0.0f, 1.2f, -1.0f});
  const glm::mat4 flip = glm::scale(glm::mat4(1.0f), {1.0f, -1.0f, 1.0f});
  Scene scene;
  scene.add_object(plane(kFloor, kFloor), phong_mirror());
  scene.add_object(box(glm::vec3(2.0f)), uvs, place);
  Scene reference_scene;
  reference_scene.add_object(box(glm::vec3(2.0f)), uvs, place);
  reference_scene.add_object(box(glm::vec3(2.0f)), uvs, flip * place);
  Scene mask;
  mask.add_object(plane(kFloor, kFloor), unlit(glm::vec3(1.0f)));
  mask.add_object(box(glm::vec3(2.0f)), unlit(glm::vec3(0.0f)), place);
  const Framebuffer image =
      render_scene_image(scene, camera, kWidth, kHeight, full_size_reflections());
  const Framebuffer reference =
      render_scene_image(reference_scene, camera, kWidth, kHeight, full_size_reflections());
  const Framebuffer floor = render_scene_image(mask, camera, kWidth, kHeight);
  std::vector<bool> pixels(static_cast<std::size_t>(kWidth) * kHeight);
  int shown = 0;  // mirror pixels showing the box
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    pixels[i] = floor.rgba8()[i * 4] == 255;
    shown += pixels[i] && reference.rgba8()[i * 4 + 2] == 0;  // texcoords: blue 0
  }
  ASSERT_GT(shown, 1000);
  const MirrorCompare c = compare_floor(image, reference, pixels, 24);
  EXPECT_LT(c.differing, shown / 20) << c.differing << " of " << shown << " pixels of the box";
}

// Blended draws are mirrored as they are drawn over what is behind them: a red glass before
// the green box, a blue one before both.
TEST(PlanarReflection, MirrorsBlendedDrawsInTheirOrder) {
  const Camera camera = view_camera();
  const auto add_glass = [](Scene& scene, bool mirror) {
    const glm::mat4 flip = glm::scale(glm::mat4(1.0f), {1.0f, mirror ? -1.0f : 1.0f, 1.0f});
    Material red = unlit({1.0f, 0.2f, 0.2f}), blue = unlit({0.2f, 0.3f, 1.0f});
    red.base_color.a = 0.5f, blue.base_color.a = 0.4f;
    red.alpha_mode = blue.alpha_mode = AlphaMode::blend;
    scene.add_object(box({1.2f, 1.2f, 0.1f}), red,
                     flip * glm::translate(glm::mat4(1.0f), {1.0f, 1.0f, 0.0f}));
    scene.add_object(box({3.0f, 0.8f, 0.1f}), blue,
                     flip * glm::translate(glm::mat4(1.0f), {0.0f, 0.6f, 1.5f}));
  };
  Scene scene = mirror_scene(phong_mirror());
  add_glass(scene, false);
  Scene reference_scene;
  add_boxes(reference_scene, false);
  add_boxes(reference_scene, true);
  add_glass(reference_scene, false);
  add_glass(reference_scene, true);
  const Framebuffer image =
      render_scene_image(scene, camera, kWidth, kHeight, full_size_reflections());
  const Framebuffer reference =
      render_scene_image(reference_scene, camera, kWidth, kHeight, full_size_reflections());
  // The floor's pixels that neither the boxes nor the glasses cover.
  Scene mask;
  mask.add_object(plane(kFloor, kFloor), unlit(glm::vec3(1.0f)));
  add_boxes(mask, false, true);
  Material black = unlit(glm::vec3(0.0f));
  mask.add_object(box({1.2f, 1.2f, 0.1f}), black,
                  glm::translate(glm::mat4(1.0f), {1.0f, 1.0f, 0.0f}));
  mask.add_object(box({3.0f, 0.8f, 0.1f}), black,
                  glm::translate(glm::mat4(1.0f), {0.0f, 0.6f, 1.5f}));
  const Framebuffer floor = render_scene_image(mask, camera, kWidth, kHeight);
  std::vector<bool> pixels(static_cast<std::size_t>(kWidth) * kHeight);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = floor.rgba8()[i * 4] == 255;
  const MirrorCompare c = compare_floor(image, reference, pixels, 24);
  ASSERT_GT(c.floor, kWidth * kHeight / 5);
  EXPECT_LT(c.differing, c.floor / 50) << c.differing << " of " << c.floor << " floor pixels";
  EXPECT_FALSE(image.rgba8() == render_scene_image(mirror_scene(phong_mirror()), camera, kWidth,
                                                   kHeight, full_size_reflections())
                                    .rgba8());
}

// A frame's reflections depend on that frame alone: a renderer that drew another view first (a
// mirror seen smaller, its pass cropped otherwise) draws the same bytes as a fresh one.
TEST(PlanarReflection, AFrameIsTheSameWhateverCameBefore) {
  const Scene scene = mirror_scene(pbr_mirror(0.3f));
  const Camera first = Camera::look_at({6.0f, 9.0f, 14.0f}, {0.0f, 0.0f, 0.0f}, {0, 1, 0}, 30.0f,
                                       static_cast<float>(kWidth) / kHeight, 0.5f, 60.0f);
  const auto render = [&](Renderer& renderer, const Camera& camera) {
    Framebuffer fb(kWidth, kHeight);
    renderer.begin_frame(camera, scene.lighting);
    draw_scene(renderer, scene);
    renderer.finish(fb);
    return fb;
  };
  Renderer fresh, used;
  render(used, first);
  EXPECT_TRUE(render(used, view_camera()).rgba8() == render(fresh, view_camera()).rgba8());
}

// A small mirror, whose pass is cropped to where it is seen (a corner of the view), shows the
// same: its texels are the full pass's.
TEST(PlanarReflection, ASmallMirrorShowsTheSame) {
  const Camera camera = view_camera();
  Scene scene;
  const glm::mat4 corner = glm::translate(glm::mat4(1.0f), {-1.5f, 0.0f, 1.5f});
  scene.add_object(plane(3.0f, 3.0f), phong_mirror(), corner);
  add_boxes(scene, false);
  scene.lighting.ambient = glm::vec3(0.0f);
  const Framebuffer image =
      render_scene_image(scene, camera, kWidth, kHeight, full_size_reflections());
  const Framebuffer reference = mirrored_reference(camera);
  // The small mirror's pixels: the floor's where the small mirror lies.
  Scene small;
  small.add_object(plane(3.0f, 3.0f), unlit(glm::vec3(1.0f)), corner);
  const Framebuffer mask = render_scene_image(small, camera, kWidth, kHeight);
  std::vector<bool> pixels = floor_pixels(camera);
  for (std::size_t i = 0; i < pixels.size(); ++i)
    pixels[i] = pixels[i] && mask.rgba8()[i * 4] == 255;
  const MirrorCompare c = compare_floor(image, reference, pixels, 24);
  ASSERT_GT(c.floor, 500);
  EXPECT_GT(c.red, 50) << "the red box's reflection";
  EXPECT_LT(c.differing, c.floor / 50) << c.differing << " of " << c.floor << " mirror pixels";
}

// A quad under the floor, between the mirrored eye and the plane, its far end rising above
// the plane only beyond the far plane: cut at the mirror's plane, it never hides the
// reflection (whole-draw culling cannot drop it: its bounds cross the plane).
TEST(PlanarReflection, CutsWhatLiesBehindThePlane) {
  const Camera camera = view_camera();
  Scene scene = mirror_scene(phong_mirror());
  const glm::mat4 tilted = glm::translate(glm::mat4(1.0f), {0.0f, -0.3f, -25.0f}) *
                           glm::rotate(glm::mat4(1.0f), 0.012f, {1.0f, 0.0f, 0.0f});
  scene.add_object(plane(60.0f, 70.0f), unlit({0.0f, 0.0f, 1.0f}), tilted);
  const Framebuffer image =
      render_scene_image(scene, camera, kWidth, kHeight, full_size_reflections());
  const Framebuffer reference = mirrored_reference(camera);
  const MirrorCompare c = compare_floor(image, reference, floor_pixels(camera), 24);
  EXPECT_LT(c.differing, c.floor / 50) << c.differing << " of " << c.floor << " floor pixels";
}

// Sum of the squared differences between horizontal neighbours on the floor: how sharp what it
// shows is. (Squared: a blur spreads a step over several pixels, whose absolute differences add
// up to the step's as before.)
double sharpness(const Framebuffer& image, const std::vector<bool>& floor) {
  double edges = 0.0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x + 1 < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
      if (!floor[i] || !floor[i + 1]) continue;
      for (int k = 0; k < 3; ++k) {
        const double d = int(image.rgba8()[i * 4 + k]) - int(image.rgba8()[(i + 1) * 4 + k]);
        edges += d * d;
      }
    }
  }
  return edges;
}

// A rough mirror shows the boxes blurred: its edges weaker than a smooth one's. (Phong: its
// reflection is not dimmed as it roughens, as PBR's is.)
TEST(PlanarReflection, RougherSurfacesBlurIt) {
  const Camera camera = view_camera();
  const std::vector<bool> floor = floor_pixels(camera);
  Material rough = phong_mirror();
  rough.shininess = 8.0f;
  const double smooth_edges =
      sharpness(render_scene_image(mirror_scene(phong_mirror()), camera, kWidth, kHeight,
                                   full_size_reflections()),
                floor);
  const double rough_edges = sharpness(
      render_scene_image(mirror_scene(rough), camera, kWidth, kHeight, full_size_reflections()),
      floor);
  ASSERT_GT(smooth_edges, 0.0);
  EXPECT_LT(rough_edges, 0.5 * smooth_edges)
      << "smooth " << smooth_edges << ", rough " << rough_edges;
}

// Off, or on a material that does not ask, the mirror shows the environment alone (here none:
// black); on, the pass is timed.
TEST(PlanarReflection, OnlyWhereAskedAndOnlyWhenOn) {
  const Camera camera = view_camera();
  RenderSettings off = full_size_reflections();
  off.reflections = false;
  Material plain_mirror = phong_mirror();
  plain_mirror.reflects_scene = false;
  const Framebuffer without =
      render_scene_image(mirror_scene(plain_mirror), camera, kWidth, kHeight, off);
  EXPECT_TRUE(
      render_scene_image(mirror_scene(phong_mirror()), camera, kWidth, kHeight, off).rgba8() ==
      without.rgba8());
  EXPECT_TRUE(render_scene_image(mirror_scene(plain_mirror), camera, kWidth, kHeight,
                                 full_size_reflections())
                  .rgba8() == without.rgba8());
  const Framebuffer with = render_scene_image(mirror_scene(phong_mirror()), camera, kWidth, kHeight,
                                              full_size_reflections());
  EXPECT_FALSE(with.rgba8() == without.rgba8());

  Renderer renderer(full_size_reflections());
  Framebuffer fb(kWidth, kHeight);
  const Scene scene = mirror_scene(phong_mirror());
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(fb);
  EXPECT_GT(renderer.stats().ms_reflections, 0.0);
}

// A mirror under a shadowing sun, at the default half size, with a PBR sphere reflected: the
// same bytes for any thread count, tile size and SIMD target.
TEST(PlanarReflection, SameImageForAnyThreadsTilesAndSimdTarget) {
  Scene scene = mirror_scene(pbr_mirror(0.2f));
  Material ball;
  ball.shading = ShadingModel::pbr;
  ball.base_color = {0.8f, 0.6f, 0.3f, 1.0f};
  scene.add_object(uv_sphere(0.6f), ball, glm::translate(glm::mat4(1.0f), {0.2f, 0.7f, 1.2f}));
  scene.lighting.lights = {Light::directional({0.4f, -1.0f, -0.3f}, glm::vec3(1.0f), 2.0f)};
  scene.lighting.ambient = glm::vec3(0.1f);
  const Camera camera = view_camera();
  RenderSettings base;
  base.shadows = true;
  base.threads = 1;
  const Framebuffer expected = render_scene_image(scene, camera, kWidth, kHeight, base);
  for (int msaa : {1, 4}) {
    RenderSettings first = base;
    first.msaa = msaa;
    const Framebuffer reference = render_scene_image(scene, camera, kWidth, kHeight, first);
    for (int threads : {2, 3}) {
      for (int tile : {16, 128}) {
        RenderSettings s = first;
        s.threads = threads;
        s.tile_size = tile;
        EXPECT_TRUE(render_scene_image(scene, camera, kWidth, kHeight, s).rgba8() ==
                    reference.rgba8())
            << threads << " threads, tiles of " << tile << ", msaa " << msaa;
      }
    }
  }
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    EXPECT_TRUE(render_scene_image(scene, camera, kWidth, kHeight, base).rgba8() ==
                expected.rgba8())
        << hwy::TargetName(target);
  }
}

TEST(PlanarReflection, RefusesAScaleOutsideZeroToOne) {
  for (float scale : {0.0f, -0.5f, 1.5f, NAN}) {
    RenderSettings settings;
    settings.reflection_scale = scale;
    EXPECT_THROW(Renderer{settings}, Error) << scale;
  }
}

// --- The geometry (mirror.hpp) ---

TEST(MirrorPlane, OfAFlatMeshFacingTheEye) {
  const glm::mat4 raised = glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, 0.0f});
  const auto above =
      pipeline::mirror_plane(plane(4.0f, 4.0f), raised, {1.0f, 5.0f, 1.0f}, CullMode::none);
  ASSERT_TRUE(above);
  EXPECT_NEAR(above->y, 1.0f, 1e-6f);
  EXPECT_NEAR(above->w, -2.0f, 1e-6f);
  const auto below =
      pipeline::mirror_plane(plane(4.0f, 4.0f), raised, {1.0f, -5.0f, 1.0f}, CullMode::none);
  ASSERT_TRUE(below);
  EXPECT_TRUE(pipeline::same_plane(*below, -*above));
  EXPECT_FALSE(pipeline::same_plane(*below, *above));
  // The side its culling drops (the plane faces +y, counter-clockwise from above): none.
  EXPECT_TRUE(
      pipeline::mirror_plane(plane(4.0f, 4.0f), raised, {1.0f, 5.0f, 1.0f}, CullMode::back));
  EXPECT_FALSE(
      pipeline::mirror_plane(plane(4.0f, 4.0f), raised, {1.0f, -5.0f, 1.0f}, CullMode::back));
  EXPECT_FALSE(
      pipeline::mirror_plane(plane(4.0f, 4.0f), raised, {1.0f, 5.0f, 1.0f}, CullMode::front));
  // Not flat, seen edge-on, no area: none.
  EXPECT_FALSE(
      pipeline::mirror_plane(box({1.0f, 1.0f, 1.0f}), raised, {0.0f, 5.0f, 0.0f}, CullMode::none));
  EXPECT_FALSE(
      pipeline::mirror_plane(plane(4.0f, 4.0f), raised, {9.0f, 2.0f, 0.0f}, CullMode::none));
  Mesh line_like;
  line_like.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_FALSE(
      pipeline::mirror_plane(line_like, glm::mat4(1.0f), {0.0f, 5.0f, 0.0f}, CullMode::none));
}

// The mirrored camera sees a point's mirror image where the camera sees the point in the mirror:
// a point on the plane lands at the same place in both views (its own reflection).
TEST(MirrorPlane, MirroredCameraSeesThePlaneWhereTheCameraDoes) {
  const Camera camera = view_camera();
  const glm::vec4 floor(0.0f, 1.0f, 0.0f, 0.0f);
  const Camera mirrored = pipeline::mirrored_camera(camera, floor);
  EXPECT_NEAR(mirrored.eye.y, -camera.eye.y, 1e-6f);
  const glm::mat4 to_image = pipeline::mirror_image_transform(mirrored);
  for (const glm::vec3 p : {glm::vec3(0.5f, 0.0f, 1.0f), glm::vec3(-2.0f, 0.0f, -3.0f)}) {
    const glm::vec4 c = camera.view_projection() * glm::vec4(p, 1.0f);
    const glm::vec4 t = to_image * glm::vec4(p, 1.0f);
    // The camera's image, flipped left to right: the mirrored camera's view is the mirror image.
    EXPECT_NEAR(t.x / t.w, 0.5f - 0.5f * c.x / c.w, 1e-5f);
    EXPECT_NEAR(t.y / t.w, 0.5f + 0.5f * c.y / c.w, 1e-5f);
  }
}

// The cropped camera sees a rectangle of the camera's image as its whole image: a point at
// NDC p there is at (p - centre) / half in the cropped view, perspective and orthographic.
TEST(MirrorPlane, CroppedCameraSeesItsRectangle) {
  pipeline::NdcRect rect;
  rect.low = {-0.2f, -1.0f}, rect.high = {0.6f, 0.1f};
  Camera shifted = view_camera();
  shifted.lens_shift = {0.1f, -0.05f};
  const Camera ortho =
      Camera::orthographic({0, 2, 6}, {0, 0.5f, 0}, {0, 1, 0}, 3.0f, 1.3f, 0.5f, 40);
  for (const Camera& camera : {view_camera(), shifted, ortho}) {
    const Camera cropped = pipeline::cropped_camera(camera, rect);
    const glm::vec2 centre = (rect.low + rect.high) * 0.5f, half = (rect.high - rect.low) * 0.5f;
    for (const glm::vec3 p : {glm::vec3(0.3f, 0.2f, 0.5f), glm::vec3(-1.0f, 1.0f, -2.0f)}) {
      const glm::vec4 c = camera.view_projection() * glm::vec4(p, 1.0f);
      const glm::vec4 k = cropped.view_projection() * glm::vec4(p, 1.0f);
      const glm::vec2 expected = (glm::vec2(c) / c.w - centre) / half;
      EXPECT_NEAR(k.x / k.w, expected.x, 1e-4f);
      EXPECT_NEAR(k.y / k.w, expected.y, 1e-4f);
    }
  }
}

// Clipping against the user plane keeps exactly the part of a triangle in front of it.
TEST(MirrorPlane, ClipperCutsAtTheUserPlane) {
  pipeline::ClipBounds bounds;
  bounds.clips_user_plane = true;
  bounds.user_plane = {0.0f, 1.0f, 0.0f, -0.25f};  // y >= 0.25 w
  pipeline::ClipPolygon polygon;
  polygon.count = 3;
  polygon.vertices[0].clip = {-1.0f, -1.0f, 0.0f, 1.0f};
  polygon.vertices[1].clip = {1.0f, -1.0f, 0.0f, 1.0f};
  polygon.vertices[2].clip = {0.0f, 1.0f, 0.0f, 1.0f};
  pipeline::clip_polygon(polygon, pipeline::kClipUser, bounds, 0);
  ASSERT_EQ(polygon.count, 3);  // the tip above y = 0.25
  for (int i = 0; i < polygon.count; ++i) {
    EXPECT_GE(polygon.vertices[i].clip.y, 0.25f - 1e-6f);
  }
}

}  // namespace
}  // namespace facet::test
