// `facet info MODEL`: prints what a model holds, aligned; errors are one line and exit code 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kUsageError = 2;

// Built by appending: GCC 12 warns (-Wrestrict, a false positive) about "'" + path + "'".
std::string quoted(const std::string& path) {
  std::string out = "'";
  out += path;
  out += "'";
  return out;
}

CommandResult run_info(const std::string& args) {
  return run_command(std::string(FACET_CLI) + " info " + args);
}

// The value printed after a label such as "triangles", or "" if the label is missing.
std::string value_of(const std::string& output, const std::string& label) {
  std::size_t at = output.find("\n" + label + " ");
  if (output.rfind(label + " ", 0) == 0)
    at = 0;
  else if (at == std::string::npos)
    return "";
  else
    ++at;
  std::size_t start = output.find_first_not_of(' ', at + label.size());
  return output.substr(start, output.find('\n', start) - start);
}

TEST(CliInfo, DescribesAGltfModel) {
  const fs::path model = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  FACET_REQUIRE_PACKAGE(fs::exists(model), "assimp-testmodels is not installed");
  CommandResult r = run_info(quoted(model.string()));
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stderr_text, "");
  const std::string& out = r.stdout_text;
  EXPECT_EQ(value_of(out, "file"), model.string());
  EXPECT_EQ(value_of(out, "meshes"), "1");
  EXPECT_EQ(value_of(out, "triangles").rfind("12", 0), 0u) << out;
  EXPECT_EQ(value_of(out, "vertices"), "24");
  EXPECT_EQ(value_of(out, "bounds"), "min (-0.5, -0.5, -0.5)  max (0.5, 0.5, 0.5)  size (1, 1, 1)");
  EXPECT_EQ(value_of(out, "materials"), "1");  // the file's one (no unused default added)
  EXPECT_NE(out.find("pbr"), std::string::npos);
  EXPECT_NE(out.find("base_color embedded:0"), std::string::npos) << out;
  EXPECT_EQ(value_of(out, "textures"), "1");
  EXPECT_NE(out.find("mip levels, sRGB"), std::string::npos);
  EXPECT_NE(value_of(out, "lights"), "");
  EXPECT_NE(value_of(out, "cameras"), "");
  EXPECT_NE(value_of(out, "nodes"), "");
  // Every value starts in the same column.
  for (const char* label : {"file", "meshes", "triangles", "vertices", "bounds", "textures"}) {
    std::size_t line = out.find(std::string(label) + " ");
    ASSERT_NE(line, std::string::npos) << label;
    EXPECT_EQ(out.find_first_not_of(' ', line + std::string(label).size()) - line, 12u) << label;
  }
}

TEST(CliInfo, DescribesADFile) {
  fs::path file = fs::path(::testing::TempDir()) / "facet_info_square.d";
  std::ofstream(file) << "data 4 1\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 1 2 3 4\n";
  CommandResult r = run_info(quoted(file.string()));
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(value_of(r.stdout_text, "triangles").rfind("2 ", 0), 0u) << r.stdout_text;
  EXPECT_NE(r.stdout_text.find("blinn_phong"), std::string::npos);
}

TEST(CliInfo, ErrorsAreOneLineWithExitCode2) {
  CommandResult missing = run_info("/nonexistent/model.obj");
  EXPECT_EQ(missing.exit_code, kUsageError);
  EXPECT_EQ(missing.stdout_text, "");
  EXPECT_EQ(missing.stderr_text, "facet: error: /nonexistent/model.obj: no such file\n");

  fs::path bad = fs::path(::testing::TempDir()) / "facet_info_bad.d";
  std::ofstream(bad) << "data 3 1\n0 0 0\n1 0 0\n0 1 0\n3 1 2 7\n";
  CommandResult out_of_range = run_info(quoted(bad.string()));
  EXPECT_EQ(out_of_range.exit_code, kUsageError);
  EXPECT_EQ(out_of_range.stderr_text,
            "facet: error: " + bad.string() + ":5: polygon index 7 is out of range (1..3)\n");

  CommandResult no_model = run_command(std::string(FACET_CLI) + " info");
  EXPECT_EQ(no_model.exit_code, kUsageError);
}

// A texture outside the model's folder: one warning naming the path and the rule, the model
// still described; --allow-outside-paths reads it without a word.
TEST(CliInfo, TextureOutsideTheModelsFolderWarnsUnlessAllowed) {
  const fs::path root = fresh_test_dir("facet_info_", "outside");
  fs::create_directories(root / "model");
  fs::create_directories(root / "elsewhere");
  std::ofstream(root / "elsewhere" / "secret.ppm", std::ios::binary) << "P6\n1 1\n255\n"
                                                                     << std::string(3, '\x80');
  std::ofstream(root / "model" / "tri.mtl") << "newmtl m\nmap_Kd ../elsewhere/secret.ppm\n";
  const fs::path model = root / "model" / "tri.obj";
  std::ofstream(model) << "mtllib tri.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                          "f 1/1 2/1 3/1\n";
  CommandResult refused = run_info(quoted(model.string()));
  ASSERT_EQ(refused.exit_code, 0) << refused.stderr_text;
  EXPECT_EQ(refused.stderr_text.rfind("facet: warning: " + model.string() +
                                          ": texture ../elsewhere/secret.ppm is outside the "
                                          "model's folder",
                                      0),
            0u)
      << refused.stderr_text;
  EXPECT_EQ(std::count(refused.stderr_text.begin(), refused.stderr_text.end(), '\n'), 1);

  CommandResult allowed = run_info("--allow-outside-paths " + quoted(model.string()));
  ASSERT_EQ(allowed.exit_code, 0) << allowed.stderr_text;
  EXPECT_EQ(allowed.stderr_text, "");
}

}  // namespace
}  // namespace facet::test
