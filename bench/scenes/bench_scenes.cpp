// The built-in benchmark scenes (see bench_scenes.hpp).
#include "scenes/bench_scenes.hpp"

#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "facet/islands.hpp"
#include "facet/procedural.hpp"
#include "facet/scene.hpp"
#include "facet/texture.hpp"

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

// The scenes' meshes do not change: they are drawn through shared pointers, so the renderer
// checks each once, as a GPU driver checks the vertex buffers glmark2 draws from.

// bunny.obj (70k triangles, indexed) in the normals view, fov 45, near 0.1, far 100, looking
// at the origin from (0, 0.1, distance).
class BunnyScene : public BenchScene {
 public:
  explicit BunnyScene(float distance) : distance_(distance), mesh_(load_first_mesh(kBunnyPath)) {
    material_.shading = ShadingModel::normals;
  }
  void record(Renderer& renderer, double, float aspect) override {
    renderer.begin_frame(Camera::look_at({0.0f, 0.1f, distance_}, {0, 0, 0}, {0, 1, 0}, 45.0f,
                                         aspect, 0.1f, 100.0f));
    renderer.draw(mesh_, material_);
  }

 private:
  float distance_;
  std::shared_ptr<const Mesh> mesh_;
  Material material_;
};

// At least a million small triangles: a 16 x 9 grid of spheres of 7,200 triangles each
// (1,036,800 in all), Gouraud-lit, turning slowly.
class MillionScene : public BenchScene {
 public:
  MillionScene() : sphere_(std::make_shared<const Mesh>(uv_sphere(0.45f, 60, 60))) {
    material_.shading = ShadingModel::gouraud;
    material_.base_color = {0.8f, 0.5f, 0.3f, 1.0f};
    lighting_.lights = {Light::directional({-0.3f, -0.5f, -1.0f})};
  }
  void record(Renderer& renderer, double t, float aspect) override {
    renderer.begin_frame(
        Camera::look_at({0, 0, 11.5f}, {0, 0, 0}, {0, 1, 0}, 45.0f, aspect, 0.5f, 50.0f),
        lighting_);
    for (int row = 0; row < kRows; ++row) {
      for (int column = 0; column < kColumns; ++column) {
        glm::vec3 position{(column - (kColumns - 1) * 0.5f) * 1.0f, (row - (kRows - 1) * 0.5f),
                           0.0f};
        transforms_[row * kColumns + column] = glm::rotate(
            glm::translate(glm::mat4(1.0f), position), static_cast<float>(t), glm::vec3(0, 1, 0));
        renderer.draw(sphere_, material_, transforms_[row * kColumns + column]);
      }
    }
  }

 private:
  static constexpr int kColumns = 16, kRows = 9;
  std::shared_ptr<const Mesh> sphere_;
  Material material_;
  Lighting lighting_;
  glm::mat4 transforms_[kColumns * kRows];
};

// Eight full-screen textured quads with trilinear filtering: every pixel shaded 8 times
// when drawn back to front; front to back, the early depth test rejects all but one.
class OverdrawScene : public BenchScene {
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
    material_.shading = ShadingModel::unlit;
    material_.base_color_map.texture = Texture::from_rgba8(512, 512, rgba, true, "overdraw");
    material_.cull = CullMode::none;
    quad_ = std::make_shared<const Mesh>(rectangle(2.0f, 2.0f));
  }
  void record(Renderer& renderer, double, float aspect) override {
    // An orthographic-like setup: the camera at the origin, quads at depths 1..8 scaled to
    // fill the view exactly.
    Camera camera = Camera::look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, aspect, 0.5f, 20.0f);
    renderer.begin_frame(camera);
    float half_height = std::tan(glm::radians(30.0f));
    for (int i = 0; i < 8; ++i) {
      float depth = front_to_back_ ? 1.0f + i : 8.0f - i;
      transforms_[i] =
          glm::scale(glm::translate(glm::mat4(1.0f), {0, 0, -depth}),
                     {half_height * aspect * depth * 1.02f, half_height * depth * 1.02f, 1.0f});
      renderer.draw(quad_, material_, transforms_[i]);
    }
  }

 private:
  bool front_to_back_;
  std::shared_ptr<const Mesh> quad_;
  Material material_;
  glm::mat4 transforms_[8];
};

// The islands world (facet view --scene islands) from its start camera, animated by the clock:
// the interactive engine's workload (its speed targets are for this scene).
class IslandsScene : public BenchScene {
 public:
  IslandsScene() : world_(make_islands_world()) {}
  void record(Renderer& renderer, double t, float aspect) override {
    world_.animate(t);
    Camera camera = world_.scene.camera;
    camera.aspect = aspect;
    renderer.begin_frame(camera, world_.scene.lighting);
    draw_scene(renderer, world_.scene);
  }
  glm::vec4 clear_color() const override { return {world_.scene.lighting.fog.color, 1.0f}; }

 private:
  IslandsWorld world_;
};

}  // namespace

std::vector<std::string> bench_scene_names() {
  std::vector<std::string> names = glmark2_scene_names();
  for (const char* name :
       {"bunny-close", "bunny-far", "million", "overdraw", "overdraw-front-to-back", "islands"}) {
    names.push_back(name);
  }
  return names;
}

std::unique_ptr<BenchScene> make_bench_scene(const std::string& name) {
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
