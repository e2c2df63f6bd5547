// Two-sided lighting: the back of a two-sided material is lit as a front, decided per triangle
// by the side seen (setup/back_faces.hpp), not per pixel by where the interpolated normal
// points, which turns away from the viewer at a smooth silhouette of a face that is seen.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/light.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 160, kHeight = 120;

Framebuffer render(const Mesh& mesh, ShadingModel shading, CullMode cull,
                   const glm::mat4& transform = glm::mat4(1.0f)) {
  // From above, lit from straight above: the sphere's lower silhouette has normals turned
  // down and away from the camera, on faces the camera sees.
  const Camera camera =
      Camera::look_at({0.0f, 1.6f, 2.2f}, {0, 0, 0}, {0, 1, 0}, 50.0f, float(kWidth) / kHeight);
  Lighting lighting;
  lighting.ambient = glm::vec3(0.05f);
  lighting.lights = {Light::directional({0, -1, 0}, glm::vec3(1.0f), 2.0f)};
  Material material;
  material.shading = shading;
  material.cull = cull;
  Renderer renderer;
  Framebuffer image(kWidth, kHeight);
  renderer.begin_frame(camera, lighting);
  renderer.draw(mesh, material, transform);
  renderer.finish(image);
  return image;
}

TEST(TwoSided, AClosedMeshLooksTheSameTwoSidedAsOneSided) {
  // Every face of a closed mesh that the camera sees is a front face: two-sided changes nothing.
  const Mesh ball = uv_sphere(0.8f, 24, 12);
  for (ShadingModel shading : {ShadingModel::lambert, ShadingModel::phong, ShadingModel::pbr}) {
    const Framebuffer one_sided = render(ball, shading, CullMode::back);
    const Framebuffer two_sided = render(ball, shading, CullMode::none);
    int differing = 0;
    for (std::size_t i = 0; i < one_sided.rgba8().size(); ++i) {
      differing += std::abs(one_sided.rgba8()[i] - two_sided.rgba8()[i]) > 1;
    }
    EXPECT_EQ(differing, 0) << static_cast<int>(shading);
  }
}

TEST(TwoSided, TheInsideOfAnOpenMeshIsLitAsAFront) {
  // A bowl: the lower half of a sphere, seen from above, its inside facing up into the light;
  // one-sided its inside is culled, two-sided it is lit.
  Mesh bowl = uv_sphere(0.8f, 24, 12);
  std::vector<std::uint32_t> lower;
  for (std::size_t t = 0; t + 2 < bowl.indices.size(); t += 3) {
    const std::uint32_t* v = &bowl.indices[t];
    if (bowl.positions[v[0]].y + bowl.positions[v[1]].y + bowl.positions[v[2]].y < -0.01f) {
      lower.insert(lower.end(), v, v + 3);
    }
  }
  bowl.indices = lower;
  const Framebuffer inside = render(bowl, ShadingModel::lambert, CullMode::none);
  const glm::vec4 floor = inside.pixel(kWidth / 2, kHeight / 2);  // the bowl's inside bottom
  EXPECT_GT(floor.g, 0.5f);  // lit from above, not ambient only
}

}  // namespace
}  // namespace facet::test
