// The glmark2-equivalent benchmark scenes: glmark2 2023.01's benchmarks 1-11 of
// GLMARK2_SCENES.md (shared bench folder) with the same models, textures, projection, model
// transforms, animation and shading formulas, so that facet's frame time is measured on the
// same work as glmark2 on llvmpipe. tests/glmark2_equivalence_test.cpp checks frame 0 against
// glmark2's own frames.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>
#include <utility>

#include "facet/error.hpp"
#include "facet/render_texture.hpp"
#include "facet/texture.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "scenes/bench_scenes.hpp"
#include "scenes/glmark2_model.hpp"
#include "scenes/glmark2_shading.hpp"

namespace facet::bench {
namespace {

const std::string kModels = "/usr/share/glmark2/models/";
const std::string kTextures = "/usr/share/glmark2/textures/";

// θ = 36°/s x t in every scene: one turn every 10 s (§1.2).
constexpr double kDegreesPerSecond = 36.0;

// glmark2 draws de-indexed triangle lists (glDrawArrays, §1.4): so do we, so the vertex work
// is the same (3 vertex-shader runs per face). The image would be the same either way.
constexpr bool kDeindex = true;

enum class Rotation {
  y,    // MV = T · Ry(θ)
  xyz,  // MV = T · Rx(θ) · Ry(θ) · Rz(θ) (texture)
};

// The projection and where the model sits in eye space.
struct View {
  float fov_y_degrees;
  float near_plane;
  float far_plane;
  glm::vec3 translation;  // MV = T(translation) · rotations
};

// The "fit" camera of §1.4: the bounding box's diagonal D, r = D / 2, fovy = 2 atan(r / (2 + r)),
// near 2, far 2 + D, and the box centre moved to distance d = distance_offset + r.
View fit_view(const Glmark2Model& model, float distance_offset) {
  const glm::vec3 centre = (model.bbox_min + model.bbox_max) * 0.5f;
  const float diagonal = glm::length(model.bbox_max - model.bbox_min);
  const float r = diagonal * 0.5f;
  const float fov = static_cast<float>(glm::degrees(2.0 * std::atan(r / (2.0 + r))));
  return {fov, 2.0f, 2.0f + diagonal,
          glm::vec3(-centre.x, -centre.y, -(centre.z + distance_offset + r))};
}

// The canvas default projection (bump): perspective(60°, W/H, 1, 1024), model at z = -3.5.
View canvas_view() { return {60.0f, 1.0f, 1024.0f, glm::vec3(0.0f, 0.0f, -3.5f)}; }

// The camera at the origin looking down -Z, the identity view: world space == glmark2's eye
// space, and the projection is gluPerspective (§1.3), as glmark2's.
Camera eye_camera(const View& view, float aspect) {
  return Camera::look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, view.fov_y_degrees, aspect,
                         view.near_plane, view.far_plane);
}

// The scenes' lighting: no lights (the shading models carry glmark2's lights themselves) and no
// fog (glmark2 has none, and the models' kernel applies none: glmark2_batch.hpp).
Lighting glmark2_lighting() {
  Lighting lighting;
  lighting.lights.clear();
  if (lighting.fog.mode != FogMode::none) throw Error("glmark2 scenes: the shaders have no fog");
  return lighting;
}

// The models' turn at time t: Ry(θ), θ = 36°/s x t.
glm::mat4 turn_at(double t) {
  const float theta = static_cast<float>(glm::radians(kDegreesPerSecond * t));
  return glm::rotate(glm::mat4(1.0f), theta, {0, 1, 0});
}

// glmark2's passes seen from a light: P . lookAt(light -> 0, up y), P the view's projection.
Camera light_camera(const glm::vec3& light, const View& view, float aspect) {
  return Camera::look_at(light, {0, 0, 0}, {0, 1, 0}, view.fov_y_degrees, aspect, view.near_plane,
                         view.far_plane);
}

// Makes `target` shadow's or refract's off-screen target for a width x height frame, 2W x 2H
// with `options`, unless it already is (GL clamps a side to GL_MAX_TEXTURE_SIZE, 16384 on
// llvmpipe; facet's limit, Framebuffer::kMaxSize, is lower, reached above 4K). Returns whether
// it was made again: only when the frame's size changes.
bool ensure_target(std::unique_ptr<RenderTexture>& target, int width, int height,
                   const RenderTextureOptions& options) {
  const int target_width = std::min(2 * width, Framebuffer::kMaxSize);
  const int target_height = std::min(2 * height, Framebuffer::kMaxSize);
  if (target && target->width() == target_width && target->height() == target_height) {
    return false;
  }
  target = std::make_unique<RenderTexture>(target_width, target_height, options);
  return true;
}

// glmark2's wrap for every texture: clamped to the edges (§1.5).
Sampler clamped(Filter filter) { return {filter, Wrap::clamp_to_edge, Wrap::clamp_to_edge}; }

// One glmark2 benchmark: one mesh, one draw per frame with the scene's own shading model.
class Glmark2Scene : public BenchScene {
 public:
  Glmark2Scene(Mesh mesh, const View& view, Rotation rotation, Material material,
               const pipeline::DrawPipeline& pipeline)
      : mesh_(std::make_shared<const Mesh>(std::move(mesh))),
        view_(view),
        rotation_(rotation),
        material_(std::move(material)),
        pipeline_(pipeline) {}

