// The built-in benchmark scenes (see bench_scenes.hpp).
#include "scenes/bench_scenes.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "facet/islands.hpp"
#include "facet/procedural.hpp"
#include "facet/scene.hpp"
#include "facet/texture.hpp"
#include "facet/worlds.hpp"

namespace facet::bench {
namespace {

const char* kBunnyPath = "/usr/share/glmark2/models/bunny.obj";

std::shared_ptr<const Mesh> load_first_mesh(const std::string& path) {
  if (!std::filesystem::exists(path)) {
    throw Error(path + ": missing (install the Debian package glmark2-data)");
  }
  Scene scene = import_scene(path);
  return scene.meshes.at(0);
}

// A benchmark scene that is a Scene: facet records it with draw_scene, the OpenGL twin draws it
// whole. Its meshes do not change: they are drawn through shared pointers, so the renderer
// checks each once, as a GPU driver checks the vertex buffers glmark2 draws from.
class SceneBench : public BenchScene {
 public:
  void record(Renderer& renderer, double t, int width, int height) override {
    Camera camera;
    const Scene* frame =
        scene_at(t, static_cast<float>(width) / static_cast<float>(height), camera);
    renderer.begin_frame(camera, frame->lighting);
    draw_scene(renderer, *frame);
  }
  const Scene* scene_at(double t, float aspect, Camera& camera) override {
    pose(t, aspect);
    camera = scene_camera(scene_, aspect);
    camera.aspect = aspect;
    return &scene_;
  }

 protected:
  // Moves what the frame at time t moves (the camera's aspect is set after).
  virtual void pose(double /*t*/, float /*aspect*/) {}
  // One node drawing `mesh` with `material`.
  void add_node(std::shared_ptr<const Mesh> mesh, const Material& material) {
    scene_.meshes.push_back(std::move(mesh));
    scene_.materials.push_back(material);
    SceneNode node;
    node.instances.push_back({static_cast<int>(scene_.meshes.size()) - 1,
                              static_cast<int>(scene_.materials.size()) - 1});
    scene_.nodes.push_back(std::move(node));
  }

  Scene scene_;
};

// A built-in world (shapes, teapot) from its own camera, still.
class WorldScene : public SceneBench {
 public:
  explicit WorldScene(const std::string& name) { scene_ = make_builtin_scene(name); }
};

// bunny.obj (70k triangles, indexed) in the normals view, fov 45, near 0.1, far 100, looking
// at the origin from (0, 0.1, distance).
class BunnyScene : public SceneBench {
 public:
  explicit BunnyScene(float distance) {
    Material material;
    material.shading = ShadingModel::normals;
    add_node(load_first_mesh(kBunnyPath), material);
    scene_.camera =
        Camera::look_at({0.0f, 0.1f, distance}, {0, 0, 0}, {0, 1, 0}, 45.0f, 1.0f, 0.1f, 100.0f);
  }
};

// At least a million small triangles: a 16 x 9 grid of spheres of 7,200 triangles each
// (1,036,800 in all), Gouraud-lit, turning slowly.
class MillionScene : public SceneBench {
 public:
  MillionScene() {
    Material material;
    material.shading = ShadingModel::gouraud;
    material.base_color = {0.8f, 0.5f, 0.3f, 1.0f};
    auto sphere = std::make_shared<const Mesh>(uv_sphere(0.45f, 60, 60));
    for (int i = 0; i < kColumns * kRows; ++i) add_node(sphere, material);
    scene_.lighting.lights = {Light::directional({-0.3f, -0.5f, -1.0f})};
    scene_.camera = Camera::look_at({0, 0, 11.5f}, {0, 0, 0}, {0, 1, 0}, 45.0f, 1.0f, 0.5f, 50.0f);
  }

 protected:
  void pose(double t, float) override {
    for (int row = 0; row < kRows; ++row) {
      for (int column = 0; column < kColumns; ++column) {
        glm::vec3 position{(column - (kColumns - 1) * 0.5f) * 1.0f, (row - (kRows - 1) * 0.5f),
                           0.0f};
        scene_.nodes[row * kColumns + column].transform = glm::rotate(
            glm::translate(glm::mat4(1.0f), position), static_cast<float>(t), glm::vec3(0, 1, 0));
      }
    }
  }

