// facet_classic_demo: draws a scene with one of the classic rasterizers (src/classic,
// docs/classic/) and says how long it took; with --costs, measures what each costs per covered
// pixel and per triangle, the numbers the chapters quote. A rough teaching measure: one thread,
// processor time (less disturbed than wall-clock time on a busy machine), the best of a few
// runs.
//
//   facet_classic_demo SCENE OUT.png [--method bounding_box|scanline|ray_per_pixel]
//                      [--size WxH] [--no-fill-rule] [--repeat N]
//   facet_classic_demo --costs
//
// SCENE is `triangle`, a built-in scene (`shapes`, ...) or a model file.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iterator>
#include <string>
#include <vector>

#include "classic/classic.hpp"
#include "facet/error.hpp"
#include "facet/image_io.hpp"
#include "facet/import.hpp"
#include "facet/worlds.hpp"

namespace {

using facet::classic::Method;

const char* const kMethodNames[] = {"bounding_box", "scanline", "ray_per_pixel"};

struct Usage {
  std::string what;
};

facet::Scene load(const std::string& name) {
  if (name == "triangle") return facet::classic::make_triangle_scene();
  const std::vector<std::string> builtin = facet::builtin_scene_names();
  if (std::find(builtin.begin(), builtin.end(), name) != builtin.end()) {
    return facet::make_builtin_scene(name);
  }
  facet::ImportOptions options;
  options.warn = [](const std::string&) {};
  return facet::import_scene(name, options);
}

// The best of `repeat` draws, in seconds; the last image stays in `image`.
double time_draw(const facet::Scene& scene, const facet::Camera& camera,
                 const facet::classic::Options& options, int repeat, facet::classic::Image& image) {
  double best = 1e30;
  for (int r = 0; r < repeat; ++r) {
    image = facet::classic::Image(image.width, image.height);
    const std::clock_t start = std::clock();
    facet::classic::draw_scene(scene, camera, options, image);
    best = std::min(best, static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
  }
  return best;
}

// A scene of `count` triangles in a grid of squares facing the camera, each `side` pixels wide
// in a width x height image: large ones measure the cost per pixel, tiny ones the cost per
// triangle.
facet::Scene grid(int width, int height, int across, float fill) {
  facet::Mesh mesh;
  const int down = std::max(1, across * height / width);
  const float cell = 2.0f / across;
  for (int j = 0; j < down; ++j) {
    for (int i = 0; i < across; ++i) {
      const float x = -1.0f + (i + 0.5f) * cell, y = 1.0f - (j + 0.5f) * cell;
      const float h = 0.5f * cell * fill;
      mesh.positions.insert(mesh.positions.end(),
                            {{x - h, y - h, 0}, {x + h, y - h, 0}, {x - h, y + h, 0}});
    }
  }
  facet::Scene scene;
  scene.add_object(std::move(mesh), facet::Material{});
  // Orthographic, a view exactly 2 units wide: the grid fills the image's width.
  scene.camera = facet::Camera::orthographic({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 2.0f * height / width,
                                             static_cast<float>(width) / height, 0.1f, 10.0f);
  return scene;
}

int costs() {
  constexpr int kWidth = 640, kHeight = 360;
  const facet::Scene large = grid(kWidth, kHeight, 8, 0.95f),
                     tiny = grid(kWidth, kHeight, 320, 0.3f);
  std::printf("%-14s %16s %16s\n", "method", "ns per pixel", "ns per triangle");
  for (int m = 0; m < 3; ++m) {
    facet::classic::Options options;
    options.method = static_cast<Method>(m);
    facet::classic::Image image(kWidth, kHeight);
    const double large_time = time_draw(large, large.camera, options, 9, image);
    long covered = 0;
    for (std::uint16_t h : image.hits) covered += h;
    const double tiny_time = time_draw(tiny, tiny.camera, options, 9, image);
    const double triangles = static_cast<double>(tiny.triangle_count());
    std::printf("%-14s %16.2f %16.1f\n", kMethodNames[m], large_time * 1e9 / covered,
                tiny_time * 1e9 / triangles);
  }
  return 0;
}

int run(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--costs") return costs();
  if (argc < 3) throw Usage{"needs SCENE OUT.png (or --costs)"};
  facet::classic::Options options;
  int width = 320, height = 180, repeat = 1;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--method" && has_value) {
      const std::string name = argv[++i];
      const auto* found = std::find(std::begin(kMethodNames), std::end(kMethodNames), name);
      if (found == std::end(kMethodNames)) throw Usage{"unknown method '" + name + "'"};
      options.method = static_cast<Method>(found - std::begin(kMethodNames));
    } else if (arg == "--size" && has_value) {
      if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 1 || height < 1 ||
          width > 8192 || height > 8192) {
        throw Usage{"--size wants WxH within 1..8192, not '" + std::string(argv[i]) + "'"};
      }
    } else if (arg == "--repeat" && has_value) {
      repeat = std::atoi(argv[++i]);
      if (repeat < 1 || repeat > 1000) throw Usage{"--repeat wants 1..1000"};
    } else if (arg == "--no-fill-rule") {
      options.fill_rule = false;
    } else {
      throw Usage{"unknown or incomplete option '" + arg + "'"};
    }
  }
  const facet::Scene scene = load(argv[1]);
  facet::Camera camera =
      facet::scene_camera(scene, static_cast<float>(width) / static_cast<float>(height));
  camera.aspect = static_cast<float>(width) / static_cast<float>(height);
  facet::classic::Image image(width, height);
  const double seconds = time_draw(scene, camera, options, repeat, image);
  facet::write_image(facet::classic::to_framebuffer(image), argv[2]);
  std::printf("%s: %.2f ms for %zu triangles at %dx%d\n",
              kMethodNames[static_cast<int>(options.method)], seconds * 1e3, scene.triangle_count(),
              width, height);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const Usage& usage) {
    std::fprintf(stderr, "facet_classic_demo: %s\n", usage.what.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facet_classic_demo: %s\n", e.what());
    return 2;
  }
}