  void record(Renderer& renderer, double t, int width, int height) override {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    renderer.begin_frame(eye_camera(view_, aspect), lighting_);
    const float theta = static_cast<float>(glm::radians(kDegreesPerSecond * t));
    // Right-multiplied, as libmatrix does: the rightmost rotation touches the vertex first.
    glm::mat4 model_view = glm::translate(glm::mat4(1.0f), view_.translation);
    if (rotation_ == Rotation::xyz) model_view = glm::rotate(model_view, theta, {1, 0, 0});
    model_view = glm::rotate(model_view, theta, {0, 1, 0});
    if (rotation_ == Rotation::xyz) model_view = glm::rotate(model_view, theta, {0, 0, 1});
    pipeline::draw_with_pipeline(renderer, mesh_, material_, model_view, pipeline_);
  }

 private:
  std::shared_ptr<const Mesh> mesh_;  // does not change: checked once by the renderer
  View view_;
  Rotation rotation_;
  Material material_;
  pipeline::DrawPipeline pipeline_;
  Lighting lighting_ = glmark2_lighting();
};

// glmark2's material colours (MaterialDiffuse): white by default, blue in the shading scenes.
Material material_with(glm::vec4 diffuse) {
  Material material;  // back-face culling, CCW front faces: glmark2's GL state (§1.1)
  material.base_color = diffuse;
  return material;
}

// A texture as glmark2 sets it up (§1.5): 8-bit data used as it is (not sRGB), clamped.
TextureMap texture_map(const std::string& file, Filter filter) {
  TextureMap map;
  map.texture = load_texture(kTextures + file, false);
  map.sampler = clamped(filter);
  return map;
}

// The pipeline of glmark2 shading model Shading for `material`. The textured models read the
// material's base colour map, which their kernel has no way to do without (glmark2_batch.hpp).
template <class Shading>
pipeline::DrawPipeline glmark2_pipeline(const Material& material) {
  if constexpr (pipeline::base_color_texcoord<Shading>() >= 0) {
    if (!material.base_color_map) {
      throw Error("glmark2 scenes: a textured shader's material has no base colour map");
    }
  }
  return pipeline::make_pipeline<Shading>();
}

const glm::vec4 kWhite{1.0f, 1.0f, 1.0f, 1.0f};
const glm::vec4 kBlue{0.0f, 0.0f, 1.0f, 1.0f};

// §2.1 build and §2.3 gouraud: per-vertex light on the fitted model.
std::unique_ptr<BenchScene> basic_light_scene(const std::string& file, glm::vec4 diffuse) {
  Glmark2Model model = load_3ds(kModels + file);
  Material material = material_with(diffuse);
  const pipeline::DrawPipeline pipeline = glmark2_pipeline<glmark2::BasicLightShading>(material);
  return std::make_unique<Glmark2Scene>(glmark2_mesh(model, {.normals = true, .deindex = kDeindex}),
                                        fit_view(model, 2.0f), Rotation::y, std::move(material),
                                        pipeline);
}

// §2.2: the crate, turning about all three axes, 2.5 + r away.
std::unique_ptr<BenchScene> texture_scene(Filter filter) {
  Glmark2Model model = load_3ds(kModels + "cube.3ds");
  Material material = material_with(kWhite);
  material.base_color_map = texture_map("crate-base.png", filter);
  const pipeline::DrawPipeline pipeline =
      glmark2_pipeline<glmark2::BasicLightTextureShading>(material);
  return std::make_unique<Glmark2Scene>(
      glmark2_mesh(model, {.normals = true, .texcoords = true, .deindex = kDeindex}),
      fit_view(model, 2.5f), Rotation::xyz, std::move(material), pipeline);
}

// §2.3: the cat with a per-pixel shading model.
template <class Shading>
std::unique_ptr<BenchScene> shading_scene() {
  Glmark2Model model = load_3ds(kModels + "cat.3ds");
  Material material = material_with(kBlue);
  const pipeline::DrawPipeline pipeline = glmark2_pipeline<Shading>(material);
  return std::make_unique<Glmark2Scene>(glmark2_mesh(model, {.normals = true, .deindex = kDeindex}),
                                        fit_view(model, 2.0f), Rotation::y, std::move(material),
                                        pipeline);
}

// §2.4: the low-poly asteroid lit by its object-space normal map (NEAREST, no mips).
std::unique_ptr<BenchScene> bump_normals_scene() {
  Glmark2Model model = load_3ds(kModels + "asteroid-low.3ds");
  Material material = material_with(kWhite);
  material.base_color_map = texture_map("asteroid-normal-map.png", Filter::nearest);
  const pipeline::DrawPipeline pipeline = glmark2_pipeline<glmark2::BumpNormalsShading>(material);
  return std::make_unique<Glmark2Scene>(
      glmark2_mesh(model, {.texcoords = true, .deindex = kDeindex}), canvas_view(), Rotation::y,
      std::move(material), pipeline);
}

// §2.5: the high-poly asteroid with its generated normals.
std::unique_ptr<BenchScene> bump_high_poly_scene() {
  Glmark2Model model = load_3ds(kModels + "asteroid-high.3ds");
  Material material = material_with(kWhite);
  const pipeline::DrawPipeline pipeline = glmark2_pipeline<glmark2::BumpPolyShading>(material);
  return std::make_unique<Glmark2Scene>(glmark2_mesh(model, {.normals = true, .deindex = kDeindex}),
                                        canvas_view(), Rotation::y, std::move(material), pipeline);
}

// §2.6 shadow, per frame: the horse's depth seen from the light (0, 3, 2) into a 2W x 2H
// depth-only target, then the ground quad shaded by that depth map (ShadowGroundShading) and the
// horse lit from the light's direction.
class ShadowScene : public BenchScene {
 public:
  ShadowScene(Mesh horse, const View& view)
      : horse_(std::make_shared<const Mesh>(std::move(horse))),
        ground_(ground_quad()),
        view_(view),
        horse_material_(material_with(kWhite)) {
    ground_material_.base_color_map.sampler = clamped(Filter::nearest);
    horse_pipeline_ = pipeline::make_pipeline<glmark2::ShadowHorseShading>();
    ground_pipeline_ = pipeline::make_pipeline<glmark2::ShadowGroundShading>();
  }