 private:
  static constexpr int kColumns = 16, kRows = 9;
};

// Eight full-screen textured quads with trilinear filtering: every pixel shaded 8 times
// when drawn back to front; front to back, the early depth test rejects all but one.
class OverdrawScene : public SceneBench {
 public:
  explicit OverdrawScene(bool front_to_back) : front_to_back_(front_to_back) {
    // A generated 512x512 texture: no data files needed.
    std::vector<std::uint8_t> rgba(512 * 512 * 4);
    for (int y = 0; y < 512; ++y) {
      for (int x = 0; x < 512; ++x) {
        std::uint8_t* p = &rgba[(y * 512 + x) * 4];
        p[0] = static_cast<std::uint8_t>(x / 2), p[1] = static_cast<std::uint8_t>(y / 2);
        p[2] = ((x / 32 + y / 32) % 2) ? 200 : 60, p[3] = 255;
      }
    }
    Material material;
    material.shading = ShadingModel::unlit;
    material.base_color_map.texture = Texture::from_rgba8(512, 512, rgba, true, "overdraw");
    material.cull = CullMode::none;
    scene_.textures.push_back(material.base_color_map.texture);
    auto quad = std::make_shared<const Mesh>(rectangle(2.0f, 2.0f));
    for (int i = 0; i < 8; ++i) add_node(quad, material);
    // The camera at the origin, quads at depths 1..8 scaled to fill the view exactly.
    scene_.camera = Camera::look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 1.0f, 0.5f, 20.0f);
  }

 protected:
  void pose(double, float aspect) override {
    float half_height = std::tan(glm::radians(30.0f));
    for (int i = 0; i < 8; ++i) {
      float depth = front_to_back_ ? 1.0f + i : 8.0f - i;
      scene_.nodes[i].transform =
          glm::scale(glm::translate(glm::mat4(1.0f), {0, 0, -depth}),
                     {half_height * aspect * depth * 1.02f, half_height * depth * 1.02f, 1.0f});
    }
  }

 private:
  bool front_to_back_;
};

// The islands world (facet view --scene islands) from its start camera, animated by the clock:
// the interactive engine's workload (its speed targets are for this scene).
class IslandsScene : public SceneBench {
 public:
  IslandsScene() : world_(make_islands_world()) {}
  const Scene* scene_at(double t, float aspect, Camera& camera) override {
    world_.animate(t);
    camera = world_.scene.camera;
    camera.aspect = aspect;
    return &world_.scene;
  }
  glm::vec4 clear_color() const override { return {world_.scene.lighting.fog.color, 1.0f}; }

 private:
  IslandsWorld world_;
};

}  // namespace

std::vector<std::string> bench_scene_names() {
  std::vector<std::string> names = glmark2_scene_names();
  for (const char* name : {"shapes", "teapot", "bunny-close", "bunny-far", "million", "overdraw",
                           "overdraw-front-to-back", "islands"}) {
    names.push_back(name);
  }
  return names;
}

std::unique_ptr<BenchScene> make_bench_scene(const std::string& name) {
  if (name == "shapes" || name == "teapot") return std::make_unique<WorldScene>(name);
  if (name == "bunny-close") return std::make_unique<BunnyScene>(2.2f);
  if (name == "bunny-far") return std::make_unique<BunnyScene>(6.0f);
  if (name == "million") return std::make_unique<MillionScene>();
  if (name == "overdraw") return std::make_unique<OverdrawScene>(false);
  if (name == "overdraw-front-to-back") return std::make_unique<OverdrawScene>(true);
  if (name == "islands") return std::make_unique<IslandsScene>();
  if (auto scene = make_glmark2_scene(name)) return scene;
  std::string known;
  for (const auto& n : bench_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown benchmark scene '" + name + "' (" + known + ", or all)");
}

}  // namespace facet::bench
