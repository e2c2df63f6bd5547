// Closed casters (pipeline/shadow/closed_surface.hpp): which meshes bound a solid, and which way
// their front faces point; the procedural solids close bit for bit; and a closed caster's shadow
// maps, drawn with only the faces toward the light, shade as maps of both faces do, for solids
// wound either way, mirrored, and with receivers inside them.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <utility>

#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "pipeline/shadow/closed_surface.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

using pipeline::closed_surface;
using pipeline::Closure;

// The mesh with every triangle's winding reversed.
Mesh reversed(Mesh mesh) {
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  }
  return mesh;
}

glm::mat4 at(glm::vec3 p) { return glm::translate(glm::mat4(1.0f), p); }

TEST(ClosedSurface, TheProceduralSolidsCloseWithTheirFrontsOut) {
  const std::pair<const char*, Mesh> solids[] = {{"uv_sphere", uv_sphere(1.0f)},
                                                 {"coarse uv_sphere", uv_sphere(0.3f, 3, 2)},
                                                 {"odd uv_sphere", uv_sphere(2.0f, 7, 5)},
                                                 {"cone", cone(0.5f, 2.0f)},
                                                 {"coarse cone", cone(0.5f, 2.0f, 3)},
                                                 {"flat prism", prism(6, 0.4f, 1.0f)},
                                                 {"smooth prism", prism(40, 0.4f, 1.0f)},
                                                 {"box", box({1.0f, 2.0f, 3.0f})},
                                                 {"cube", cube()},
                                                 {"pyramid", pyramid(1.0f, 2.0f, 1.5f)}};
  for (const auto& [name, mesh] : solids) {
    EXPECT_EQ(closed_surface(mesh), Closure::fronts_out) << name;
    EXPECT_EQ(closed_surface(reversed(mesh)), Closure::fronts_in) << name;
  }
  // Several solids in one mesh, some far from the origin (the islands' merged scenery).
  Mesh several;
  append(several, transformed(uv_sphere(0.5f, 16, 10), at({-105.46f, 11.55f, 12.61f})));
  append(several, transformed(cone(0.3f, 1.0f, 7), at({-105.0f, 11.0f, 12.0f})));
  append(several, transformed(box({1.0f, 1.0f, 1.0f}), at({3.0f, 0.0f, 0.0f})));
  EXPECT_EQ(closed_surface(several), Closure::fronts_out);
}

TEST(ClosedSurface, OpenFlatOrUnusualMeshesAreOpen) {
  EXPECT_EQ(closed_surface(plane(1.0f, 1.0f, 2, 2)), Closure::open);
  Mesh holed = uv_sphere(1.0f, 8, 4);
  holed.indices.resize(holed.indices.size() - 3);
  EXPECT_EQ(closed_surface(holed), Closure::open);
  // Two spheres on one spot: each edge runs twice each way.
  Mesh doubled = uv_sphere(1.0f, 8, 4);
  append(doubled, uv_sphere(1.0f, 8, 4));
  EXPECT_EQ(closed_surface(doubled), Closure::open);
  // A sphere and its inside-out copy on one spot: every edge runs once each way, but nothing is
  // enclosed.
  Mesh both_sides = uv_sphere(1.0f, 8, 4);
  append(both_sides, reversed(uv_sphere(1.0f, 8, 4)));
  EXPECT_EQ(closed_surface(both_sides), Closure::open);
  Mesh not_finite = cube();
  not_finite.positions[0].x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(closed_surface(not_finite), Closure::open);
  Mesh strip = cube();
  strip.topology = Topology::triangle_strip;
  EXPECT_EQ(closed_surface(strip), Closure::open);
  const Mesh big = uv_sphere(1.0f, 128, 64);
  ASSERT_GT(big.primitive_count(), pipeline::kMaxClosedSurfaceTriangles);
  EXPECT_EQ(closed_surface(big), Closure::open);
}

// A ground plane, a sphere standing on it, and two boxes of 2 x 2 x 2 seen from outside whose
// near faces the color pass culls, so that a ball inside each shows: one box wound inside out, one
// wound as usual but mirrored by its transform (both cast with the faces their winding calls
// back). A sun from above and to the side shades the balls through the boxes' tops.
struct BoxesScene {
  Mesh ground = plane(12.0f, 12.0f);
  Mesh sphere = uv_sphere(0.8f, 24, 12);
  Mesh inside_out = reversed(box({2.0f, 2.0f, 2.0f}));
  Mesh outside_in = box({2.0f, 2.0f, 2.0f});  // mirrored below
  Mesh ball = uv_sphere(0.5f, 16, 8);

  // By reference (`shared` false) a mesh is not remembered, so its maps draw both its sides.
  void draw(Renderer& renderer, bool shared) const {
    Material matte;
    matte.shading = ShadingModel::lambert;
    matte.base_color = {0.8f, 0.7f, 0.6f, 1.0f};
    Material two_sided = matte;
    two_sided.cull = CullMode::none;
    const auto draw = [&](const Mesh& mesh, const Material& material, const glm::mat4& transform) {
      if (shared) {
        renderer.draw(std::make_shared<const Mesh>(mesh), material, transform);
      } else {
        renderer.draw(mesh, material, transform);
      }
    };
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f});
    draw(ground, two_sided, glm::mat4(1.0f));
    draw(sphere, matte, at({-2.5f, 0.8f, 1.5f}));
    draw(inside_out, matte, at({0.0f, 1.0f, 0.0f}));
    draw(ball, matte, at({0.0f, 0.6f, 0.0f}));
    draw(outside_in, matte, at({2.8f, 1.0f, -1.0f}) * mirror);
    draw(ball, matte, at({2.8f, 0.6f, -1.0f}));
  }
};

Framebuffer render_boxes(bool shared) {
  RenderSettings settings;
  settings.shadows = true;
  settings.shadow_map_size = 1024;
  settings.msaa = 1;
  Renderer renderer(settings);
  Lighting lighting;
  lighting.lights = {Light::directional({0.5f, -1.0f, 0.3f})};
  lighting.ambient = glm::vec3(0.1f);
  constexpr int kWidth = 240, kHeight = 160;
  const Camera camera = Camera::look_at({1.0f, 6.0f, 7.0f}, {0.5f, 0.5f, 0.0f}, {0, 1, 0}, 45.0f,
                                        static_cast<float>(kWidth) / kHeight, 0.5f, 40.0f);
  const BoxesScene scene;
  renderer.begin_frame(camera, lighting);
  scene.draw(renderer, shared);
  Framebuffer fb(kWidth, kHeight);
  renderer.finish(fb);
  return fb;
}

TEST(ClosedCasters, CastAsBothSidesDo) {
  // Silhouette texels whose centres lie exactly on an edge between a face toward the light and
  // one away from it keep what is behind them: a code at most, at a few pixels.
  expect_same_but_rounding(render_boxes(false), render_boxes(true));
}

}  // namespace
}  // namespace facet::test
