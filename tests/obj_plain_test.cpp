// facet's reader of plain OBJ geometry (src/import/obj_plain.cpp, obj_import.cpp): a file of
// positions, normals, texture coordinates and triangles in every corner form gives the scene
// assimp's reader gives it (nodes, material, meshes, bit for bit); every other file, and every
// odd one, goes to assimp's reader whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "facet/import.hpp"
#include "import/import_internal.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"
#include "support/scene_compare.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const std::string kBunny = "/usr/share/glmark2/models/bunny.obj";

fs::path write_model(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(::testing::TempDir()) / "facet_obj_plain";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  return path;
}

// A unit square in two triangles and a third off it, with everything a plain file may hold.
const char kEveryForm[] =
    "# plain geometry\r\n"
    "v 0 0 0\r\n"
    "v\t1.0  0 0\r\n"
    "v +1 1.e0 -0\r\n"
    "v 0 1 0 \r\n"
    "v 2.5E-1 2e+0 1\r\n"
    "vt 0 0\r\n"
    "vt 1 0 0\r\n"
    "vt 1 1\r\n"
    "vt 0 1\r\n"
    "vn 0 0 1\r\n"
    "vn 0 0.6 0.8\r\n"
    "\r\n"
    "f 1/1/1 2/2/1 3/3/1\r\n"
    "f -5/-4/-2 -2/-1/-2 -3/-2/-1\r\n"
    "f 4/4/2 3/3/2 5/1/2\r\n";

TEST(ObjPlain, EveryCornerFormGivesAssimpsScene) {
  const std::vector<std::pair<std::string, std::string>> models = {
      {"positions.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"},
      {"texcoords.obj",
       "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 3/3 2/2 1/1\n"},
      {"normals.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nvn 0 1 0\nf 1//1 2//1 3//2\n"},
      {"every_form.obj", kEveryForm},
      {"no_last_line_end.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3"}};
  for (const auto& [name, text] : models) {
    SCOPED_TRACE(name);
    const fs::path path = write_model(name, text);
    ASSERT_TRUE(io::read_plain_obj(text)) << "not read as plain geometry";
    expect_same_scene(io::import_obj_scene(path.string(), ImportOptions{}),
                      io::import_assimp_scene(path.string(), ImportOptions{}));
  }
}