  void record(Renderer& renderer, double t, int width, int height) override {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    ensure_depth_map(width, height);
    const glm::mat4 turn = turn_at(t);
    // 1. The light's view: P . lookAt((0, 3, 2) -> 0, up y) . Ry(θ), the horse not moved away.
    renderer.begin_frame(light_camera(glmark2::kShadowLightPosition, view_, aspect), lighting_);
    pipeline::draw_with_pipeline(renderer, horse_, horse_material_, turn, horse_pipeline_);
    renderer.finish(*depth_map_);
    // 2. The ground: MV_g = T(0, -0.8, P[2][3] - 0.5) . Rx(-85°) . S(2), P[2][3] = 2 f n / (n - f).
    renderer.begin_frame(eye_camera(view_, aspect), lighting_);
    const float p23 =
        2.0f * view_.far_plane * view_.near_plane / (view_.near_plane - view_.far_plane);
    glm::mat4 ground = glm::translate(glm::mat4(1.0f), {0.0f, -0.8f, p23 - 0.5f});
    ground = glm::rotate(ground, glm::radians(-85.0f), {1, 0, 0});
    ground = glm::scale(ground, glm::vec3(2.0f));
    pipeline::draw_with_pipeline(renderer, ground_, ground_material_, ground, ground_pipeline_);
    // 3. The horse: T . Ry(θ).
    pipeline::draw_with_pipeline(renderer, horse_, horse_material_,
                                 glm::translate(glm::mat4(1.0f), view_.translation) * turn,
                                 horse_pipeline_);
  }

