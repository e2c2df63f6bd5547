// The program's modules (apps/facet/modules.hpp), in a build with shared libraries: the program
// starts without the desktop's libraries (SDL2, OpenAL, EGL, OpenGL), and a program whose
// modules are missing, as on a server given the program alone, still renders; `facet view` and
// `--backend gl` then say which module is missing, in one line, exit code 2, writing nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

constexpr int kUsageError = 2;

TEST(ProgramModules, TheProgramStartsWithoutTheDesktopsLibraries) {
  // What the dynamic loader loads at start (ldd asks it the same way). Built by appending: GCC
  // 12 warns (-Warray-bounds, a false positive) about a literal + a literal's string.
  std::string command = "LD_TRACE_LOADED_OBJECTS=1 ";
  command += FACET_CLI;
  const CommandResult r = run_command(command);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  ASSERT_NE(r.stdout_text.find("libfacet.so"), std::string::npos) << r.stdout_text;
  for (const char* library : {"libSDL2", "libopenal", "libEGL", "libOpenGL", "libfacet-sound"}) {
    EXPECT_EQ(r.stdout_text.find(library), std::string::npos) << library << " in\n"
                                                              << r.stdout_text;
  }
}

TEST(ProgramModules, WithoutThemTheProgramRendersAndSaysWhichIsMissing) {
  // The program alone in a folder of its own: no module beside it, none in ../lib*/facet.
  const fs::path dir = fs::path(::testing::TempDir()) / ("facet_alone_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "bin");
  const fs::path program = dir / "bin" / "facet";
  fs::copy_file(FACET_CLI, program);
  const std::string run = program.string() + " ";

  const CommandResult render =
      run_command(run + "render --scene shapes --size 32x18 -o " + (dir / "facet.png").string());
  EXPECT_EQ(render.exit_code, 0) << render.stderr_text;
  EXPECT_TRUE(fs::exists(dir / "facet.png"));

  // Bad flags are told first, as where the module is.
  const CommandResult bad_flag = run_command(run + "view --msaa 3");
  EXPECT_EQ(bad_flag.exit_code, kUsageError);
  EXPECT_NE(bad_flag.stderr_text.find("--msaa"), std::string::npos) << bad_flag.stderr_text;
  EXPECT_EQ(bad_flag.stderr_text.find("module"), std::string::npos) << bad_flag.stderr_text;

  const CommandResult view = run_command(run + "view --frames 1");
  EXPECT_EQ(view.exit_code, kUsageError);
  EXPECT_EQ(view.stderr_text.rfind("facet: error: facet view needs the module facet-view.so, "
                                   "which is not installed (not in " +
                                       (dir / "bin").string(),
                                   0),
            0u)
      << view.stderr_text;
  EXPECT_EQ(view.stderr_text.find('\n'), view.stderr_text.size() - 1) << view.stderr_text;

#if FACET_HAS_GL
  const fs::path gl_image = dir / "gl.png";
  const CommandResult gl =
      run_command(run + "render --scene shapes --size 32x18 --backend gl -o " + gl_image.string());
  EXPECT_EQ(gl.exit_code, kUsageError);
  EXPECT_NE(gl.stderr_text.find("--backend gl needs the module facet-gl.so, which is not "
                                "installed"),
            std::string::npos)
      << gl.stderr_text;
  EXPECT_FALSE(fs::exists(gl_image));
#endif
  fs::remove_all(dir);
}

}  // namespace
}  // namespace facet::test