// assimp reads numbers its own way, not always correctly rounded: positions may be a unit in the
// last place off; each of ours is the float nearest the number written (strtof's).
TEST(ObjPlain, TheSampleFilesOfPlainGeometryGiveAssimpsScene) {
  FACET_REQUIRE_PACKAGE(fs::exists(kBunny), kBunny << " is not installed (glmark2-data)");
  FACET_REQUIRE_PACKAGE(fs::exists(kSampleModels), "assimp-testmodels is not installed");
  for (const fs::path& path : {fs::path(kBunny), kSampleModels / "OBJ/multiple_spaces.obj"}) {
    SCOPED_TRACE(path.string());
    std::ifstream in(path, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    const std::optional<Mesh> mesh = io::read_plain_obj(text);
    ASSERT_TRUE(mesh) << "not read as plain geometry";
    expect_same_scene(io::import_obj_scene(path.string(), ImportOptions{}),
                      io::import_assimp_scene(path.string(), ImportOptions{}), 1);
    // The first face's corners against the numbers of their `v` lines.
    std::istringstream lines(text);
    std::string kind, x, y, z;
    std::vector<glm::vec3> written;
    while (lines >> kind && kind == "v" && lines >> x >> y >> z) {
      written.push_back({std::strtof(x.c_str(), nullptr), std::strtof(y.c_str(), nullptr),
                         std::strtof(z.c_str(), nullptr)});
    }
    ASSERT_GE(written.size(), 3u);
    const auto before = [](const glm::vec3& a, const glm::vec3& b) {
      return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    std::sort(written.begin(), written.end(), before);
    std::size_t found = 0;
    for (const glm::vec3& p : mesh->positions)
      found += std::binary_search(written.begin(), written.end(), p, before);
    EXPECT_EQ(found, mesh->positions.size());
  }
}

// Each corner its own vertex, in face order, as assimp's reader makes them.
TEST(ObjPlain, CornersInFaceOrder) {
  const std::optional<Mesh> mesh = io::read_plain_obj(kEveryForm);
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->topology, Topology::triangles);
  ASSERT_EQ(mesh->positions.size(), 9u);
  EXPECT_EQ(mesh->indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
  // f -5/-4/-2 -2/-1/-2 -3/-2/-1: counted back from the fifth position, fourth texture
  // coordinate and second normal.
  EXPECT_EQ(mesh->positions[3], glm::vec3(0, 0, 0));
  EXPECT_EQ(mesh->positions[4], glm::vec3(0, 1, 0));
  EXPECT_EQ(mesh->positions[5], glm::vec3(1, 1, -0.0f));
  EXPECT_EQ(mesh->positions[8], glm::vec3(0.25f, 2.0f, 1.0f));
  EXPECT_EQ(mesh->texcoords[4], glm::vec2(0, 1));
  EXPECT_EQ(mesh->texcoords[5], glm::vec2(1, 1));
  EXPECT_EQ(mesh->normals[3], glm::vec3(0, 0, 1));
  EXPECT_EQ(mesh->normals[5], glm::vec3(0, 0.6f, 0.8f));
}

// Anything else is assimp's to read: the other kinds of line, other ways of writing these, and
// what assimp's post-processing would change.
TEST(ObjPlain, AnythingElseGoesToAssimp) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<std::string> others = {
      "",                                         // nothing
      triangle,                                   // a point cloud
      triangle + "v 1 1 0\nf 1 2 3 4\n",          // a polygon
      triangle + "f 1 2\n",                       // too few corners
      triangle + "l 1 2\n",                       // a line
      triangle + "p 1\n",                         // a point
      "o cube\n" + triangle + "f 1 2 3\n",        // an object
      "g side\n" + triangle + "f 1 2 3\n",        // a group
      "s 1\n" + triangle + "f 1 2 3\n",           // a smoothing group
      "mtllib m.mtl\n" + triangle + "f 1 2 3\n",  // materials
      "usemtl m\n" + triangle + "f 1 2 3\n",
      "v 0 0 0 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",      // w
      "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",  // a vertex color
      "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",          // two numbers
      "v 0 0 3.1+e2\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",   // assimp's own number reading
      "v 0 0 +-1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",      // two signs
      "v 0 0 inf\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",      // not finite
      "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
      "v 0 0 1e39\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",      // beyond a float
      "v 0 0 0x1p3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",     // hexadecimal
      "v 0 0 0 # here\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",  // a comment after data
      "v 0 0 0\\\n1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",    // a continued line
      triangle + "f 1 2 4\n",                         // an index past the positions
      triangle + "f 0 1 2\n",                         // index 0
      triangle + "f -4 1 2\n",                        // counted back too far
      triangle + "f +1 2 3\n",                        // a signed index
      triangle + "f 1/1 2/1 3/1\nvt 0 0\n",           // a texture coordinate before its line
      triangle + "vt 0 0\nvt 1 0\nf 1/1 2/2 3/1\nf 1 2 3\n",  // corner forms mixed
      triangle + "vt 0 0\nf 1/1/ 2/1/ 3/1/\n",                // a form of none
      triangle + "vn 0 0 1\nf 1//1//1 2//1 3//1\n",
      triangle + "vn 0 0 0\nf 1//1 2//1 3//1\n",                // a normal of zero length
      triangle + "vt 0.5 0.5\nf 1/1 2/1 3/1\nf 3/1 2/1 1/1\n",  // texture coordinates alike
      triangle + "vn 0 0 1\nf 1//1 2//1 3//1\n",                // normals alike
      "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n",                   // positions alike
      triangle + "f 1 2 3\n\x01\n",                             // other bytes
      triangle + "F 1 2 3\n",
  };
  for (const std::string& text : others) {
    EXPECT_FALSE(io::read_plain_obj(text)) << text;
  }
}

}  // namespace
}  // namespace facet::test
