// facet's PLY reader (src/import/ply_header.cpp, ply_format.cpp, ply_import.cpp): ASCII and both
// binary byte orders read alike; any property order and type; unknown elements and list
// properties skipped; point clouds; every PLY of assimp-testmodels imports as assimp read it;
// and hostile or damaged files (no end_header, truncated anywhere, counts that lie) are one
// clear error, promptly, without a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "facet/color.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "facet/texture.hpp"
#include "import/import_internal.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"
#include "support/sample_models.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const fs::path kPlyModels = "/usr/share/assimp/models/PLY";  // Debian's assimp-testmodels

ImportOptions collecting(std::vector<std::string>& warnings) {
  ImportOptions options;
  options.warn = [&warnings](const std::string& w) { warnings.push_back(w); };
  return options;
}

std::string error_of(const std::string& bytes) {
  try {
    io::parse_ply_geometry(bytes, "t.ply");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// --- one mesh written in the three formats ------------------------------------------------

// A square pyramid whose base is one quad: 5 vertices, a quad and four triangles. Its header
// mixes what the reader must skip (an unknown element with a list, an unknown scalar and a
// list among the vertex properties, face flags and a list of face weights) with the
// properties it reads, in an unusual order and of several types.
const glm::vec3 kApex(0.5f, 0.5f, 1.0f);
const std::vector<glm::vec3> kPositions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, kApex};
const std::vector<std::vector<std::uint32_t>> kFaces = {
    {0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

std::string pyramid_header(const std::string& format) {
  return "ply\nformat " + format +
         " 1.0\ncomment made by ply_format_test\nobj_info nothing\n"
         "element material 2\nproperty list uchar float params\nproperty int32 id\n"
         "element vertex 5\nproperty double y\nproperty float x\nproperty short extra\n"
         "property float32 z\nproperty list uint8 int neighbours\nproperty uchar red\n"
         "property uint8 green\nproperty uchar blue\nproperty float texture_u\n"
         "property float texture_v\n"
         "element face 5\nproperty uchar flags\nproperty list uchar uint vertex_indices\n"
         "property list uchar float weights\n"
         "end_header\n";
}

glm::u8vec3 color_of(std::size_t i) {
  return {static_cast<std::uint8_t>(40 * i), 255, static_cast<std::uint8_t>(255 - 50 * i)};
}

std::string pyramid_ascii() {
  std::string out = pyramid_header("ascii");
  out += "3 0.5 1 2 7\n0 8\n";  // two materials: a list of 3 and one of none
  for (std::size_t i = 0; i < kPositions.size(); ++i) {
    const glm::vec3 p = kPositions[i];
    const glm::u8vec3 c = color_of(i);
    out += std::to_string(p.y) + " " + std::to_string(p.x) + " -7 " + std::to_string(p.z) +
           " 2 1 3 " + std::to_string(c.r) + " " + std::to_string(c.g) + " " + std::to_string(c.b) +
           " " + std::to_string(p.x * 0.5f) + " " + std::to_string(p.y * 0.25f) + "\n";
  }
  for (const auto& face : kFaces) {
    out += "1 ";  // appended piece by piece: GCC 12 warns wrongly of "literal" + string&&
    out += std::to_string(face.size());
    for (std::uint32_t index : face) out += ' ' + std::to_string(index);
    out += " 2 0.25 0.75\n";
  }
  return out;
}

template <class T>
void put(std::string& out, T value, std::endian order) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof value);
  if (order != std::endian::native) std::reverse(bytes, bytes + sizeof bytes);
  out.append(bytes, sizeof bytes);
}

std::string pyramid_binary(std::endian order) {
  std::string out =
      pyramid_header(order == std::endian::little ? "binary_little_endian" : "binary_big_endian");
  put<std::uint8_t>(out, 3, order);
  for (float f : {0.5f, 1.0f, 2.0f}) put(out, f, order);
  put<std::int32_t>(out, 7, order);
  put<std::uint8_t>(out, 0, order);
  put<std::int32_t>(out, 8, order);
  for (std::size_t i = 0; i < kPositions.size(); ++i) {
    const glm::vec3 p = kPositions[i];
    const glm::u8vec3 c = color_of(i);
    put<double>(out, p.y, order);
    put<float>(out, p.x, order);
    put<std::int16_t>(out, -7, order);
    put<float>(out, p.z, order);
    put<std::uint8_t>(out, 2, order);
    put<std::int32_t>(out, 1, order);
    put<std::int32_t>(out, 3, order);
    put<std::uint8_t>(out, c.r, order);
    put<std::uint8_t>(out, c.g, order);
    put<std::uint8_t>(out, c.b, order);
    put<float>(out, p.x * 0.5f, order);
    put<float>(out, p.y * 0.25f, order);
  }
  for (const auto& face : kFaces) {
    put<std::uint8_t>(out, 1, order);
    put<std::uint8_t>(out, static_cast<std::uint8_t>(face.size()), order);
    for (std::uint32_t index : face) put<std::uint32_t>(out, index, order);
    put<std::uint8_t>(out, 2, order);
    put<float>(out, 0.25f, order);
    put<float>(out, 0.75f, order);
  }
  return out;
}

void expect_pyramid(const Mesh& mesh) {
  EXPECT_EQ(mesh.topology, Topology::triangles);
  EXPECT_EQ(mesh.positions, kPositions);
  // The quad fanned from its first corner, then the four triangles.
  const std::vector<std::uint32_t> indices = {0, 3, 2, 0, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  EXPECT_EQ(mesh.indices, indices);
  ASSERT_EQ(mesh.colors.size(), 5u);
  ASSERT_EQ(mesh.texcoords.size(), 5u);
  EXPECT_TRUE(mesh.normals.empty());
  for (std::size_t i = 0; i < kPositions.size(); ++i) {
    const glm::vec3 srgb = glm::vec3(color_of(i)) / 255.0f;
    const glm::vec3 linear = srgb_to_linear(srgb);
    // The reader scales in double, the test in float: the same to a few ulps.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mesh.colors[i][c], linear[c], 1e-6f) << i;
    EXPECT_EQ(mesh.colors[i].a, 1.0f);
    EXPECT_EQ(mesh.texcoords[i], glm::vec2(kPositions[i].x * 0.5f, kPositions[i].y * 0.25f));
  }
}

TEST(PlyFormat, AsciiAndBothBinaryByteOrdersReadTheSameMesh) {
  const std::string ascii = pyramid_ascii();
  const std::string little = pyramid_binary(std::endian::little);
  const std::string big = pyramid_binary(std::endian::big);
  ASSERT_NE(little, big);
  for (const std::string* bytes : {&ascii, &little, &big}) {
    SCOPED_TRACE(bytes->substr(4, 30));
    expect_pyramid(io::parse_ply_geometry(*bytes, "pyramid.ply").mesh);
  }
}

TEST(PlyFormat, AsciiAndBothBinaryByteOrdersImportTheSameScene) {
  const fs::path dir = fresh_test_dir("facet_ply_", "three_formats");
  write_file(dir / "ascii.ply", pyramid_ascii());
  write_file(dir / "little.ply", pyramid_binary(std::endian::little));
  write_file(dir / "big.ply", pyramid_binary(std::endian::big));
  std::vector<Scene> scenes;
  for (const char* name : {"ascii.ply", "little.ply", "big.ply"}) {
    std::vector<std::string> warnings;
    scenes.push_back(import_scene((dir / name).string(), collecting(warnings)));
    EXPECT_TRUE(warnings.empty()) << warnings.front();
  }
  for (const Scene& scene : scenes) {
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = *scene.meshes[0];
    const Mesh& first = *scenes[0].meshes[0];
    EXPECT_EQ(mesh.positions, first.positions);
    EXPECT_EQ(mesh.normals, first.normals);
    EXPECT_EQ(mesh.colors, first.colors);
    EXPECT_EQ(mesh.texcoords, first.texcoords);
    EXPECT_EQ(mesh.indices, first.indices);
    EXPECT_EQ(scene.triangle_count(), 6u);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());  // computed: the file has none
    // The material assimp's reader gave a PLY: white Blinn-Phong, both sides, vertex colors.
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].shading, ShadingModel::blinn_phong);
    EXPECT_EQ(scene.materials[0].cull, CullMode::none);
    EXPECT_TRUE(scene.materials[0].use_vertex_colors);
    EXPECT_EQ(scene.materials[0].base_color, glm::vec4(1.0f));
    EXPECT_GT(render_small(scene).triangles_in, 0u);
  }
}

