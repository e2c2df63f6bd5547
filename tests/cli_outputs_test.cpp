// `facet render --outputs` through the real binary: which files each -o extension gives, and
// what they hold, read back with readers written from the formats (support/output_readers)
// and compared value for value with the library's Framebuffer for the same render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "facet/color.hpp"
#include "facet/framebuffer.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/cli_content_inputs.hpp"
#include "support/output_readers.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 64, kHeight = 48;
const std::string kRender = "render --scene shapes --size 64x48 ";

ExtraOutputs all_extra(NormalSpace normals = NormalSpace::world) {
  ExtraOutputs extra;
  extra.view_depth = extra.ray_distance = extra.instance_ids = true;
  extra.triangle_ids = extra.barycentrics = extra.albedo = true;
  extra.normals = normals;
  return extra;
}

// What `facet render --scene shapes --size 64x48` draws, in process: the scene's own camera,
// the CLI's default background as clear color, its default 4 samples a pixel, tone mapping
// and shadows.
Framebuffer reference(ColorFormat format, NormalSpace normals = NormalSpace::world) {
  Scene scene = make_builtin_scene("shapes");
  const glm::vec3 background = srgb_to_linear(glm::vec3(0.53f, 0.66f, 0.82f));
  scene.lighting.fog.color = background;
  Camera camera = scene.camera;
  camera.aspect = static_cast<float>(kWidth) / kHeight;
  RenderSettings settings;
  settings.clear_color = glm::vec4(background, 1.0f);
  settings.msaa = 4;                                 // facet render's default
  settings.tone_mapping = ToneMapping::pbr_neutral;  // likewise
  settings.shadows = true;                           // likewise
  settings.shadow_map_size = 256;                    // its auto size for 64x48
  Renderer renderer(settings);
  Framebuffer image(kWidth, kHeight, format, DepthImage::none, all_extra(normals));
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(image);
  return image;
}

// Bit for bit: the files hold the exact values, never a rounded copy.
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expect_array(const NpyArray& array, const std::string& dtype,
                  std::vector<std::size_t> shape_tail, const std::string& name) {
  std::vector<std::size_t> shape = {kHeight, kWidth};
  shape.insert(shape.end(), shape_tail.begin(), shape_tail.end());
  EXPECT_EQ(array.dtype, dtype) << name;
  EXPECT_FALSE(array.fortran_order) << name;
  EXPECT_EQ(array.shape, shape) << name;
  EXPECT_EQ(array.data_offset % 64, 0u) << name << ": values not aligned as NumPy writes them";
}

TEST(CliOutputs, NpzHoldsOneArrayPerOutputWithTheFramebuffersValues) {
  fs::path dir = fresh_test_dir("facet_cli_outputs_", "npz");
  CommandResult r = run_facet(dir, kRender +
                                       "-o out.npz --outputs "
                                       "color,depth,distance,normal,instance,triangle,barycentric,"
                                       "albedo");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"out.npz"});
  auto members = read_npz((dir / "out.npz").string());
  ASSERT_EQ(members.size(), 8u);
  const char* names[] = {"color",    "depth",    "distance",    "normal",
                         "instance", "triangle", "barycentric", "albedo"};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(members[i].first, names[i]);
  auto array = [&](int i) -> const NpyArray& { return members[i].second; };

  Framebuffer expected = reference(ColorFormat::rgba8_srgb);
  expect_array(array(0), "|u1", {4}, "color");
  EXPECT_TRUE(same_bits(array(0).values<std::uint8_t>(), expected.rgba8()));
  expect_array(array(1), "<f4", {}, "depth");
  EXPECT_TRUE(same_bits(array(1).values<float>(), expected.view_depth()));
  expect_array(array(2), "<f4", {}, "distance");
  EXPECT_TRUE(same_bits(array(2).values<float>(), expected.ray_distance()));
  expect_array(array(3), "<f4", {3}, "normal");
  EXPECT_TRUE(same_bits(array(3).values<float>(), expected.normals()));
  expect_array(array(4), "<u4", {}, "instance");
  EXPECT_TRUE(same_bits(array(4).values<std::uint32_t>(), expected.instance_ids()));
  expect_array(array(5), "<u4", {}, "triangle");
  EXPECT_TRUE(same_bits(array(5).values<std::uint32_t>(), expected.triangle_ids()));
  expect_array(array(6), "<f4", {3}, "barycentric");
  EXPECT_TRUE(same_bits(array(6).values<float>(), expected.barycentrics()));
  expect_array(array(7), "<f4", {4}, "albedo");
  EXPECT_TRUE(same_bits(array(7).values<float>(), expected.albedo()));
  // Something was drawn, and something was not.
  std::vector<std::uint32_t> ids = array(4).values<std::uint32_t>();
  EXPECT_NE(std::count(ids.begin(), ids.end(), 0u), 0);
  EXPECT_NE(std::count(ids.begin(), ids.end(), 0u), static_cast<long>(ids.size()));
}