 private:
  // glmark2's quad: a 4-vertex strip (-1, -1), (1, -1), (-1, 1), (1, 1) at z = 0, as two
  // counter-clockwise triangles.
  static Mesh ground_quad() {
    Mesh quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}};
    quad.indices = {0, 1, 2, 2, 1, 3};
    return quad;
  }

  // The light's depth alone (ensure_target).
  void ensure_depth_map(int width, int height) {
    if (ensure_target(depth_map_, width, height, {.depth = true, .color = false})) {
      ground_material_.base_color_map.texture = depth_map_->depth_texture();
    }
  }

  std::shared_ptr<const Mesh> horse_;  // does not change: checked once by the renderer
  // Drawn by reference, checked in every frame (4 vertices): the renderer forgets a shared mesh
  // that the frame before did not draw, and the light's frame between two of ours does not.
  Mesh ground_;
  View view_;
  Material horse_material_, ground_material_;
  pipeline::DrawPipeline horse_pipeline_, ground_pipeline_;
  Lighting lighting_ = glmark2_lighting();
  std::unique_ptr<RenderTexture> depth_map_;
};

// §2.6: the horse with the fit camera, but far 50.
std::unique_ptr<BenchScene> shadow_scene() {
  Glmark2Model model = load_3ds(kModels + "horse.3ds");
  View view = fit_view(model, 2.0f);
  view.far_plane = 50.0f;
  return std::make_unique<ShadowScene>(glmark2_mesh(model, {.normals = true, .deindex = kDeindex}),
                                       view);
}

// §2.7 refract, per frame: the bunny's back faces seen from the light (1, 1, 2) into a 2W x 2H
// target, their object-space normals as its color (whose mip chain is filtered every frame) and
// their depth; then the bunny, whose pixels refract through the front face to the back faces'
// normals and out onto nasa1 (RefractShading).
class RefractScene : public BenchScene {
 public:
  RefractScene(Mesh bunny, const View& view)
      : bunny_(std::make_shared<const Mesh>(std::move(bunny))), view_(view) {
    back_material_.cull = CullMode::front;  // the back faces alone
    bunny_material_.base_color_map = texture_map("nasa1.png", Filter::bilinear);
    bunny_material_.normal_map.sampler = clamped(Filter::trilinear);
    bunny_material_.occlusion_map.sampler = clamped(Filter::nearest);
    back_pipeline_ = pipeline::make_pipeline<glmark2::RefractBackNormalShading>();
    bunny_pipeline_ = pipeline::make_pipeline<glmark2::RefractShading>();
  }