TEST(PlyFormat, ColorsNamedDiffuseAndOfWiderTypesAreRead) {
  const Mesh mesh = io::parse_ply_geometry(
                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                        "property float y\nproperty float z\nproperty uchar diffuse_red\n"
                        "property uchar diffuse_green\nproperty ushort diffuse_blue\n"
                        "property float alpha\nend_header\n"
                        "0 0 0 255 0 0 0.5\n1 0 0 0 255 65535 1\n0 1 0 0 0 0 0\n",
                        "c.ply")
                        .mesh;
  EXPECT_EQ(mesh.topology, Topology::points);
  ASSERT_EQ(mesh.colors.size(), 3u);
  EXPECT_EQ(mesh.colors[0], glm::vec4(1, 0, 0, 0.5f));  // alpha is not a display value
  EXPECT_EQ(mesh.colors[1], glm::vec4(0, 1, 1, 1));
  EXPECT_EQ(mesh.colors[2], glm::vec4(0, 0, 0, 0));
  // A byte of 128 is sRGB 128/255: linear 0.2158.
  const Mesh half = io::parse_ply_geometry(
                        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                        "property float y\nproperty float z\nproperty uchar r\nproperty uchar g\n"
                        "property uchar b\nend_header\n0 0 0 128 128 128\n",
                        "h.ply")
                        .mesh;
  ASSERT_EQ(half.colors.size(), 1u);
  EXPECT_NEAR(half.colors[0].r, 0.2158f, 1e-4f);
}

