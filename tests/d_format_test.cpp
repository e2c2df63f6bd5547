// The `.d` reader (src/io/d_format.cpp): optional header, comments, blank lines, fan
// triangulation, outward winding, and every malformed input reported as "<name>:<line>: ...".
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

using Triangle = std::array<glm::vec3, 3>;

std::vector<Triangle> triangles(const Mesh& mesh) {
  std::vector<Triangle> out;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    out.push_back({mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                   mesh.positions[mesh.indices[i + 2]]});
  }
  return out;
}

std::string error_of(const std::string& text) {
  try {
    parse_d(text, "t.d");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

const char* const kSquareWithHeader =
    "data 4 2\n"
    "0 0 0\n"
    "1 0 0\n"
    "1 1 0\n"
    "0 1 0\n"
    "3 1 2 3\n"
    "3 1 3 4\n";

TEST(DFormat, HeaderIsOptional) {
  const std::string without = std::string(kSquareWithHeader).substr(9);  // drop "data 4 2\n"
  Mesh a = parse_d(kSquareWithHeader, "a.d");
  Mesh b = parse_d(without, "b.d");
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(triangles(a).size(), 2u);
}

TEST(DFormat, CommentsBlankLinesAndWindowsLineEndings) {
  Mesh mesh = parse_d(
      "# a square\r\n\r\ndata 4 2   # header\r\n  0 0 0\r\n1 0 0 # right\r\n\r\n"
      "+1 1e0 0\r\n0 1 0\r\n# polygons\r\n3 1 2 3\r\n\t3 1 3 4\r\n",
      "c.d");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[2], glm::vec3(1, 1, 0));
  EXPECT_EQ(triangles(mesh).size(), 2u);
}

TEST(DFormat, PentagonIsFanTriangulated) {
  const std::vector<glm::vec3> p = {
      {0, 0, 0}, {1, 0, 0}, {1.3f, 1, 0}, {0.5f, 1.6f, 0}, {-0.3f, 1, 0}};
  Mesh mesh = parse_d("0 0 0\n1 0 0\n1.3 1 0\n0.5 1.6 0\n-0.3 1 0\n5 1 2 3 4 5\n", "p.d");
  std::vector<Triangle> t = triangles(mesh);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0], (Triangle{p[0], p[1], p[2]}));
  EXPECT_EQ(t[1], (Triangle{p[0], p[2], p[3]}));
  EXPECT_EQ(t[2], (Triangle{p[0], p[3], p[4]}));
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
  EXPECT_NO_THROW(mesh.validate());
}

// A cube wound clockwise (inside out): the reader turns it so normals point outward.
TEST(DFormat, ClosedModelsAreWoundOutward) {
  Mesh mesh = parse_d(
      "data 8 6\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
      "4 1 2 3 4\n4 8 7 6 5\n4 5 6 2 1\n4 6 7 3 2\n4 7 8 4 3\n4 8 5 1 4\n",
      "cube.d");
  EXPECT_EQ(mesh.positions.size(), 24u);  // hard edges
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_GT(glm::dot(mesh.normals[i], mesh.positions[i]), 0.0f) << "vertex " << i;
  }
  for (const Triangle& t : triangles(mesh)) {
    glm::vec3 face = glm::cross(t[1] - t[0], t[2] - t[0]);
    EXPECT_GT(glm::dot(face, t[0] + t[1] + t[2]), 0.0f);  // counter-clockwise from outside
  }
}