TEST(CliOutputs, NpyWritesOneFilePerOutput) {
  fs::path dir = fresh_test_dir("facet_cli_outputs_", "npy");
  CommandResult r =
      run_facet(dir, kRender + "-o out.npy --outputs depth,color,normal --normal-space camera");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(list_dir(dir),
            (std::vector<std::string>{"out.depth.npy", "out.normal.npy", "out.npy"}));
  Framebuffer expected = reference(ColorFormat::rgba8_srgb, NormalSpace::camera);
  NpyArray color = read_npy((dir / "out.npy").string());
  expect_array(color, "|u1", {4}, "color");
  EXPECT_TRUE(same_bits(color.values<std::uint8_t>(), expected.rgba8()));
  NpyArray depth = read_npy((dir / "out.depth.npy").string());
  expect_array(depth, "<f4", {}, "depth");
  EXPECT_TRUE(same_bits(depth.values<float>(), expected.view_depth()));
  NpyArray normal = read_npy((dir / "out.normal.npy").string());
  expect_array(normal, "<f4", {3}, "normal");
  EXPECT_TRUE(same_bits(normal.values<float>(), expected.normals()));
  EXPECT_FALSE(same_bits(normal.values<float>(), reference(ColorFormat::rgba8_srgb).normals()))
      << "camera-space normals are the world-space ones";
}

TEST(CliOutputs, ExrHoldsFloatColorAndEveryOutputExactly) {
  fs::path dir = fresh_test_dir("facet_cli_outputs_", "exr");
  CommandResult r =
      run_facet(dir, kRender + "-o out.exr --outputs color,depth,normal,instance,albedo");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"out.albedo.exr", "out.depth.exr", "out.exr",
                                                     "out.instance.exr", "out.normal.exr"}));
  Framebuffer expected = reference(ColorFormat::rgba32f);
  // Channels of several values are interleaved in the framebuffer: take channel c of n.
  auto channel = [](const std::vector<float>& values, int c, int n) {
    std::vector<float> out;
    for (std::size_t i = c; i < values.size(); i += n) out.push_back(values[i]);
    return out;
  };
  ExrImage color = read_exr((dir / "out.exr").string());
  EXPECT_EQ(color.width, kWidth);
  EXPECT_EQ(color.height, kHeight);
  ASSERT_EQ(color.floats.size(), 4u);
  const char* rgba[] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c) {
    EXPECT_TRUE(same_bits(color.floats[rgba[c]], channel(expected.rgba32f(), c, 4))) << rgba[c];
  }
  ExrImage depth = read_exr((dir / "out.depth.exr").string());
  ASSERT_EQ(depth.floats.size(), 1u);
  EXPECT_TRUE(same_bits(depth.floats["Z"], expected.view_depth()));
  ExrImage normal = read_exr((dir / "out.normal.exr").string());
  ASSERT_EQ(normal.floats.size(), 3u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(same_bits(normal.floats[rgba[c]], channel(expected.normals(), c, 3))) << rgba[c];
  }
  ExrImage albedo = read_exr((dir / "out.albedo.exr").string());
  ASSERT_EQ(albedo.floats.size(), 4u);
  EXPECT_TRUE(same_bits(albedo.floats["G"], channel(expected.albedo(), 1, 4)));
  ExrImage instance = read_exr((dir / "out.instance.exr").string());
  ASSERT_EQ(instance.uints.size(), 1u);
  EXPECT_TRUE(same_bits(instance.uints["id"], expected.instance_ids()));
}