TEST(PlyFormat, TristripsUnrollWithAlternateWindingAndRestarts) {
  const Mesh mesh = io::parse_ply_geometry(
                        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\n"
                        "property float y\nproperty float z\nelement tristrips 1\n"
                        "property list int int vertex_indices\nend_header\n"
                        "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n2 1 0\n"
                        "8 0 1 2 3 -1 1 4 3\n",
                        "s.ply")
                        .mesh;
  const std::vector<std::uint32_t> indices = {0, 1, 2, 2, 1, 3, 1, 4, 3};
  EXPECT_EQ(mesh.indices, indices);
}

// MeshLab writes texture coordinates per face corner (a `texcoord` list): each corner keeps its
// own, so the two sides of a seam sharing a vertex keep theirs; the importer joins the corners
// that are identical again.
TEST(PlyFormat, TextureCoordinatesPerFaceCorner) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
      "property list uchar float texcoord\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n-1 0.5 0\n"
      "3 0 1 2 6 0 0 0.5 0 0.5 0.5\n"
      "4 0 2 3 4 8 0.5 0 1 1 0 1 0.25 0.75\n";
  const Mesh mesh = io::parse_ply_geometry(text, "uv.ply").mesh;
  ASSERT_EQ(mesh.indices.size(), 9u);
  ASSERT_EQ(mesh.positions.size(), 9u);  // a vertex per corner
  ASSERT_EQ(mesh.texcoords.size(), 9u);
  // The triangle, then the quad fanned: (0 2 3) and (0 3 4), each corner with its face's pair.
  const std::vector<int> vertices = {0, 1, 2, 0, 2, 3, 0, 3, 4};
  const std::vector<glm::vec2> uvs = {{0, 0}, {0.5f, 0}, {0.5f, 0.5f}, {0.5f, 0},     {1, 1},
                                      {0, 1}, {0.5f, 0}, {0, 1},       {0.25f, 0.75f}};
  const std::vector<glm::vec3> positions = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5f, 0}};
  for (std::size_t k = 0; k < 9; ++k) {
    EXPECT_EQ(mesh.texcoords[mesh.indices[k]], uvs[k]) << k;
    EXPECT_EQ(mesh.positions[mesh.indices[k]], positions[vertices[k]]) << k;
  }
  // Through the importer, identical corners are joined again: vertex 0 keeps two pairs, (0, 0)
  // and (0.5, 0), and vertex 2 two, so 5 positions make 7 vertices.
  const fs::path file = fresh_test_dir("facet_ply_", "corner_uvs") / "uv.ply";
  write_file(file, text);
  const Scene scene = import_scene(file.string());
  EXPECT_EQ(scene.meshes[0]->positions.size(), 7u);
  EXPECT_EQ(scene.triangle_count(), 3u);
}

