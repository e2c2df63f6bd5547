// `facet render MODEL` and the content flags through the real binary: models of several
// formats render, the flags change the image, and bad input gives one error line, exit code 2
// and no file; a missing texture warns once and draws a checker.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kUsageError = 2;
const char* const kBunny = "/usr/share/glmark2/models/bunny.obj";
const char* const kBox = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";

fs::path fresh_dir(const std::string& name) {
  fs::path dir = fs::path(::testing::TempDir()) / ("facet_model_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A shell-quoted path. (Built by appending: GCC 12 warns falsely (-Wrestrict) on
// "'" + std::string temporaries.)
std::string quoted(const std::string& path) {
  std::string q;
  q += '\'';
  q += path;
  q += '\'';
  return q;
}

CommandResult facet(const std::string& args) {
  return run_command(std::string(FACET_CLI) + " " + args);
}

// A cube in OBJ with an MTL whose diffuse map may be missing.
fs::path write_cube_obj(const fs::path& dir, const std::string& texture) {
  std::ofstream(dir / "cube.mtl") << "newmtl red\nKd 0.8 0.2 0.2\nKs 0.5 0.5 0.5\nNs 40\n"
                                  << (texture.empty() ? "" : "map_Kd " + texture + "\n");
  std::ofstream obj(dir / "cube.obj");
  obj << "mtllib cube.mtl\nusemtl red\n";
  for (int i = 0; i < 8; ++i)
    obj << "v " << (i & 1 ? 1 : -1) << " " << (i & 2 ? 1 : -1) << " " << (i & 4 ? 1 : -1) << "\n";
  obj << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  // Faces counter-clockwise seen from outside.
  const int faces[6][4] = {{1, 5, 7, 3}, {2, 4, 8, 6}, {1, 2, 6, 5},
                           {3, 7, 8, 4}, {1, 3, 4, 2}, {5, 6, 8, 7}};
  for (const auto& f : faces)
    obj << "f " << f[0] << "/1 " << f[1] << "/2 " << f[2] << "/3 " << f[3] << "/4\n";
  return dir / "cube.obj";
}

fs::path write_d(const fs::path& dir, const std::string& polygons) {
  std::ofstream(dir / "shape.d") << "data 4 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" << polygons;
  return dir / "shape.d";
}

// Renders and reads back; fails the test on a non-zero exit.
Rgba8Image render(const fs::path& dir, const std::string& args, const std::string& name) {
  fs::path out = dir / (name + ".png");
  CommandResult r = facet("render " + args + " --size 160x90 -o '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.stderr_text;
  EXPECT_EQ(std::count(r.stdout_text.begin(), r.stdout_text.end(), '\n'), 1) << r.stdout_text;
  return fs::exists(out) ? read_png(out.string()) : Rgba8Image{};
}

long differing_pixels(const Rgba8Image& a, const Rgba8Image& b) {
  if (a.pixels.size() != b.pixels.size()) return -1;
  long n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      if (std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > 8) {
        ++n;
        break;
      }
    }
  }
  return n;
}

bool has_many_colors(const Rgba8Image& image) {
  std::vector<std::uint32_t> seen;
  for (std::size_t i = 0; i < image.pixels.size(); i += 4 * 7) {
    seen.push_back(image.pixels[i] << 16 | image.pixels[i + 1] << 8 | image.pixels[i + 2]);
  }
  std::sort(seen.begin(), seen.end());
  return std::unique(seen.begin(), seen.end()) - seen.begin() > 20;
}

TEST(CliModel, ModelsOfSeveralFormatsRender) {
  fs::path dir = fresh_dir("formats");
  std::vector<std::string> models = {write_cube_obj(dir, "").string(),
                                     write_d(dir, "3 1 3 2\n3 1 2 4\n3 1 4 3\n3 2 3 4\n").string()};
  for (const char* path : {kBunny, kBox}) {
    if (fs::exists(path)) models.push_back(path);
  }
  int index = 0;
  for (const auto& model : models) {
    Rgba8Image image = render(dir, quoted(model), std::string("m").append(std::to_string(index++)));
    EXPECT_EQ(image.width, 160) << model;
    EXPECT_TRUE(has_many_colors(image)) << model << " rendered as a flat image";
  }
}

TEST(CliModel, FlagsChangeTheImage) {
  if (!fs::exists(kBunny)) GTEST_SKIP() << kBunny << " missing (glmark2-data)";
  fs::path dir = fresh_dir("flags");
  const std::string bunny = std::string("'") + kBunny + "'";
  Rgba8Image base = render(dir, bunny, "base");
  const char* variants[] = {
      "--shading pbr",
      "--shading normals",
      "--light dir,0,-1,0",
      "--light point,0,2,2,1,1,1,6 --light dir,1,0,0,0.2,0.2,1",
      "--fog exp,0.8",
      "--env sky",
      "--exposure 1",
      "--shading wire_overlay",
      "--texture '" FACET_GOLDEN_DIR "/shapes_normals.png' --projection spherical",
  };
  int index = 0;
  for (const char* flags : variants) {
    Rgba8Image changed =
        render(dir, bunny + " " + flags, std::string("v").append(std::to_string(index++)));
    EXPECT_GT(differing_pixels(base, changed), 160 * 90 / 50)
        << flags << " did not change the image";
  }
  Rgba8Image cylindrical = render(
      dir, bunny + " --texture '" FACET_GOLDEN_DIR "/shapes_normals.png' --projection cylindrical",
      "cyl");
  Rgba8Image planar = render(
      dir, bunny + " --texture '" FACET_GOLDEN_DIR "/shapes_normals.png' --projection planar",
      "planar");
  EXPECT_GT(differing_pixels(cylindrical, planar), 100) << "projections should differ";
}

TEST(CliModel, MissingTextureWarnsOnceAndRendersAChecker) {
  fs::path dir = fresh_dir("missing_texture");
  fs::path model = write_cube_obj(dir, "nowhere.png");
  fs::path out = dir / "out.png";
  CommandResult r =
      facet("render '" + model.string() + "' --size 160x90 -o '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("nowhere.png"), std::string::npos) << r.stderr_text;
  EXPECT_TRUE(fs::exists(out));
}

TEST(CliModel, BadInputIsOneLineExitTwoAndNoFile) {
  fs::path dir = fresh_dir("errors");
  fs::path obj = write_cube_obj(dir, "");
  std::ofstream(dir / "garbage.glb") << "this is not a glb file at all";
  fs::path bad_d = write_d(dir, "3 1 2 3\n3 1 2 9\n");
  const std::string cube = quoted(obj.string()) + " ";
  struct Case {
    std::string args, expect;
  } cases[] = {
      {quoted((dir / "nosuch.obj").string()), "nosuch.obj"},
      {quoted(dir.string()), ""},
      {quoted((dir / "garbage.glb").string()), "garbage.glb"},
      {quoted(bad_d.string()), "shape.d:7"},
      {cube + "--light bogus,1,2", "--light"},
      {cube + "--light dir,1,2", "--light"},
      {cube + "--light point,a,b,c", "--light"},
      {cube + "--fog fog", "--fog"},
      {cube + "--fog linear,5", "--fog"},
      {cube + "--fog linear,10,5", "--fog"},
      {cube + "--fog exp,-1", "--fog"},
      {cube + "--env " + quoted((dir / "missing.png").string()), "missing.png"},
      {cube + "--texture " + quoted((dir / "missing.png").string()), "missing.png"},
      {cube + "--texture '" FACET_GOLDEN_DIR "/shapes_unlit.png' --projection weird",
       "--projection"},
      {cube + "--reflectivity 2", "--reflectivity"},
      {cube + "--scene shapes", "not both"},
      {cube + "--exposure 100", "--exposure"},
      {cube + "--camera 3", "--camera"},
  };
  for (const Case& c : cases) {
    fs::path out = dir / "out.png";
    CommandResult r = facet("render " + c.args + " --size 64x36 -o '" + out.string() + "'");
    EXPECT_EQ(r.exit_code, kUsageError) << c.args << "\n" << r.stderr_text;
    EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << c.args << "\n"
                                                                               << r.stderr_text;
    EXPECT_EQ(r.stderr_text.rfind("facet: error:", 0), 0u) << c.args << "\n" << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(c.expect), std::string::npos) << c.args << "\n" << r.stderr_text;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

}  // namespace
}  // namespace facet::test
