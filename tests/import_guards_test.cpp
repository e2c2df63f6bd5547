// The guards around the files an import opens (src/import/guarded_files.cpp, guarded_io.cpp,
// precheck.cpp): a named pipe or directory as a texture, buffer or material library is refused
// at once, saying what it is; references outside the model's folder (symbolic links resolved)
// are refused with one warning unless ImportOptions::allow_outside_paths; a GLB whose chunk
// claims more bytes than the file has fails at once without allocating the claim.
//
// A test here must not hang when a guard is broken: every import runs on a thread watched by
// the test, which after a few seconds opens the test's named pipes read-write, once and
// closed again, so that a reader blocked on one sees a writer come and go and gets end of file.
// The test itself opens nothing that can block.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/import.hpp"
#include "facet/texture.hpp"
#include "support/render_helpers.hpp"
#include "support/text.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr auto kPrompt = std::chrono::seconds(3);

// What one import did: the scene or the error, its warnings, and whether it was prompt.
struct Outcome {
  std::optional<Scene> scene;
  std::string error;
  std::vector<std::string> warnings;
  bool prompt = false;
};

Outcome watched_import(const fs::path& model, const std::vector<fs::path>& pipes,
                       bool allow_outside = false) {
  Outcome out;
  ImportOptions options;
  options.allow_outside_paths = allow_outside;
  options.warn = [&](const std::string& w) { out.warnings.push_back(w); };
  auto done = std::async(std::launch::async, [&] {
    try {
      out.scene = import_scene(model.string(), options);
    } catch (const Error& e) {
      out.error = e.what();
    }
  });
  out.prompt = done.wait_for(kPrompt) == std::future_status::ready;
  // Unblock a reader stuck on a pipe: a writer that comes and goes gives it end of file.
  while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
    for (const fs::path& pipe : pipes) {
      const int fd = ::open(pipe.c_str(), O_RDWR | O_NONBLOCK);
      if (fd >= 0) ::close(fd);
    }
  }
  done.get();
  return out;
}

fs::path make_pipe(const fs::path& path) {
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

// A 2x2 binary PPM, which the texture loader reads whatever the file is called.
void write_image(const fs::path& path) {
  std::ofstream(path, std::ios::binary) << "P6\n2 2\n255\n" << std::string(12, '\x80');
}

// One textured triangle; `texture` is the map_Kd path, `mtl` the mtllib name.
fs::path write_obj(const fs::path& dir, const std::string& texture,
                   const std::string& mtl = "tri.mtl") {
  if (mtl == "tri.mtl")
    std::ofstream(dir / mtl) << "newmtl m\nKd 1 1 1\nmap_Kd " << texture << "\n";
  std::ofstream(dir / "tri.obj") << "mtllib " << mtl << "\nusemtl m\n"
                                 << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                 << "f 1/1 2/2 3/3\n";
  return dir / "tri.obj";
}

// One triangle whose positions are in the buffer file `uri` (36 bytes).
fs::path write_gltf(const fs::path& dir, const std::string& uri) {
  std::ofstream(dir / "tri.gltf")
      << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
      << R"("buffers":[{"uri":")" << uri << R"(","byteLength":36}],)"
      << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36}],)"
      << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
      << R"("min":[0,0,0],"max":[1,1,0]}]})";
  return dir / "tri.gltf";
}

void write_buffer(const fs::path& path) {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(positions), sizeof positions);
}

std::shared_ptr<const Texture> base_color_texture(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (m.base_color_map.texture) return m.base_color_map.texture;
  return nullptr;
}

// --- special files -------------------------------------------------------------------------

TEST(ImportGuards, PipeAsTextureIsRefusedPromptlyAndDrawsTheChecker) {
  const fs::path dir = fresh_test_dir("facet_import_guards_", "pipe_texture");
  const fs::path pipe = make_pipe(dir / "wood.ppm");
  Outcome r = watched_import(write_obj(dir, "wood.ppm"), {pipe});
  EXPECT_TRUE(r.prompt);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "wood.ppm is a named pipe")) << r.warnings[0];
  EXPECT_EQ(base_color_texture(*r.scene), missing_texture());
}