TEST(PlyFormat, TrailingListsALineLeavesOutAreEmpty) {
  // assimp's issue623.ply: the vertex element declares a list its lines do not have.
  const Mesh mesh = io::parse_ply_geometry(
                        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                        "property float y\nproperty float z\nproperty list uchar uint idx\n"
                        "end_header\n0 0 0\n1 2 3 2 0 1\n",
                        "l.ply")
                        .mesh;
  EXPECT_EQ(mesh.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 2, 3}}));
}

TEST(PlyFormat, NonFinitePositions) {
  // Points: left out. Triangles: kept as NaN, so the pipeline skips the triangles using them
  // and the bounds ignore them; vertices no face uses are dropped.
  const io::PlyGeometry points = io::parse_ply_geometry(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\nnan 0 0\n1 inf 0\n",
      "p.ply");
  EXPECT_EQ(points.mesh.positions, (std::vector<glm::vec3>{{0, 0, 0}}));
  EXPECT_EQ(points.non_finite, 2u);
  const io::PlyGeometry triangles = io::parse_ply_geometry(
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n-inf 0 0\n7 7 7\nnan 0 0\n3 0 1 2\n3 0 2 3\n",
      "t.ply");
  ASSERT_EQ(triangles.mesh.positions.size(), 4u);  // 4 and 5 are used by no face
  EXPECT_TRUE(std::isnan(triangles.mesh.positions[3].x));
  EXPECT_EQ(triangles.non_finite, 1u);
  EXPECT_EQ(triangles.mesh.indices.size(), 6u);
}

// --- what assimp read, read by facet --------------------------------------------------------

TEST(PlyFormat, EveryAssimpSampleImportsAsAssimpReadIt) {
  FACET_REQUIRE_PACKAGE(fs::exists(kPlyModels), "assimp-testmodels is not installed");
  struct Expected {
    std::size_t triangles, points, vertices;
  };
  // `facet info` of each file when assimp read it (pond.0.ply: below, an error either way).
  const std::map<std::string, Expected> expected = {
      {"Wuson.ply", {3732, 0, 11184}},  {"cube.ply", {12, 0, 24}},
      {"cube_binary.ply", {12, 0, 24}}, {"cube_uv.ply", {12, 0, 24}},
      {"float-color.ply", {1, 0, 3}},   {"issue623.ply", {0, 24, 24}},
      {"points.ply", {0, 4, 4}},
  };
  for (const auto& [name, counts] : expected) {
    SCOPED_TRACE(name);
    std::vector<std::string> warnings;
    const auto start = Clock::now();
    const Scene scene = import_scene((kPlyModels / name).string(), collecting(warnings));
    EXPECT_LT(Clock::now() - start, std::chrono::seconds(5));
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = *scene.meshes[0];
    EXPECT_EQ(scene.triangle_count(), counts.triangles);
    EXPECT_EQ(mesh.topology == Topology::points ? mesh.primitive_count() : 0u, counts.points);
    EXPECT_EQ(mesh.positions.size(), counts.vertices);
    const FrameStats stats = render_small(scene);
    EXPECT_GT(stats.triangles_in + stats.points_drawn, 0u);
  }
  // cube_uv.ply's texture coordinates and Wuson's normals come through.
  const Scene uv = import_scene((kPlyModels / "cube_uv.ply").string());
  EXPECT_EQ(uv.meshes[0]->texcoords.size(), uv.meshes[0]->positions.size());
  const Scene wuson = import_scene((kPlyModels / "Wuson.ply").string());
  EXPECT_EQ(wuson.meshes[0]->normals.size(), 11184u);
  // float-color.ply: float colors (0, 0, 1, 1) taken as they are.
  const Scene colored = import_scene((kPlyModels / "float-color.ply").string());
  ASSERT_EQ(colored.meshes[0]->colors.size(), 3u);
  EXPECT_EQ(colored.meshes[0]->colors[0], glm::vec4(0, 0, 1, 1));
}