TEST(DFormat, MalformedInputNamesFileAndLine) {
  const std::string three = "data 3 1\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(error_of(three + "3 1 2 9\n"), "t.d:5: polygon index 9 is out of range (1..3)");
  EXPECT_EQ(error_of(three + "3 0 1 2\n"), "t.d:5: polygon index 0 is out of range (1..3)");
  EXPECT_EQ(error_of(three + "3 1 2 -3\n"), "t.d:5: polygon index -3 is out of range (1..3)");
  EXPECT_EQ(error_of(three + "3 1 2 99999999999999999999\n"),
            "t.d:5: polygon index 99999999999999999999 is out of range (1..3)");
  EXPECT_EQ(error_of(three + "3 1 2 2.5\n"), "t.d:5: polygon index '2.5' is not a whole number");
  EXPECT_EQ(error_of("data 3 1\n0 0 0\n1 zero 0\n0 1 0\n3 1 2 3\n"),
            "t.d:3: 'zero' is not a number");
  EXPECT_EQ(error_of("data 3 1\n0 0 0\n\n1 0 nan\n0 1 0\n3 1 2 3\n"),
            "t.d:4: coordinate 'nan' is not a finite number");
  EXPECT_EQ(error_of("data 3 1\n0 0 0\n1 0 1e999\n0 1 0\n3 1 2 3\n"),
            "t.d:3: coordinate '1e999' is not a finite number");
  EXPECT_EQ(error_of("data 3 1\n0 0 0\n1 0\n0 1 0\n3 1 2 3\n"),
            "t.d:3: the header says 3 vertices but only 1 come before this line (a vertex is x "
            "y z)");
  EXPECT_EQ(error_of("data 4 1\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n"),
            "t.d:5: the header says 4 vertices but only 3 come before this line (a vertex is x "
            "y z)");
  EXPECT_EQ(error_of("data 5 0\n0 0 0\n# end\n"),
            "t.d:3: the header says 5 vertices but the "
            "file has 1");
  EXPECT_EQ(error_of(three + "2 1 2\n"),
            "t.d:5: a polygon needs at least 3 vertices, this one has 2");
  EXPECT_EQ(error_of(three + "4 1 2 3\n"), "t.d:5: the polygon says 4 vertices but lists 3");
  EXPECT_EQ(error_of("data 3 2\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n"),
            "t.d:5: the header says 2 polygons but the file has 1");
  EXPECT_EQ(error_of(three + "3 1 2 3\n3 3 2 1\n"),
            "t.d:6: the header says 1 polygons but there are more lines");
  EXPECT_EQ(error_of("data 3\n"),
            "t.d:1: the header must be 'data <vertex count> <polygon count>'");
  EXPECT_EQ(error_of("data -1 2\n"),
            "t.d:1: the header must be 'data <vertex count> <polygon count>'");
  // Without a header, a line that is not 3 numbers starts the polygons.
  EXPECT_EQ(error_of("0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n0.5 1\n"),
            "t.d:5: a polygon line starts with its vertex count, found '0.5'");
}

TEST(DFormat, EmptyTextGivesAnEmptyMesh) {
  Mesh mesh = parse_d("# nothing\n\n", "e.d");
  EXPECT_TRUE(mesh.positions.empty());
  EXPECT_TRUE(mesh.indices.empty());
}

fs::path write(const std::string& name, const std::string& text) {
  fs::path path = fs::path(::testing::TempDir()) / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(DFormat, ReadFileAndImportScene) {
  fs::path path = write("facet_square.d", kSquareWithHeader);
  Mesh mesh = read_d_file(path.string());
  EXPECT_EQ(triangles(mesh).size(), 2u);
  Scene scene = import_scene(path.string());
  ASSERT_EQ(scene.nodes.size(), 1u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].shading, ShadingModel::blinn_phong);
  EXPECT_FLOAT_EQ(scene.materials[0].shininess, 32.0f);
  EXPECT_EQ(scene.triangle_count(), 2u);
  EXPECT_FALSE(scene.has_file_lights);
  EXPECT_NO_THROW(scene.camera.validate());
  EXPECT_NEAR(glm::distance(scene.camera.target, glm::vec3(0.5f, 0.5f, 0.0f)), 0.0f, 1e-5f);
}

TEST(DFormat, FileErrorsNameThePath) {
  fs::path bad = write("facet_bad.d", "data 3 1\n0 0 0\n1 0 0\n0 1 0\n3 1 2 4\n");
  try {
    import_scene(bad.string());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), bad.string() + ":5: polygon index 4 is out of range (1..3)");
  }
  EXPECT_THROW(read_d_file("/nonexistent/cow.d"), Error);
  try {
    read_d_file("/nonexistent/cow.d");
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/cow.d: no such file");
  }
  fs::path empty = write("facet_empty.d", "# no polygons\n");
  try {
    import_scene(empty.string());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), empty.string() + ": no triangles to draw");
  }
}

}  // namespace
}  // namespace facet::test