TEST(ImportGuards, PipeAsBufferFailsPromptlySayingWhatItIs) {
  const fs::path dir = fresh_test_dir("facet_import_guards_", "pipe_buffer");
  const fs::path pipe = make_pipe(dir / "tri.bin");
  Outcome r = watched_import(write_gltf(dir, "tri.bin"), {pipe});
  EXPECT_TRUE(r.prompt);
  EXPECT_FALSE(r.scene);
  EXPECT_TRUE(contains(r.error, "tri.bin is a named pipe")) << r.error;
}

TEST(ImportGuards, PipeAsMaterialLibraryIsRefusedPromptly) {
  const fs::path dir = fresh_test_dir("facet_import_guards_", "pipe_mtl");
  const fs::path pipe = make_pipe(dir / "lib.mtl");
  Outcome r = watched_import(write_obj(dir, "", "lib.mtl"), {pipe});
  EXPECT_TRUE(r.prompt);
  ASSERT_TRUE(r.scene) << r.error;  // the geometry does not need its materials
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "lib.mtl is a named pipe")) << r.warnings[0];
}

TEST(ImportGuards, DirectoryAsBufferFailsSayingWhatItIs) {
  const fs::path dir = fresh_test_dir("facet_import_guards_", "directory_buffer");
  fs::create_directory(dir / "tri.bin");
  Outcome r = watched_import(write_gltf(dir, "tri.bin"), {});
  EXPECT_FALSE(r.scene);
  EXPECT_TRUE(contains(r.error, "tri.bin is a directory")) << r.error;
}

// --- paths outside the model's folder ------------------------------------------------------

struct OutsideLayout {
  fs::path model_dir, outside_image;
};

OutsideLayout outside_layout(const std::string& name) {
  const fs::path root = fresh_test_dir("facet_import_guards_", name);
  fs::create_directories(root / "model");
  fs::create_directories(root / "elsewhere");
  write_image(root / "elsewhere" / "secret.ppm");
  return {root / "model", root / "elsewhere" / "secret.ppm"};
}

TEST(ImportGuards, RelativeTexturePathOutsideIsRefusedWithOneWarning) {
  const OutsideLayout l = outside_layout("outside_relative");
  const fs::path model = write_obj(l.model_dir, "../elsewhere/secret.ppm");
  Outcome r = watched_import(model, {});
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0],
                       "texture ../elsewhere/secret.ppm is outside the model's "
                       "folder"))
      << r.warnings[0];
  EXPECT_TRUE(contains(r.warnings[0], "--allow-outside-paths")) << r.warnings[0];
  EXPECT_EQ(base_color_texture(*r.scene), missing_texture());

  Outcome allowed = watched_import(model, {}, true);
  ASSERT_TRUE(allowed.scene) << allowed.error;
  EXPECT_TRUE(allowed.warnings.empty()) << allowed.warnings[0];
  ASSERT_TRUE(base_color_texture(*allowed.scene));
  EXPECT_NE(base_color_texture(*allowed.scene), missing_texture());
}

TEST(ImportGuards, AbsoluteTexturePathOutsideIsRefused) {
  const OutsideLayout l = outside_layout("outside_absolute");
  Outcome r = watched_import(write_obj(l.model_dir, fs::absolute(l.outside_image).string()), {});
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "is outside the model's folder")) << r.warnings[0];
  EXPECT_EQ(base_color_texture(*r.scene), missing_texture());
}

