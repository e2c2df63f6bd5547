// Steady-state frames allocate nothing on the heap: every per-frame container is cleared and
// reused. Counted by replacing the global operator new for this test binary.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <new>

#include "facet/procedural.hpp"
#include "facet/render_texture.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "scenes/bench_scenes.hpp"
#include "support/required_package.hpp"

// Sanitizer runtimes replace operator new themselves (and check that what they allocate is
// freed by their own delete): sanitizer builds leave this file out (tests/CMakeLists.txt).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#error "allocation_test.cpp counts allocations: leave it out of sanitizer builds"
#endif

namespace {
std::atomic<long> g_allocations{0};
}

// The replaced operator new takes its memory from malloc, so its delete hands it to free: they
// match. GCC 12 at -O1 inlines them into gtest's `new TestClass` and warns of a mismatch.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace facet::test {
namespace {

long allocations_in_frames(bench::BenchScene& scene, Renderer& renderer, Framebuffer& fb,
                           int frames) {
  long before = g_allocations.load();
  for (int i = 0; i < frames; ++i) {
    scene.record(renderer, 0.01 * i, fb.width(), fb.height());
    renderer.finish(fb);
  }
  return g_allocations.load() - before;
}

TEST(Allocations, SteadyStateFramesAllocateNothing) {
  // The islands draw their scene's shared meshes (the renderer remembers them).
  for (const char* name : {"overdraw", "million", "islands"}) {
    auto scene = bench::make_bench_scene(name);
    RenderSettings settings;
    settings.threads = 2;
    Renderer renderer(settings);
    Framebuffer fb(320, 180);
    allocations_in_frames(*scene, renderer, fb, 5);  // warm-up: buffers grow to size
    EXPECT_EQ(allocations_in_frames(*scene, renderer, fb, 100), 0) << name;
  }
}

// With shadows, the maps' targets and the passes' draw lists are kept from frame to frame too.
TEST(Allocations, SteadyStateFramesWithShadowsAllocateNothing) {
  for (const char* name : {"shapes", "islands"}) {
    auto scene = bench::make_bench_scene(name);
    RenderSettings settings;
    settings.threads = 2;
    settings.shadows = true;
    settings.shadow_map_size = 256;
    Renderer renderer(settings);
    Framebuffer fb(320, 180);
    allocations_in_frames(*scene, renderer, fb, 5);
    EXPECT_EQ(allocations_in_frames(*scene, renderer, fb, 30), 0) << name;
    EXPECT_GT(renderer.stats().ms_shadows, 0.0) << name << ": no shadow pass ran";
  }
}

// A render texture's frames, its mip chains and depth texture refreshed in place, likewise.
TEST(Allocations, SteadyStateFramesIntoARenderTextureAllocateNothing) {
  auto scene = bench::make_bench_scene("shapes");
  RenderSettings settings;
  settings.threads = 2;
  Renderer renderer(settings);
  RenderTexture target(160, 90, {ColorFormat::rgba8_srgb, true, true});
  auto frames = [&](int count) {
    const long before = g_allocations.load();
    for (int i = 0; i < count; ++i) {
      scene->record(renderer, 0.01 * i, 160, 90);
      renderer.finish(target);
    }
    return g_allocations.load() - before;
  };
  frames(5);
  EXPECT_EQ(frames(30), 0);
}

// glmark2's shadow renders the light's depth map before each frame, refract the back faces'
// normals and depth, with their mip chain: those targets are kept too.
TEST(Allocations, SteadyStateRenderToTextureBenchFramesAllocateNothing) {
  FACET_REQUIRE_PACKAGE(std::filesystem::is_directory("/usr/share/glmark2/models"),
                        "/usr/share/glmark2 missing (Debian package glmark2-data)");
  for (const char* name : {"shadow", "refract"}) {
    SCOPED_TRACE(name);
    auto scene = bench::make_bench_scene(name);
    RenderSettings settings;
    settings.threads = 2;
    Renderer renderer(settings);
    Framebuffer fb(320, 180);
    allocations_in_frames(*scene, renderer, fb, 5);
    EXPECT_EQ(allocations_in_frames(*scene, renderer, fb, 30), 0);
  }
}

// Materials keep their names (glTF's are often long), but a frame's copies of them must not
// allocate: with shadows and a mirror, each draw is copied into several passes.
TEST(Allocations, SteadyStateFramesOfLongNamedMaterialsAllocateNothing) {
  RenderSettings settings;
  settings.threads = 2;
  settings.shadows = true;
  settings.shadow_map_size = 256;
  settings.reflections = true;
  Renderer renderer(settings);
  Framebuffer fb(160, 90);
  const Mesh ball = uv_sphere(0.5f, 16, 8), floor = plane(6.0f, 6.0f);
  Material ball_material, floor_material;
  ball_material.name = "a material whose name no short-string buffer holds";
  floor_material.name = "the floor, a mirror, also named at some length";
  floor_material.reflects_scene = true;
  floor_material.reflectivity = 0.5f;
  floor_material.shading = ShadingModel::phong;
  const Camera camera = Camera::look_at({0.0f, 2.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                                        50.0f, 160.0f / 90.0f, 0.1f, 50.0f);
  auto frames = [&](int count) {
    const long before = g_allocations.load();
    for (int i = 0; i < count; ++i) {
      renderer.begin_frame(camera);
      renderer.draw(floor, floor_material);
      renderer.draw(ball, ball_material, glm::translate(glm::mat4(1.0f), {0.0f, 0.6f, 0.0f}));
      renderer.finish(fb);
    }
    return g_allocations.load() - before;
  };
  frames(5);
  EXPECT_EQ(frames(20), 0);
  EXPECT_GT(renderer.stats().ms_shadows, 0.0) << "no shadow pass ran";
  EXPECT_GT(renderer.stats().ms_reflections, 0.0) << "no reflection pass ran";
}

TEST(Allocations, TheCounterSeesAllocations) {
  long before = g_allocations.load();
  void* p = ::operator new(16);  // a new-expression could be elided; this call cannot
  ::operator delete(p);
  EXPECT_GT(g_allocations.load(), before);
}

}  // namespace
}  // namespace facet::test
