// Test helpers: render meshes through the real Renderer and read back counts, depth or color.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/texture.hpp"
#include "pipeline/frame.hpp"

namespace facet::test {

// A mesh that is a plain triangle soup (every 3 positions a triangle).
Mesh soup(const std::vector<glm::vec3>& positions);

// The rectangle [x0, x1] x [y0, y1] at depth z (facing +Z) as a soup of two triangles sharing
// the diagonal from (x0, y0) to (x1, y1).
Mesh soup_quad(float x0, float y0, float x1, float y1, float z);

// The scene seen by camera (its own lighting), width x height, by facet's renderer.
Framebuffer render_scene_image(const Scene& scene, const Camera& camera, int width, int height,
                               RenderSettings settings = {});

// The built-in shapes scene with every material set to `model`, width x height.
Framebuffer render_shapes(ShadingModel model, int width, int height, RenderSettings settings = {});

// Renders meshes (each placed by transform) with the overdraw counter (no depth test): how
// many triangles covered each pixel centre, row-major.
std::vector<int> coverage_counts(const std::vector<const Mesh*>& meshes, const Camera& camera,
                                 int width, int height, CullMode cull = CullMode::none,
                                 RenderSettings settings = {},
                                 const glm::mat4& transform = glm::mat4(1.0f));

// Renders meshes with an unlit material and returns the framebuffer (color and depth).
Framebuffer render_unlit(const std::vector<const Mesh*>& meshes, const Camera& camera, int width,
                         int height, CullMode cull = CullMode::none, RenderSettings settings = {});

// Two meshes side by side in front of test_camera (left at x = -1.2, 4 units away; right at
// x = 1.2, 5 away), both drawn with `pipe` rather than the pipeline their material would get:
// how a cheaper form of a shading model is compared with the full one.
// lighting: null for the default lights.
Framebuffer render_side_by_side(const Mesh& left, const Mesh& right, const Material& material,
                                const pipeline::DrawPipeline& pipe, int width, int height,
                                const Lighting* lighting = nullptr);

// That a cheaper form's image (render_side_by_side) is the full form's but for rounding: every
// byte within one code, almost all equal, the same depths, and the meshes drawn (an eighth of
// the pixels at least).
void expect_same_but_rounding(const Framebuffer& full, const Framebuffer& cheaper);

// A 2x2 sRGB texture of two colors, white and blue, on the diagonals.
std::shared_ptr<const Texture> checker_texture();

// A perfect Phong mirror (Material::reflects_scene): black itself, all reflection, an exponent
// too high to blur.
Material phong_mirror();

// A camera at the origin looking down -Z with the aspect of width x height.
Camera test_camera(int width, int height, float fov = 60.0f, float near_plane = 0.1f,
                   float far_plane = 100.0f);

// PNG reading for golden images (8-bit RGBA).
struct Rgba8Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
};
Rgba8Image read_png(const std::string& path);

// An empty directory under the test temp dir, named prefix + name (the prefix keeps test
// files apart when ctest runs them in parallel), so stray or partial files show in a listing.
std::filesystem::path fresh_test_dir(const std::string& prefix, const std::string& name);

// Runs a shell command; returns its exit status and what it printed on stderr.
struct CommandResult {
  int exit_code = -1;
  std::string stdout_text;
  std::string stderr_text;
};
CommandResult run_command(const std::string& command);

}  // namespace facet::test
