// Scenes compared (see scene_compare.hpp).
#include "support/scene_compare.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <limits>
#include <vector>

namespace facet::test {
namespace {

// How far apart two floats are, in units in the last place (-0 and +0 none apart).
std::int64_t ulps_apart(float a, float b) {
  const auto ordered = [](float f) {
    const auto bits = std::bit_cast<std::int32_t>(f);
    return bits < 0 ? std::int64_t{std::numeric_limits<std::int32_t>::min()} - bits
                    : std::int64_t{bits};
  };
  return std::abs(ordered(a) - ordered(b));
}

template <class Vector>
void expect_near(const std::vector<Vector>& a, const std::vector<Vector>& b, std::int64_t ulps,
                 const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  std::int64_t worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int c = 0; c < Vector::length(); ++c)
      worst = std::max(worst, ulps_apart(a[i][c], b[i][c]));
  }
  EXPECT_LE(worst, ulps) << what;
}

void expect_same_textures(const TextureMap& a, const TextureMap& b) {
  ASSERT_EQ(a.texture == nullptr, b.texture == nullptr);
  if (!a.texture) return;
  EXPECT_EQ(a.texture->level(0).width, b.texture->level(0).width);
  EXPECT_EQ(a.texture->level(0).rgba8, b.texture->level(0).rgba8);
  EXPECT_EQ(a.transform, b.transform);
}

}  // namespace

void expect_same_scene(const Scene& a, const Scene& b, std::int64_t ulps) {
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    const Mesh &x = *a.meshes[i], &y = *b.meshes[i];
    SCOPED_TRACE("mesh " + std::to_string(i));
    EXPECT_EQ(x.topology, y.topology);
    expect_near(x.positions, y.positions, ulps, "positions");
    expect_near(x.normals, y.normals, 2 * ulps, "normals");
    expect_near(x.texcoords, y.texcoords, ulps, "texture coordinates");
    EXPECT_EQ(x.colors, y.colors);
    EXPECT_EQ(x.tangents, y.tangents);
    EXPECT_EQ(x.indices, y.indices);
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    const Material &x = a.materials[i], &y = b.materials[i];
    SCOPED_TRACE("material " + std::to_string(i));
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.shading, y.shading);
    EXPECT_EQ(x.base_color, y.base_color);
    EXPECT_EQ(x.use_vertex_colors, y.use_vertex_colors);
    EXPECT_EQ(x.specular_color, y.specular_color);
    EXPECT_EQ(x.shininess, y.shininess);
    EXPECT_EQ(x.metallic, y.metallic);
    EXPECT_EQ(x.roughness, y.roughness);
    EXPECT_EQ(x.emissive, y.emissive);
    EXPECT_EQ(x.reflectivity, y.reflectivity);
    EXPECT_EQ(x.cull, y.cull);
    EXPECT_EQ(x.alpha_mode, y.alpha_mode);
    EXPECT_EQ(x.casts_shadows, y.casts_shadows);
    expect_same_textures(x.base_color_map, y.base_color_map);
    expect_same_textures(x.normal_map, y.normal_map);
    expect_same_textures(x.specular_map, y.specular_map);
  }
  EXPECT_EQ(a.textures.size(), b.textures.size());
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    SCOPED_TRACE("node " + std::to_string(i));
    EXPECT_EQ(a.nodes[i].name, b.nodes[i].name);
    EXPECT_EQ(a.nodes[i].parent, b.nodes[i].parent);
    EXPECT_EQ(a.nodes[i].transform, b.nodes[i].transform);
    ASSERT_EQ(a.nodes[i].instances.size(), b.nodes[i].instances.size());
    for (std::size_t k = 0; k < a.nodes[i].instances.size(); ++k) {
      EXPECT_EQ(a.nodes[i].instances[k].mesh, b.nodes[i].instances[k].mesh);
      EXPECT_EQ(a.nodes[i].instances[k].material, b.nodes[i].instances[k].material);
    }
  }
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (std::size_t i = 0; i < a.cameras.size(); ++i) {
    EXPECT_EQ(a.cameras[i].eye, b.cameras[i].eye);
    EXPECT_EQ(a.cameras[i].target, b.cameras[i].target);
    EXPECT_EQ(a.cameras[i].fov_y_degrees, b.cameras[i].fov_y_degrees);
    EXPECT_EQ(a.cameras[i].projection_kind, b.cameras[i].projection_kind);
    EXPECT_EQ(a.cameras[i].view_height, b.cameras[i].view_height);
  }
  EXPECT_EQ(a.has_file_lights, b.has_file_lights);
  ASSERT_EQ(a.lighting.lights.size(), b.lighting.lights.size());
  for (std::size_t i = 0; i < a.lighting.lights.size(); ++i) {
    EXPECT_EQ(a.lighting.lights[i].type, b.lighting.lights[i].type);
    EXPECT_EQ(a.lighting.lights[i].position, b.lighting.lights[i].position);
    EXPECT_EQ(a.lighting.lights[i].direction, b.lighting.lights[i].direction);
    EXPECT_EQ(a.lighting.lights[i].color, b.lighting.lights[i].color);
    EXPECT_EQ(a.lighting.lights[i].intensity, b.lighting.lights[i].intensity);
  }
}

}  // namespace facet::test