  void record(Renderer& renderer, double t, int width, int height) override {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    ensure_distance_map(width, height);
    const glm::mat4 turn = turn_at(t);
    // 1. The back faces from the light: P . lookAt((1, 1, 2) -> 0, up y) . Ry(θ). The light is
    // nearer than the bunny's far side, so the near plane cuts into it.
    renderer.begin_frame(light_camera(glmark2::kRefractLightPosition, view_, aspect), lighting_);
    pipeline::draw_with_pipeline(renderer, bunny_, back_material_, turn, back_pipeline_);
    renderer.finish(*distance_map_);
    // 2. The bunny: T . Ry(θ).
    renderer.begin_frame(eye_camera(view_, aspect), lighting_);
    pipeline::draw_with_pipeline(renderer, bunny_, bunny_material_,
                                 glm::translate(glm::mat4(1.0f), view_.translation) * turn,
                                 bunny_pipeline_);
  }

 private:
  // The back faces' normals as 8-bit data (their codes read as they are, as GL's RGBA8 target),
  // mipmapped, and their depth (ensure_target).
  void ensure_distance_map(int width, int height) {
    if (ensure_target(distance_map_, width, height,
                      {.mipmaps = true, .depth = true, .srgb_texture = false})) {
      bunny_material_.normal_map.texture = distance_map_->texture();
      bunny_material_.occlusion_map.texture = distance_map_->depth_texture();
    }
  }

  std::shared_ptr<const Mesh> bunny_;  // does not change: checked once by the renderer
  View view_;
  Material back_material_, bunny_material_;
  pipeline::DrawPipeline back_pipeline_, bunny_pipeline_;
  Lighting lighting_ = glmark2_lighting();
  std::unique_ptr<RenderTexture> distance_map_;
};

// §2.7: bunny.obj with the fit camera.
std::unique_ptr<BenchScene> refract_scene() {
  Glmark2Model model = load_obj(kModels + "bunny.obj");
  return std::make_unique<RefractScene>(glmark2_mesh(model, {.normals = true, .deindex = kDeindex}),
                                        fit_view(model, 2.0f));
}

}  // namespace

std::vector<std::string> glmark2_scene_names() {
  return {"build:use-vbo=true",
          "texture:texture-filter=linear",
          "texture:texture-filter=mipmap",
          "shading:shading=gouraud",
          "shading:shading=blinn-phong-inf",
          "shading:shading=phong",
          "shading:shading=cel",
          "bump:bump-render=normals",
          "bump:bump-render=high-poly",
          "shadow",
          "refract"};
}

std::unique_ptr<BenchScene> make_glmark2_scene(const std::string& name) {
  if (name == "build:use-vbo=true") return basic_light_scene("horse.3ds", kWhite);
  if (name == "texture:texture-filter=linear") return texture_scene(Filter::bilinear);
  if (name == "texture:texture-filter=mipmap") return texture_scene(Filter::trilinear);
  if (name == "shading:shading=gouraud") return basic_light_scene("cat.3ds", kBlue);
  if (name == "shading:shading=blinn-phong-inf") {
    return shading_scene<glmark2::BlinnPhongInfShading>();
  }
  if (name == "shading:shading=phong") return shading_scene<glmark2::PhongShading>();
  if (name == "shading:shading=cel") return shading_scene<glmark2::CelShading>();
  if (name == "bump:bump-render=normals") return bump_normals_scene();
  if (name == "bump:bump-render=high-poly") return bump_high_poly_scene();
  if (name == "shadow") return shadow_scene();
  if (name == "refract") return refract_scene();
  return nullptr;
}

}  // namespace facet::bench
