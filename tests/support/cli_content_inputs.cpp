// Inputs and runner for the `facet render MODEL` tests (see cli_content_inputs.hpp).
#include "support/cli_content_inputs.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"

namespace facet::test {

namespace fs = std::filesystem;

namespace {

// --- inputs written at test time ----------------------------------------------------------

// A UV sphere of radius 1 in the course's .d format (quads in the middle, triangles at the
// poles), with a header, a comment and a blank line.
std::string ball_d() {
  constexpr int kRings = 12, kSegments = 24;
  std::ostringstream vertices, polygons;
  int vertex_count = 0, polygon_count = 0;
  auto vertex = [&](double x, double y, double z) {
    vertices << x << ' ' << y << ' ' << z << '\n';
    ++vertex_count;
  };
  vertex(0, 1, 0);
  for (int i = 1; i < kRings; ++i) {
    double theta = std::numbers::pi * i / kRings;
    for (int j = 0; j < kSegments; ++j) {
      double phi = 2 * std::numbers::pi * j / kSegments;
      vertex(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
    }
  }
  vertex(0, -1, 0);
  auto at = [&](int ring, int segment) { return 2 + (ring - 1) * kSegments + segment % kSegments; };
  for (int j = 0; j < kSegments; ++j, ++polygon_count)
    polygons << "3 1 " << at(1, j) << ' ' << at(1, j + 1) << '\n';
  for (int i = 1; i + 1 < kRings; ++i) {
    for (int j = 0; j < kSegments; ++j, ++polygon_count) {
      polygons << "4 " << at(i, j) << ' ' << at(i + 1, j) << ' ' << at(i + 1, j + 1) << ' '
               << at(i, j + 1) << '\n';
    }
  }
  for (int j = 0; j < kSegments; ++j, ++polygon_count)
    polygons << "3 " << at(kRings - 1, j) << ' ' << vertex_count << ' ' << at(kRings - 1, j + 1)
             << '\n';
  return "data " + std::to_string(vertex_count) + " " + std::to_string(polygon_count) +
         "\n# a ball\n" + vertices.str() + "\n" + polygons.str();
}

// A cube whose faces use three materials from an MTL file.
const char* const kCubeObj =
    "mtllib cube.mtl\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl red\nf 5/1 6/2 7/3 8/4\nf 2/1 1/2 4/3 3/4\n"
    "usemtl green\nf 6/1 2/2 3/3 7/4\nf 1/1 5/2 8/3 4/4\n"
    "usemtl blue\nf 8/1 7/2 3/3 4/4\nf 1/1 2/2 6/3 5/4\n";
const char* const kCubeMtl =
    "newmtl red\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 32\n"
    "newmtl green\nKd 0.1 0.8 0.1\n"
    "newmtl blue\nKd 0.1 0.1 0.8\n";

// A texture: an 8x4 checker of two colors with a gradient, so every projection shows.
void write_texture(const fs::path& path) {
  Framebuffer image(64, 32);
  std::vector<std::uint8_t>& px = image.rgba8();
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 64; ++x) {
      std::uint8_t* p = &px[(static_cast<std::size_t>(y) * 64 + x) * 4];
      bool odd = (x / 8 + y / 8) % 2 != 0;
      p[0] = odd ? 240 : 30;
      p[1] = static_cast<std::uint8_t>(x * 4);
      p[2] = odd ? 40 : 220;
      p[3] = 255;
    }
  }
  write_image(image, path.string());
}

// Every input file, written once per process into its own directory: ctest runs each test as
// a process, two at a time, so a shared directory would be rewritten under a running test.
struct Inputs {
  fs::path dir =
      fs::path(::testing::TempDir()) / ("facet_cli_content_inputs_" + std::to_string(::getpid()));
  Inputs() {
    fs::remove_all(dir);
    fs::create_directories(dir / "a_directory.obj");
    std::ofstream(dir / "ball.d") << ball_d();
    std::ofstream(dir / "cube.obj") << kCubeObj;
    std::ofstream(dir / "cube.mtl") << kCubeMtl;
    // Two materials share one texture that is not there.
    std::string obj = kCubeObj;
    obj.replace(obj.find("cube.mtl"), 8, "lost.mtl");
    std::ofstream(dir / "lost_texture.obj") << obj;
    std::ofstream(dir / "lost.mtl") << "newmtl red\nKd 1 1 1\nmap_Kd nowhere.png\n"
                                       "newmtl green\nKd 1 1 1\nmap_Kd nowhere.png\n"
                                       "newmtl blue\nKd 0.2 0.2 0.8\n";
    // A floor 8 wide running 40 units into the distance, for fog.
    std::ofstream(dir / "floor.d") << "data 4 1\n-4 0 0\n4 0 0\n4 0 -40\n-4 0 -40\n4 1 2 3 4\n";
    std::ofstream(dir / "index_out_of_range.d") << "data 3 1\n0 0 0\n1 0 0\n0 1 0\n3 1 2 7\n";
    std::ofstream(dir / "empty.glb");
    std::ofstream(dir / "not_an_image.png") << "this is not a PNG";
    std::mt19937 random(1234);
    std::string noise(4096, '\0');
    for (char& c : noise) c = static_cast<char>(random() & 0xff);
    std::ofstream(dir / "noise.obj", std::ios::binary) << noise;
    std::ofstream(dir / "noise.glb", std::ios::binary) << noise;
    write_texture(dir / "texture.png");
  }
  ~Inputs() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
};

}  // namespace

const fs::path& cli_inputs() {
  static const Inputs written;
  return written.dir;
}

std::string input(const std::string& name) { return (cli_inputs() / name).string(); }

// --- running facet ------------------------------------------------------------------------

std::vector<std::string> list_dir(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

CommandResult run_facet(const fs::path& dir, const std::string& args) {
  return run_command("cd '" + dir.string() + "' && " + FACET_CLI + " " + args);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace facet::test