TEST(PlyFormat, DamagedPondSampleIsOneClearError) {
  const fs::path pond = kPlyModels / "pond.0.ply";
  FACET_REQUIRE_PACKAGE(fs::exists(pond), "assimp-testmodels is not installed");
  try {
    import_scene(pond.string());
    FAIL() << "imported";
  } catch (const Error& e) {
    // 70051 vertices of 31 bytes need 2171581 bytes; the file has 69 fewer after its header.
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(pond.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("element 'vertex' (70051 items) does not fit: the elements up to it "
                           "need at least 2171581 bytes, the file has 2171512 after the header"),
              std::string::npos)
        << message;
  }
}

// --- hostile and damaged files ----------------------------------------------------------------

// The cases of issue 26 that hung assimp 5.2 or crashed it, through the facet program.
TEST(PlyFormat, FilesThatHungOrCrashedAssimpAreOneClearErrorPromptly) {
  const fs::path dir = fresh_test_dir("facet_ply_", "hostile");
  write_file(dir / "h.ply", "ply\nformat ascii 1.0\n");
  write_file(dir / "header_cut.ply",
             "ply\nformat binary_little_endian 1.0\nelement vertex 8\n"
             "property float x\nprop");
  std::vector<std::string> files = {"h.ply", "header_cut.ply"};
  if (fs::exists(kPlyModels / "cube_uv.ply")) {
    std::ifstream in(kPlyModels / "cube_uv.ply", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    write_file(dir / "a.ply", bytes.substr(0, 703));  // cut inside the vertices
    files.push_back("a.ply");
  }
  const std::map<std::string, std::string> expected = {
      {"h.ply", "the file ends before the header's end_header line (line 2)"},
      {"header_cut.ply", "the file ends before the header's end_header line (line 5)"},
      {"a.ply",
       "element 'face' (6 items) does not fit: the elements up to it need at least 396 bytes, "
       "the file has 384 after the header (line 13)"}};
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const std::string path = (dir / file).string();
    const auto start = Clock::now();
    const CommandResult result = run_command("timeout 60 " + std::string(FACET_CLI) + " render '" +
                                             path + "' -o '" + (dir / "o.png").string() + "'");
    EXPECT_LT(Clock::now() - start, std::chrono::seconds(10));
    EXPECT_EQ(result.exit_code, 2) << result.stderr_text;
    EXPECT_EQ(result.stderr_text, "facet: error: " + path + ": " + expected.at(file) + "\n");
    EXPECT_FALSE(fs::exists(dir / "o.png"));
  }
}

TEST(PlyFormat, CountsTheFileCannotHoldAreRefusedBeforeReading) {
  // 4 billion vertices in a file of 200 bytes: the header is refused, nothing is allocated for
  // them (the message comes from the header check, before any vertex is read).
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  const auto start = Clock::now();
  EXPECT_EQ(error_of(header + std::string(100, '\0')),
            "t.ply: element 'vertex' (4000000000 items) does not fit: the elements up to it need "
            "at least 48000000000 bytes, the file has 100 after the header (line 3)");
  // ASCII: at least 2 bytes a value, so 20 vertices of 3 values need 120.
  EXPECT_EQ(
      error_of("ply\nformat ascii 1.0\nelement vertex 20\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n0 0 0\n"),
      "t.ply: element 'vertex' (20 items) does not fit: the elements up to it need at least "
      "120 bytes, the file has 6 after the header (line 3)");
  // A list claiming more values than the rest of the file.
  std::string lying_list =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty uchar x\n"
      "property uchar y\nproperty uchar z\nelement face 1\n"
      "property list uint int vertex_indices\nend_header\n";
  lying_list += std::string(9, '\0');
  put<std::uint32_t>(lying_list, 4000000000u, std::endian::little);
  lying_list += std::string(12, '\0');
  EXPECT_NE(error_of(lying_list).find("has 4000000000 values, more than the rest of the file"),
            std::string::npos)
      << error_of(lying_list);
  // An element count beyond 64 bits.
  EXPECT_NE(error_of("ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\n"
                     "end_header\n")
                .find("too many items"),
            std::string::npos);
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(1));
}