// Under a .png name: color as the PNG itself, floats beside it as OpenEXR, ids as 16-bit PNGs.
TEST(CliOutputs, PngNameGivesExrForFloatsAnd16BitPngForIds) {
  fs::path dir = fresh_test_dir("facet_cli_outputs_", "png");
  CommandResult r =
      run_facet(dir, kRender + "-o out.png --outputs color,distance,instance,triangle");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stdout_text.rfind("out.png: 64x48, ", 0), 0u) << r.stdout_text;
  EXPECT_NE(
      r.stdout_text.find("; wrote out.png, out.distance.exr, out.instance.png, out.triangle.png\n"),
      std::string::npos)
      << r.stdout_text;
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"out.distance.exr", "out.instance.png",
                                                     "out.png", "out.triangle.png"}));
  Framebuffer expected = reference(ColorFormat::rgba8_srgb);
  EXPECT_EQ(read_png((dir / "out.png").string()).pixels, expected.rgba8());
  EXPECT_TRUE(same_bits(read_exr((dir / "out.distance.exr").string()).floats["Z"],
                        expected.ray_distance()));
  for (const char* name : {"instance", "triangle"}) {
    Gray16Image ids = read_png16((dir / ("out." + std::string(name) + ".png")).string());
    EXPECT_EQ(ids.width, kWidth);
    EXPECT_EQ(ids.height, kHeight);
    const std::vector<std::uint32_t>& want =
        name == std::string("instance") ? expected.instance_ids() : expected.triangle_ids();
    ASSERT_EQ(ids.values.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) ASSERT_EQ(ids.values[i], want[i]) << name << i;
  }

  // Without color, only the other outputs are written, named after -o all the same.
  fs::path only = fresh_test_dir("facet_cli_outputs_", "png_no_color");
  ASSERT_EQ(run_facet(only, kRender + "-o out.png --outputs depth").exit_code, 0);
  EXPECT_EQ(list_dir(only), std::vector<std::string>{"out.depth.exr"});
}

// A triangle id past 65535 cannot go into a 16-bit PNG: said before anything is drawn, with
// the formats that hold it; the same render to .npz holds the id.
TEST(CliOutputs, IdsPast65535AreRefusedForPngOnly) {
  fs::path inputs = fresh_test_dir("facet_cli_outputs_", "many_inputs");
  {
    // 65536 triangles out of sight, then one in front of the camera: id 65537.
    std::ofstream obj(inputs / "many.obj");
    obj << "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nv 1000 0 0\nv 1001 0 0\nv 1000 1 0\n";
    for (int i = 0; i < 65536; ++i) obj << "f 4 5 6\n";
    obj << "f 1 2 3\n";
  }
  fs::path dir = fresh_test_dir("facet_cli_outputs_", "many");
  const std::string args = "render " + (inputs / "many.obj").string() +
                           " --eye 0,0,3 --target 0,0,0 --size 32x24 --outputs color,triangle ";
  CommandResult png = run_facet(dir, args + "-o out.png");
  EXPECT_EQ(png.exit_code, kUsageError);
  EXPECT_EQ(png.stderr_text,
            "facet: error: --outputs: triangle ids of this scene go up to 65537 (a mesh of that "
            "many triangles), more than a 16-bit PNG holds (65535); name the output .exr, .npy "
            "or .npz, which hold 32-bit ids\n");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{});

  CommandResult npz = run_facet(dir, args + "-o out.npz");
  ASSERT_EQ(npz.exit_code, 0) << npz.stderr_text;
  std::vector<std::uint32_t> ids =
      read_npz((dir / "out.npz").string())[1].second.values<std::uint32_t>();
  EXPECT_NE(std::find(ids.begin(), ids.end(), 65537u), ids.end());
}

}  // namespace
}  // namespace facet::test