TEST(ImportGuards, SymlinkFromInsideToOutsideIsRefused) {
  const OutsideLayout l = outside_layout("outside_symlink");
  fs::create_symlink(fs::absolute(l.outside_image), l.model_dir / "wood.ppm");
  write_image(l.model_dir / "real.ppm");
  fs::create_symlink("real.ppm", l.model_dir / "inside_link.ppm");  // stays inside: fine
  Outcome r = watched_import(write_obj(l.model_dir, "wood.ppm"), {});
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "wood.ppm is outside the model's folder")) << r.warnings[0];
  EXPECT_TRUE(contains(r.warnings[0], "secret.ppm")) << r.warnings[0];  // where it leads
  EXPECT_EQ(base_color_texture(*r.scene), missing_texture());

  Outcome inside = watched_import(write_obj(l.model_dir, "inside_link.ppm"), {});
  ASSERT_TRUE(inside.scene) << inside.error;
  EXPECT_TRUE(inside.warnings.empty()) << inside.warnings[0];
  EXPECT_NE(base_color_texture(*inside.scene), missing_texture());
}

TEST(ImportGuards, BufferOutsideFailsUnlessAllowed) {
  const OutsideLayout l = outside_layout("outside_buffer");
  write_buffer(l.model_dir.parent_path() / "elsewhere" / "tri.bin");
  const fs::path model = write_gltf(l.model_dir, "../elsewhere/tri.bin");
  Outcome r = watched_import(model, {});
  EXPECT_FALSE(r.scene);
  EXPECT_TRUE(contains(r.error, "tri.bin is outside the model's folder")) << r.error;

  Outcome allowed = watched_import(model, {}, true);
  ASSERT_TRUE(allowed.scene) << allowed.error;
  EXPECT_EQ(allowed.scene->triangle_count(), 1u);
}

TEST(ImportGuards, BufferInsideImports) {
  const fs::path dir = fresh_test_dir("facet_import_guards_", "inside_buffer");
  write_buffer(dir / "tri.bin");
  Outcome r = watched_import(write_gltf(dir, "tri.bin"), {});
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
  EXPECT_EQ(r.scene->triangle_count(), 1u);
}

// --- sizes that lie --------------------------------------------------------------------------

long peak_resident_kib() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

void put_u32(std::string& bytes, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>((value >> (8 * i)) & 0xFF);
}

// A GLB of `json`, its header's total length `length` (0: the true one) and its JSON chunk's
// claimed length `claimed` (0: the true one).
fs::path write_glb(const fs::path& path, std::uint32_t length, std::uint32_t claimed) {
  std::string json = R"({"asset":{"version":"2.0"}})";
  while (json.size() % 4) json += ' ';
  std::string bytes = "glTF";
  put_u32(bytes, 2);
  put_u32(bytes, length ? length : static_cast<std::uint32_t>(12 + 8 + json.size()));
  put_u32(bytes, claimed ? claimed : static_cast<std::uint32_t>(json.size()));
  bytes += "JSON";
  bytes += json;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(ImportGuards, GlbChunkClaimingFourGibibytesFailsAtOnce) {
  const fs::path dir = fresh_test_dir("facet_import_guards_", "glb_chunk");
  const fs::path model = write_glb(dir / "liar.glb", 0, 0xFFFFFFF0u);
  const long peak_before = peak_resident_kib();
  const auto start = Clock::now();
  Outcome r = watched_import(model, {});
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  EXPECT_FALSE(r.scene);
  EXPECT_TRUE(contains(r.error, "GLB chunk 0 (JSON) claims 4294967280 bytes")) << r.error;
  EXPECT_LT(seconds, 5.0);  // reading the 4 GiB first takes tens of seconds
  EXPECT_LT(peak_resident_kib() - peak_before, 256 * 1024) << "KiB more at peak";
}

TEST(ImportGuards, GlbHeaderClaimingMoreThanTheFileFailsAtOnce) {
  const fs::path dir = fresh_test_dir("facet_import_guards_", "glb_header");
  // Also named .bin: binary glTF is known by its magic, not its name.
  for (const char* name : {"liar.glb", "liar.bin"}) {
    Outcome r = watched_import(write_glb(dir / name, 1u << 30, 0), {});
    EXPECT_FALSE(r.scene);
    EXPECT_TRUE(contains(r.error, "GLB header claims a length of 1073741824 bytes")) << r.error;
  }
}

}  // namespace
}  // namespace facet::test