TEST(PlyFormat, TruncatedAnywhereIsAnErrorNeverACrash) {
  // Binary: every item has its size, so any cut short of the whole file is an error.
  for (std::endian order : {std::endian::little, std::endian::big}) {
    const std::string bytes = pyramid_binary(order);
    for (std::size_t size = 0; size < bytes.size(); ++size) {
      EXPECT_EQ(error_of(bytes.substr(0, size)).rfind("t.ply: ", 0), 0u) << size << " bytes";
    }
    expect_pyramid(io::parse_ply_geometry(bytes, "whole.ply").mesh);
  }
  // ASCII: a cut inside the last number still reads ("0.7" for "0.75"), so each cut is an error
  // or a valid mesh, never a crash.
  const std::string text = pyramid_ascii();
  for (std::size_t size = 0; size < text.size(); ++size) {
    try {
      io::parse_ply_geometry(text.substr(0, size), "cut.ply").mesh.validate();
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("cut.ply: ", 0), 0u);
    }
  }
}

TEST(PlyFormat, MalformedInputNamesWhatAndWhere) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(error_of("solid cube\n"),
            "t.ply: not a PLY file (it does not start with a line 'ply') (line 1)");
  EXPECT_EQ(error_of("ply\nformat binary_middle_endian 1.0\nend_header\n"),
            "t.ply: unknown format 'binary_middle_endian' (ascii, binary_little_endian or "
            "binary_big_endian) (line 2)");
  EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n"),
            "t.ply: unknown property type 'float128' (line 4)");
  EXPECT_EQ(error_of("ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
            "t.ply: a property comes before any element (line 3)");
  EXPECT_EQ(error_of(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            "t.ply: face 0 (of 1): vertex index 3 is out of range (0..2) (line 13)");
  EXPECT_EQ(error_of(head + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"),
            "t.ply: 'zero' is not a number (in vertex 1 (of 3)) (line 11)");
  EXPECT_EQ(error_of(head + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
            "t.ply: the line ends before the last value of vertex 1 (of 3) (line 11)");
  EXPECT_EQ(error_of(head + "0 0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
            "t.ply: vertex 0 (of 3) has more values than the header declares properties (line 10)");
  EXPECT_EQ(error_of(head + "0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n"),
            "t.ply: list 'vertex_indices' has a length of -3 (line 13)");
  EXPECT_EQ(error_of("ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int "
                     "vertex_indices\nend_header\n"),
            "t.ply: the header declares no vertex element (line 5)");
}

// MeshLab's `comment TextureFile NAME`: the image next to the model is the base color map; a
// name leading out of the model's folder is refused with a warning and the checker.
TEST(PlyFormat, TextureFileCommentNamesTheBaseColorMap) {
  const fs::path dir = fresh_test_dir("facet_ply_", "texture_file");
  write_file(dir / "red.ppm", std::string("P3\n1 1\n255\n255 0 0\n"));
  const std::string body =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float s\nproperty float t\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n";
  write_file(dir / "inside.ply", "ply\nformat ascii 1.0\ncomment TextureFile red.ppm\n" + body);
  write_file(dir / "outside.ply",
             "ply\nformat ascii 1.0\ncomment TextureFile ../../etc/passwd\n" + body);
  std::vector<std::string> warnings;
  const Scene inside = import_scene((dir / "inside.ply").string(), collecting(warnings));
  EXPECT_TRUE(warnings.empty());
  ASSERT_TRUE(inside.materials[0].base_color_map);
  EXPECT_EQ(inside.materials[0].base_color_map.texture->level(0).width, 1);
  const Scene outside = import_scene((dir / "outside.ply").string(), collecting(warnings));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("outside the model's folder"), std::string::npos) << warnings[0];
  EXPECT_EQ(outside.materials[0].base_color_map.texture, missing_texture());
}

}  // namespace
}  // namespace facet::test
