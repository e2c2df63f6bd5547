// facet's STL reader (src/import/stl_format.cpp, stl_weld.cpp, stl_import.cpp): binary, ASCII
// and binary files whose header starts with "solid" told apart by content; identical positions
// welded into an indexed mesh the same whatever the thread count, with no cracks between
// triangles that share an edge; every STL of assimp-testmodels drawn as assimp's reader drew
// it; damaged files (truncated, counts that lie, NaN vertices, garbage) one clear error or
// warning, never a crash.
#include "import/stl_format.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <limits>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "import/import_internal.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;
namespace stl = io::stl;

const fs::path kStlModels = "/usr/share/assimp/models/STL";  // Debian's assimp-testmodels

struct Facet {
  glm::vec3 normal, a, b, c;
  std::uint16_t attribute = 0;
};

void put_float(std::string& out, float f) {
  const auto w = std::bit_cast<std::uint32_t>(f);
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((w >> (8 * i)) & 0xff));
}

std::string binary_stl(const std::vector<Facet>& facets, std::string header = "binary test",
                       std::uint32_t claimed = ~0u) {
  header.resize(80, ' ');
  std::string out = header;
  const std::uint32_t count = claimed != ~0u ? claimed : static_cast<std::uint32_t>(facets.size());
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((count >> (8 * i)) & 0xff));
  for (const Facet& f : facets) {
    for (const glm::vec3& v : {f.normal, f.a, f.b, f.c}) {
      put_float(out, v.x), put_float(out, v.y), put_float(out, v.z);
    }
    out.push_back(static_cast<char>(f.attribute & 0xff));
    out.push_back(static_cast<char>(f.attribute >> 8));
  }
  return out;
}

