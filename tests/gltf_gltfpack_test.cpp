// The glTF reader on files written by gltfpack (meshoptimizer's packer, Debian's gltfpack 0.18,
// the tool that made Khronos's own quantized sample variants) from Khronos sample models in
// assimp-testmodels: KHR_mesh_quantization (positions, normals and morph targets as integers,
// the node's transform undoing the scale; texture coordinates through KHR_texture_transform),
// EXT_meshopt_compression, and morph weights animated as normalized bytes. tests/data/gltfpack
// lists how each file was made, with its source's license. Each must draw what its source
// draws, but for quantization's rounding.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "facet/camera.hpp"
#include "facet/import.hpp"
#include "support/gltf_builder.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const fs::path kPacked = FACET_GLTFPACK_DIR;

// The scene at `seconds` drawn at 160x120 by a camera framing `framed` (the source's bounds).
Framebuffer draw(const fs::path& file, double seconds, const Bounds& framed) {
  ImportOptions options;
  options.time = seconds;
  const Scene scene = import_gltf(file, options).scene;
  const glm::vec3 centre = framed.centre();
  const float radius = glm::length(framed.max - framed.min) * 0.5f;
  const Camera camera =
      Camera::look_at(centre + radius * glm::vec3(1.6f, 1.2f, 2.4f), centre, {0, 1, 0}, 40.0f,
                      160.0f / 120.0f, 0.05f * radius, 20.0f * radius);
  return render_scene_image(scene, camera, 160, 120);
}

struct Difference {
  double mean = 0;  // mean absolute difference of the color bytes
  int pixels = 0;   // pixels with a channel more than 8 apart
};
Difference difference(const Framebuffer& a, const Framebuffer& b) {
  Difference d;
  long total = 0;
  for (std::size_t i = 0; i < a.rgba8().size(); i += 4) {
    int largest = 0;
    for (int c = 0; c < 3; ++c) {
      const int e = std::abs(a.rgba8()[i + c] - b.rgba8()[i + c]);
      total += e;
      largest = std::max(largest, e);
    }
    d.pixels += largest > 8;
  }
  d.mean = static_cast<double>(total) / (a.rgba8().size() / 4 * 3);
  return d;
}

// AnimatedMorphCube, quantized and meshopt-compressed: the cube and its two morph targets, posed
// at rest and along its animation, drawn as the source draws it.
TEST(GltfGltfpack, QuantizedAndCompressedMorphCubeDrawAsItsSource) {
  const fs::path source =
      kSampleModels / "glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf";
  FACET_REQUIRE_PACKAGE(fs::exists(source), "assimp-testmodels is not installed");
  const Bounds framed = import_gltf(source).scene.bounds();
  for (const char* packed :
       {"AnimatedMorphCube-quantized.gltf", "AnimatedMorphCube-meshopt.gltf"}) {
    const ImportedGltf got = import_gltf(kPacked / packed);
    EXPECT_TRUE(got.warnings.empty()) << packed << ": " << got.warnings[0];
    EXPECT_EQ(got.scene.triangle_count(), 12u) << packed;
    const Bounds bounds = got.scene.bounds();
    const float size = glm::length(framed.max - framed.min);
    EXPECT_LT(glm::length(bounds.min - framed.min), size * 1e-3f) << packed;
    EXPECT_LT(glm::length(bounds.max - framed.max), size * 1e-3f) << packed;
    for (const double seconds : {0.0, 1.0, 2.5}) {
      const Framebuffer want = draw(source, seconds, framed);
      const Framebuffer image = draw(kPacked / packed, seconds, framed);
      const Difference d = difference(want, image);
      EXPECT_LT(d.mean, 0.2) << packed << " at " << seconds << " s";
      EXPECT_LT(d.pixels, 160 * 120 / 100) << packed << " at " << seconds << " s";
    }
  }
  // The animation moves the cube: the comparisons above compare different poses.
  EXPECT_GT(difference(draw(source, 0.0, framed), draw(source, 1.0, framed)).pixels, 1000);
}

// BoxTextured with quantized texture coordinates, which gltfpack maps back through
// KHR_texture_transform: the texture lands where the source puts it. The texture (Cesium's logo,
// not copied here) is the source's own, next to the packed file in a test folder.
TEST(GltfGltfpack, QuantizedTextureCoordinatesMapTheTextureAsTheSource) {
  const fs::path source_dir = kSampleModels / "glTF2/BoxTextured-glTF";
  FACET_REQUIRE_PACKAGE(fs::exists(source_dir / "BoxTextured.gltf"),
                        "assimp-testmodels is not installed");
  const fs::path dir = fresh_test_dir("gltf_gltfpack_", "box");
  for (const char* name : {"BoxTextured-quantized.gltf", "BoxTextured-quantized.bin"}) {
    fs::copy_file(kPacked / name, dir / name);
  }
  fs::copy_file(source_dir / "CesiumLogoFlat.png", dir / "CesiumLogoFlat.png");
  const Bounds framed = import_gltf(source_dir / "BoxTextured.gltf").scene.bounds();
  const ImportedGltf got = import_gltf(dir / "BoxTextured-quantized.gltf");
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  // The premise: the texture coordinates are integers the transform scales back.
  ASSERT_TRUE(got.scene.meshes.size() == 1 &&
              got.scene.materials.at(0).base_color_map.transform != glm::mat3(1.0f));
  const Framebuffer want = draw(source_dir / "BoxTextured.gltf", 0.0, framed);
  const Framebuffer image = draw(dir / "BoxTextured-quantized.gltf", 0.0, framed);
  const Difference d = difference(want, image);
  EXPECT_LT(d.mean, 0.3);
  EXPECT_LT(d.pixels, 160 * 120 / 100);
}

// TextureTransformTest with its repeated meshes as EXT_mesh_gpu_instancing (two nodes drawing
// three and two instances), quantized, its textures through KHR_texture_transform as in the
// source: every instance drawn where the source draws its node. The textures are the source's
// own, copied next to the packed file.
TEST(GltfGltfpack, InstancedTextureTransformTestDrawsAsItsSource) {
  const fs::path source_dir = kSampleModels / "glTF2/textureTransform";
  FACET_REQUIRE_PACKAGE(fs::exists(source_dir / "TextureTransformTest.gltf"),
                        "assimp-testmodels is not installed");
  const fs::path dir = fresh_test_dir("gltf_gltfpack_", "instancing");
  for (const char* name :
       {"TextureTransformTest-instanced.gltf", "TextureTransformTest-instanced.bin"}) {
    fs::copy_file(kPacked / name, dir / name);
  }
  for (const char* name : {"UV.png", "Arrow.png", "Correct.png", "NotSupported.png", "Error.png"}) {
    fs::copy_file(source_dir / name, dir / name);
  }
  const Scene source = import_gltf(source_dir / "TextureTransformTest.gltf").scene;
  const ImportedGltf got = import_gltf(dir / "TextureTransformTest-instanced.gltf");
  EXPECT_TRUE(got.warnings.empty()) << got.warnings[0];
  EXPECT_EQ(got.scene.triangle_count(), source.triangle_count());  // every instance
  const Bounds framed = source.bounds();
  const Difference d = difference(draw(source_dir / "TextureTransformTest.gltf", 0.0, framed),
                                  draw(dir / "TextureTransformTest-instanced.gltf", 0.0, framed));
  EXPECT_LT(d.mean, 0.3);
  EXPECT_LT(d.pixels, 160 * 120 / 100);
}

}  // namespace
}  // namespace facet::test
