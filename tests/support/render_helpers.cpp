// Test helpers (see render_helpers.hpp).
#include "support/render_helpers.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"

namespace facet::test {

Mesh soup(const std::vector<glm::vec3>& positions) {
  Mesh mesh;
  mesh.positions = positions;
  return mesh;
}

Mesh soup_quad(float x0, float y0, float x1, float y1, float z) {
  return soup({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y0, z}, {x1, y1, z}, {x0, y1, z}});
}

Framebuffer render_scene_image(const Scene& scene, const Camera& camera, int width, int height,
                               RenderSettings settings) {
  Renderer renderer(settings);
  Framebuffer fb(width, height);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(fb);
  return fb;
}

Framebuffer render_shapes(ShadingModel model, int width, int height, RenderSettings settings) {
  Scene scene = make_shapes_scene();
  for (auto& material : scene.materials) material.shading = model;
  scene.camera.aspect = static_cast<float>(width) / height;
  return render_scene_image(scene, scene.camera, width, height, settings);
}

std::vector<int> coverage_counts(const std::vector<const Mesh*>& meshes, const Camera& camera,
                                 int width, int height, CullMode cull, RenderSettings settings,
                                 const glm::mat4& transform) {
  settings.clear_color = glm::vec4(0.0f);
  Renderer renderer(settings);
  Framebuffer fb(width, height, ColorFormat::rgba32f);
  Material material;
  material.cull = cull;
  auto pipe = pipeline::make_pipeline<shading::OverdrawCountShading>();
  renderer.begin_frame(camera);
  for (const Mesh* mesh : meshes)
    pipeline::draw_with_pipeline(renderer, *mesh, material, transform, pipe);
  renderer.finish(fb);
  std::vector<int> counts(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < counts.size(); ++i) counts[i] = static_cast<int>(fb.rgba32f()[i * 4]);
  return counts;
}

Framebuffer render_unlit(const std::vector<const Mesh*>& meshes, const Camera& camera, int width,
                         int height, CullMode cull, RenderSettings settings) {
  Renderer renderer(settings);
  Framebuffer fb(width, height);
  Material material;
  material.shading = ShadingModel::unlit;
  material.cull = cull;
  renderer.begin_frame(camera);
  for (const Mesh* mesh : meshes) renderer.draw(*mesh, material);
  renderer.finish(fb);
  return fb;
}

Framebuffer render_side_by_side(const Mesh& left, const Mesh& right, const Material& material,
                                const pipeline::DrawPipeline& pipe, int width, int height,
                                const Lighting* lighting) {
  Renderer renderer;
  Framebuffer fb(width, height);
  if (lighting) {
    renderer.begin_frame(test_camera(width, height), *lighting);
  } else {
    renderer.begin_frame(test_camera(width, height));
  }
  pipeline::draw_with_pipeline(renderer, left, material,
                               glm::translate(glm::mat4(1.0f), glm::vec3(-1.2f, 0.0f, -4.0f)),
                               pipe);
  pipeline::draw_with_pipeline(renderer, right, material,
                               glm::translate(glm::mat4(1.0f), glm::vec3(1.2f, 0.0f, -5.0f)), pipe);
  renderer.finish(fb);
  return fb;
}

void expect_same_but_rounding(const Framebuffer& full, const Framebuffer& cheaper) {
  ASSERT_EQ(full.rgba8().size(), cheaper.rgba8().size());
  int drawn = 0, differing = 0;
  for (std::size_t i = 0; i < full.rgba8().size(); ++i) {
    const int difference = std::abs(full.rgba8()[i] - cheaper.rgba8()[i]);
    ASSERT_LE(difference, 1) << "byte " << i;
    differing += difference != 0;
    drawn += i % 4 == 0 && full.rgba8()[i] > 0;
  }
  EXPECT_GT(drawn, full.width() * full.height() / 8);
  EXPECT_LT(differing, drawn / 20) << drawn;
  EXPECT_EQ(full.depth(), cheaper.depth());
}

Material phong_mirror() {
  Material m;
  m.shading = ShadingModel::blinn_phong;
  m.base_color = {0.0f, 0.0f, 0.0f, 1.0f};
  m.specular_color = glm::vec3(0.0f);
  m.shininess = 1e6f;
  m.reflectivity = 1.0f;
  m.reflects_scene = true;
  return m;
}

std::shared_ptr<const Texture> checker_texture() {
  return Texture::from_rgba8(
      2, 2, {255, 255, 255, 255, 40, 90, 200, 255, 40, 90, 200, 255, 255, 255, 255, 255}, true,
      "checker");
}

Camera test_camera(int width, int height, float fov, float near_plane, float far_plane) {
  return Camera::look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fov,
                         static_cast<float>(width) / static_cast<float>(height), near_plane,
                         far_plane);
}

Rgba8Image read_png(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    throw std::runtime_error(path + ": cannot read PNG: " + image.message);
  }
  image.format = PNG_FORMAT_RGBA;
  Rgba8Image out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.pixels.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) {
    throw std::runtime_error(path + ": cannot decode PNG: " + image.message);
  }
  return out;
}

std::filesystem::path fresh_test_dir(const std::string& prefix, const std::string& name) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / (prefix + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

CommandResult run_command(const std::string& command) {
  static int counter = 0;
  std::string stem = ::testing::TempDir() + "facet_cmd_" + std::to_string(::getpid()) + "_" +
                     std::to_string(counter++);
  std::string out_path = stem + ".out", err_path = stem + ".err";
  int status = std::system((command + " >" + out_path + " 2>" + err_path).c_str());
  auto slurp = [](const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.stdout_text = slurp(out_path);
  result.stderr_text = slurp(err_path);
  std::remove(out_path.c_str());
  std::remove(err_path.c_str());
  return result;
}

}  // namespace facet::test