std::string ascii_stl(const std::vector<Facet>& facets) {
  std::string out = "solid test part\n";
  char line[160];
  for (const Facet& f : facets) {
    std::snprintf(line, sizeof line, "  facet normal %g %g %g\n    outer loop\n", f.normal.x,
                  f.normal.y, f.normal.z);
    out += line;
    for (const glm::vec3& v : {f.a, f.b, f.c}) {
      std::snprintf(line, sizeof line, "      vertex %.9g %.9g %.9g\n", v.x, v.y, v.z);
      out += line;
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid test part\n";
}

stl::Geometry parse(const std::string& bytes, const std::string& name = "t.stl") {
  return stl::parse(stl::memory_source(bytes.data(), bytes.size()), name);
}

std::string error_of(const std::string& bytes) {
  try {
    parse(bytes);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// A unit square in z = 0 as two triangles sharing the diagonal, and a pyramid over it: 5
// positions shared by 6 triangles.
std::vector<Facet> pyramid() {
  const glm::vec3 p0(0, 0, 0), p1(1, 0, 0), p2(1, 1, 0), p3(0, 1, 0), apex(0.5f, 0.5f, 1.0f);
  auto facet = [](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    return Facet{glm::normalize(glm::cross(b - a, c - a)), a, b, c};
  };
  return {facet(p0, p2, p1),   facet(p0, p3, p2),   facet(p0, p1, apex),
          facet(p1, p2, apex), facet(p2, p3, apex), facet(p3, p0, apex)};
}

void expect_pyramid(const stl::Geometry& g) {
  EXPECT_EQ(g.mesh.positions.size(), 5u);
  ASSERT_EQ(g.mesh.indices.size(), 18u);
  EXPECT_TRUE(g.mesh.normals.empty());
  EXPECT_TRUE(g.facet_normals_usable);
  EXPECT_EQ(g.non_finite, 0u);
  // Numbered in order of first use: the first triangle's corners are 0, 1, 2.
  EXPECT_EQ(g.mesh.indices[0], 0u);
  EXPECT_EQ(g.mesh.indices[1], 1u);
  EXPECT_EQ(g.mesh.indices[2], 2u);
  const std::vector<Facet> facets = pyramid();
  for (std::size_t t = 0; t < facets.size(); ++t) {
    EXPECT_EQ(g.mesh.positions[g.mesh.indices[t * 3]], facets[t].a);
    EXPECT_EQ(g.mesh.positions[g.mesh.indices[t * 3 + 1]], facets[t].b);
    EXPECT_EQ(g.mesh.positions[g.mesh.indices[t * 3 + 2]], facets[t].c);
  }
}

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// --- the two encodings ----------------------------------------------------------------------

TEST(StlFormat, BinaryIsReadAndWelded) {
  const stl::Geometry g = parse(binary_stl(pyramid()));
  EXPECT_TRUE(g.binary);
  expect_pyramid(g);
}

TEST(StlFormat, AsciiIsReadAndWelded) {
  const stl::Geometry g = parse(ascii_stl(pyramid()));
  EXPECT_FALSE(g.binary);
  expect_pyramid(g);
}

TEST(StlFormat, BinaryWhoseHeaderStartsWithSolidIsBinary) {
  // SolidWorks writes "solid" at the start of a binary header: the size decides.
  const stl::Geometry g = parse(binary_stl(pyramid(), "solid part exported as binary"));
  EXPECT_TRUE(g.binary);
  expect_pyramid(g);
}

TEST(StlFormat, SeveralAsciiSolidsAreOneMesh) {
  const std::vector<Facet> all = pyramid();
  const std::string two =
      ascii_stl({all.begin(), all.begin() + 2}) + ascii_stl({all.begin() + 2, all.end()});
  expect_pyramid(parse(two));
}

TEST(StlFormat, MinusZeroWeldsWithZero) {
  std::vector<Facet> facets = pyramid();
  facets[1].a = glm::vec3(-0.0f, -0.0f, -0.0f);  // p0 again, spelled with minus zeros
  const stl::Geometry g = parse(binary_stl(facets));
  EXPECT_EQ(g.mesh.positions.size(), 5u);
  EXPECT_FALSE(std::signbit(g.mesh.positions[g.mesh.indices[3]].x));
}

// The same mesh whatever the number of threads: the weld numbers vertices by first use.
TEST(StlFormat, WeldingIsTheSameOnOneThreadAndOnAll) {
  // A 300 x 300 grid of cells (180,000 triangles, several tasks' worth), corners shuffled
  // between triangles so that the table sees positions in no particular order.
  std::vector<glm::vec3> corners;
  constexpr int kCells = 300;
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const glm::vec3 p(i, j, 0), q(i + 1, j, 0), r(i + 1, j + 1, 0), s(i, j + 1, 0);
      corners.insert(corners.end(), {p, q, r, p, r, s});
    }
  }
  const Mesh all = stl::weld(corners);
  Mesh one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = stl::weld(corners);
  }
  EXPECT_EQ(all.positions.size(), static_cast<std::size_t>((kCells + 1) * (kCells + 1)));
  EXPECT_EQ(all.positions, one.positions);
  EXPECT_EQ(all.indices, one.indices);
  for (std::size_t i = 0; i < corners.size(); ++i) {
    ASSERT_EQ(all.positions[all.indices[i]], corners[i]) << i;
  }
}

// A fan of thin triangles around a centre, all sharing edges: drawn welded, every pixel inside
// the disc is covered exactly once (no crack lets the background through, no pixel twice).
TEST(StlFormat, SharedEdgesDrawWithoutCracks) {
  std::vector<Facet> facets;
  constexpr int kSlices = 97;
  const glm::vec3 centre(0.013f, -0.021f, -3.0f);
  std::vector<glm::vec3> rim;
  for (int k = 0; k < kSlices; ++k) {
    const float a = 6.2831853f * static_cast<float>(k) / kSlices;
    rim.push_back(centre + glm::vec3(std::cos(a), std::sin(a), 0.0f) * 1.1f);
  }
  for (int k = 0; k < kSlices; ++k) {
    facets.push_back({glm::vec3(0, 0, 1), centre, rim[k], rim[(k + 1) % kSlices]});
  }
  const stl::Geometry g = parse(binary_stl(facets));
  EXPECT_EQ(g.mesh.positions.size(), static_cast<std::size_t>(kSlices + 1));
  constexpr int kSize = 96;
  const std::vector<int> counts =
      coverage_counts({&g.mesh}, test_camera(kSize, kSize), kSize, kSize);
  int covered = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const int c = counts[static_cast<std::size_t>(y * kSize + x)];
      EXPECT_LE(c, 1) << x << "," << y;
      covered += c;
      // Pixels well inside the disc (the view is 2 tan 30 * 3 = 3.46 units across).
      const float px = (x + 0.5f - kSize / 2.0f) / kSize * 3.4641f;
      const float py = (kSize / 2.0f - y - 0.5f) / kSize * 3.4641f;
      if (std::hypot(px - centre.x, py - centre.y) < 0.95f) {
        EXPECT_EQ(c, 1) << "crack at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(covered, 2000);
}

// --- what the file's normals decide -----------------------------------------------------------

TEST(StlFormat, ZeroOrEqualNormalsAreNotUsedToShade) {
  std::vector<Facet> zero = pyramid();
  zero[3].normal = glm::vec3(0.0f);
  EXPECT_FALSE(parse(binary_stl(zero)).facet_normals_usable);
  std::vector<Facet> same = pyramid();
  for (Facet& f : same) f.normal = glm::vec3(0, 0, 1);
  EXPECT_FALSE(parse(binary_stl(same)).facet_normals_usable);
}

TEST(StlFormat, ImportedMeshIsFacetedOrSmoothAsAssimpsPathMadeIt) {
  const fs::path dir = fresh_test_dir("facet_stl_", "normals");
  write_file(dir / "faceted.stl", binary_stl(pyramid()));
  std::vector<Facet> zero = pyramid();
  for (Facet& f : zero) f.normal = glm::vec3(0.0f);
  write_file(dir / "smooth.stl", binary_stl(zero));
  const Scene faceted = import_scene((dir / "faceted.stl").string());
  ASSERT_EQ(faceted.meshes.size(), 1u);
  EXPECT_TRUE(faceted.meshes[0]->normals.empty());  // the renderer's face normals
  EXPECT_EQ(faceted.meshes[0]->positions.size(), 5u);
  const Scene smooth = import_scene((dir / "smooth.stl").string());
  EXPECT_EQ(smooth.meshes[0]->normals.size(), smooth.meshes[0]->positions.size());
  EXPECT_GT(smooth.meshes[0]->positions.size(), 5u);  // split at the base's 90-degree crease
  ASSERT_EQ(faceted.materials.size(), 1u);
  EXPECT_EQ(faceted.materials[0].shading, ShadingModel::blinn_phong);
  EXPECT_EQ(faceted.materials[0].cull, CullMode::back);
}

TEST(StlFormat, MaterialiseHeaderColorIsTheModelsColor) {
  std::string header = "made by Magics COLOR=";
  header += std::string("\x33\x66\x99\xff", 4);
  const stl::Geometry g = parse(binary_stl(pyramid(), header));
  ASSERT_TRUE(g.color.has_value());
  EXPECT_EQ(*g.color, glm::vec4(0x33, 0x66, 0x99, 0xff) / 255.0f);
}

// --- damaged and hostile files -------------------------------------------------------------

TEST(StlFormat, TruncatedBinaryIsOneClearError) {
  const std::string whole = binary_stl(pyramid(), "not solid");
  EXPECT_EQ(error_of(whole.substr(0, whole.size() - 7)),
            "t.stl: binary STL claims 6 triangles (384 bytes) but the file is 377 bytes: "
            "truncated or not an STL file");
  EXPECT_EQ(error_of(whole.substr(0, 50)),
            "t.stl: binary STL of 50 bytes is shorter than its 84-byte header");
}

TEST(StlFormat, LyingCountIsRefusedBeforeAllocating) {
  // 4 billion triangles claimed by a 384-byte file: refused from the size alone.
  EXPECT_EQ(error_of(binary_stl(pyramid(), "x", 4'000'000'000u)),
            "t.stl: binary STL claims 4000000000 triangles (200000000084 bytes) but the file is "
            "384 bytes: truncated or not an STL file");
  // A count lower than the records: the rest is ignored, as assimp ignored it.
  EXPECT_EQ(parse(binary_stl(pyramid(), "x", 2)).mesh.indices.size(), 6u);
}

TEST(StlFormat, NonFiniteVerticesLeaveTheirTrianglesOut) {
  std::vector<Facet> facets = pyramid();
  facets[2].b.y = std::numeric_limits<float>::quiet_NaN();
  facets[4].c.z = std::numeric_limits<float>::infinity();
  const stl::Geometry binary = parse(binary_stl(facets));
  EXPECT_EQ(binary.non_finite, 2u);
  EXPECT_EQ(binary.mesh.indices.size(), 12u);
  for (const glm::vec3& p : binary.mesh.positions) EXPECT_TRUE(std::isfinite(p.y + p.z));
  const stl::Geometry ascii = parse(ascii_stl(facets));
  EXPECT_EQ(ascii.non_finite, 2u);
  EXPECT_EQ(ascii.mesh.indices, binary.mesh.indices);
  // Through import_scene: one warning, the rest drawn.
  const fs::path dir = fresh_test_dir("facet_stl_", "nan");
  write_file(dir / "nan.stl", binary_stl(facets));
  std::vector<std::string> warnings;
  ImportOptions options;
  options.warn = [&](const std::string& w) { warnings.push_back(w); };
  const Scene scene = import_scene((dir / "nan.stl").string(), options);
  EXPECT_EQ(scene.triangle_count(), 4u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("2 triangles with a vertex that is not finite left out"),
            std::string::npos);
}

TEST(StlFormat, DamagedAsciiIsOneClearErrorWithItsLine) {
  EXPECT_EQ(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                     "endloop\nendfacet\nendsolid\n"),
            "t.stl: facet with 2 vertices, not 3 (line 2)");
  EXPECT_EQ(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 zero 0\n"),
            "t.stl: 'zero' is not a number (line 4)");
  EXPECT_EQ(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
            "t.stl: facet not closed before the end of the file (line 2)");
  EXPECT_EQ(error_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0"),
            "t.stl: a number was expected before the end of the file (line 4)");
  EXPECT_EQ(error_of("solid x\nhello world\n"), "t.stl: unexpected 'hello' (line 2)");
  EXPECT_EQ(error_of("solid x\nvertex 1 2 3\n"), "t.stl: vertex outside a facet (line 2)");
}

TEST(StlFormat, EmptyFilesSayThereIsNothingToDraw) {
  const fs::path dir = fresh_test_dir("facet_stl_", "empty");
  write_file(dir / "empty_ascii.stl", "solid nothing\nendsolid nothing\n");
  write_file(dir / "empty_binary.stl", binary_stl({}));
  for (const char* name : {"empty_ascii.stl", "empty_binary.stl"}) {
    const std::string path = (dir / name).string();
    try {
      import_scene(path);
      ADD_FAILURE() << name << " imported";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), path + ": no triangles to draw");
    }
  }
}

TEST(StlFormat, ProgramReportsADamagedFileInOneLine) {
  const fs::path dir = fresh_test_dir("facet_stl_", "cli");
  const std::string whole = binary_stl(pyramid(), "cut");
  write_file(dir / "cut.stl", whole.substr(0, 200));
  const std::string path = (dir / "cut.stl").string();
  const CommandResult result = run_command("timeout 60 " + std::string(FACET_CLI) + " render '" +
                                           path + "' -o '" + (dir / "o.png").string() + "'");
  EXPECT_EQ(result.exit_code, 2) << result.stderr_text;
  EXPECT_EQ(result.stderr_text, "facet: error: " + path +
                                    ": binary STL claims 6 triangles (384 bytes) but the file "
                                    "is 200 bytes: truncated or not an STL file\n");
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

// --- what assimp read, drawn as assimp's path drew it --------------------------------------

Framebuffer render(const Scene& scene, const Camera& camera, const Lighting& lighting) {
  Renderer renderer;
  Framebuffer target(160, 120);
  renderer.begin_frame(camera, lighting);
  draw_scene(renderer, scene);
  renderer.finish(target);
  return target;
}

TEST(StlFormat, AssimpSamplesDrawAsAssimpsReaderDrewThem) {
  FACET_REQUIRE_PACKAGE(fs::exists(kStlModels), "assimp-testmodels is not installed");
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(kStlModels)) {
    const std::string path = entry.path().string();
    SCOPED_TRACE(path);
    const Scene ours = import_scene(path);
    Scene theirs;
    try {
      theirs = io::import_assimp_scene(path, ImportOptions{});
    } catch (const Error& e) {
      // triangle_with_empty_solid.stl: assimp refuses its empty solid, facet draws the other.
      EXPECT_GT(ours.triangle_count(), 0u);
      continue;
    }
    const Camera camera = scene_camera(ours, 160.0f / 120.0f);
    const Framebuffer a = render(ours, camera, ours.lighting);
    const Framebuffer b = render(theirs, camera, ours.lighting);
    EXPECT_EQ(ours.triangle_count(), theirs.triangle_count());
    std::size_t differing = 0, drawn = 0;
    const std::vector<std::uint8_t>& pa = a.rgba8();
    const std::vector<std::uint8_t>& pb = b.rgba8();
    for (std::size_t i = 0; i < pa.size(); i += 4) {
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(pa[i + c] - pb[i + c]));
      differing += worst > 3;
      drawn += pa[i] != pa[0] || pa[i + 1] != pa[1] || pa[i + 2] != pa[2];
    }
    // Face normals computed by the renderer and the file's normals rounded to 6 digits differ
    // in the last bits; edges may move a pixel where welding changed nothing but the rounding.
    EXPECT_LE(differing, pa.size() / 4 / 200) << differing << " pixels differ";
    EXPECT_GT(drawn, 0u);
    ++compared;
  }
  EXPECT_GE(compared, 8);
}

}  // namespace
}  // namespace facet::test
