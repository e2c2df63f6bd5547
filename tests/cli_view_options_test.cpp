// `facet render`'s view options through the real binary: automatic framing at the image's
// aspect, --up AXIS, --azimuth and --elevation, --background none (a transparent PNG),
// --debug-view, and orthographic cameras from files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/cli_content_inputs.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

const std::string kEngine =
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// `facet render <args> -o out.png` in a fresh directory; expects success and nothing on stderr.
Rgba8Image render(const std::string& name, const std::string& args) {
  fs::path dir = fresh_test_dir("facet_cli_view_", name);
  CommandResult r = run_facet(dir, "render " + args + " -o out.png");
  EXPECT_EQ(r.exit_code, 0) << "facet render " << args << "\n" << r.stderr_text;
  EXPECT_EQ(r.stderr_text, "") << "facet render " << args;
  try {
    return read_png((dir / "out.png").string());
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
    return {};
  }
}

std::uint8_t channel(const Rgba8Image& image, int x, int y, int c) {
  return image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4 + c];
}

// The box around the pixels with alpha above 0: {x0, y0, x1, y1}, inclusive.
struct Box {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
};
Box opaque_box(const Rgba8Image& image) {
  Box box;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (channel(image, x, y, 3) == 0) continue;
      box.x0 = std::min(box.x0, x), box.y0 = std::min(box.y0, y);
      box.x1 = std::max(box.x1, x), box.y1 = std::max(box.y1, y);
    }
  }
  return box;
}

// Drawn pixels on the outermost ring of a --background none image.
int border_pixels_drawn(const Rgba8Image& image) {
  int drawn = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const bool border = x == 0 || y == 0 || x == image.width - 1 || y == image.height - 1;
      if (border && channel(image, x, y, 3) != 0) ++drawn;
    }
  }
  return drawn;
}

int differing_pixels(const Rgba8Image& a, const Rgba8Image& b) {
  int different = 0;
  for (std::size_t i = 0; i + 3 < a.pixels.size() && i + 3 < b.pixels.size(); i += 4) {
    different += !std::equal(&a.pixels[i], &a.pixels[i] + 4, &b.pixels[i]);
  }
  return different;
}

// The commands of the report: the bunny at 300x600 lost half of itself, at 256x256 its ears;
// the engine at 800x600 both ends.
TEST(CliFraming, ModelsFitImagesOfEveryAspect) {
  REQUIRE_INSTALLED(kBunny);
  REQUIRE_INSTALLED(kEngine);
  for (const char* size : {"300x600", "256x256", "800x600"}) {
    Rgba8Image bunny =
        render(std::string("bunny") + size, kBunny + " --background none --size " + size);
    EXPECT_EQ(border_pixels_drawn(bunny), 0) << "bunny at " << size;
    EXPECT_GT(opaque_box(bunny).width(), bunny.width / 2) << "bunny at " << size;
  }
  Rgba8Image engine = render("engine", kEngine + " --background none --size 800x600");
  EXPECT_EQ(border_pixels_drawn(engine), 0);
}

// A column along Z, as a Z-up file stores a standing thing.
std::string z_up_column(const fs::path& dir) {
  const fs::path file = dir / "column.obj";
  std::ofstream obj(file);
  for (int i = 0; i < 8; ++i) {
    obj << "v " << (i & 1 ? 0.2 : -0.2) << " " << (i & 2 ? 0.2 : -0.2) << " " << (i & 4 ? 3 : 0)
        << "\n";
  }
  obj << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return file.string();
}

TEST(CliFraming, UpAxisStandsAZUpModelUpright) {
  const std::string column = z_up_column(fresh_test_dir("facet_cli_view_", "column_input"));
  Box lying = opaque_box(render("column_default", column + " --background none --size 200x200"));
  Box standing =
      opaque_box(render("column_up_z", column + " --background none --size 200x200 --up +Z"));
  EXPECT_GT(lying.width(), lying.height());
  EXPECT_GT(standing.height(), 3 * standing.width());
  // The sign matters: -Z stands it on its head, as tall.
  Box head =
      opaque_box(render("column_up_minus_z", column + " --background none --size 200x200 --up -z"));
  EXPECT_GT(head.height(), 3 * head.width());
}

TEST(CliFraming, AzimuthAndElevationTurnTheAutomaticView) {
  REQUIRE_INSTALLED(kBunny);
  const std::string args = kBunny + " --size 96x96";
  Rgba8Image front = render("front", args);
  Rgba8Image back = render("back", args + " --azimuth 180");
  Rgba8Image top = render("top", args + " --elevation 90 --background none");
  Rgba8Image top_parallel = render("top_ortho", args + " --elevation 90 --orthographic --up +Y");
  EXPECT_GT(differing_pixels(front, back), 96 * 96 / 10);
  EXPECT_GT(differing_pixels(front, top_parallel), 96 * 96 / 10);
  EXPECT_EQ(border_pixels_drawn(top), 0);
  EXPECT_GT(opaque_box(top).width(), 48);
}

TEST(CliFraming, ViewOptionsOutOfRangeOrWithAPlacedCameraAreUsageErrors) {
  REQUIRE_INSTALLED(kBunny);
  const fs::path dir = fresh_test_dir("facet_cli_view_", "errors");
  for (const std::string& args :
       {std::string(" --elevation 95"), std::string(" --azimuth 30 --eye 1,2,3"),
        std::string(" --elevation 10 --camera 0"), std::string(" --up +W"),
        std::string(" --debug-view heat"), std::string(" --background none -o out.ppm")}) {
    CommandResult r = run_facet(dir, "render " + kBunny + " --size 32x32 -o out.png" + args);
    EXPECT_EQ(r.exit_code, kUsageError) << args;
    EXPECT_EQ(lines_of(r.stderr_text).size(), 1u) << args << ": " << r.stderr_text;
  }
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{});
}

// The viewer's controls turn about +Y: another up axis is refused before a window opens.
TEST(CliFraming, TheViewerTakesOnlyPlusYUp) {
  REQUIRE_INSTALLED(kBunny);
  const fs::path dir = fresh_test_dir("facet_cli_view_", "view_up");
  CommandResult r = run_facet(dir, "view " + kBunny + " --up +Z");
  EXPECT_EQ(r.exit_code, kUsageError);
  EXPECT_EQ(r.stderr_text,
            "facet: error: --up +Z: the viewer's controls keep +Y up; other model axes are for "
            "facet render\n");
}

TEST(CliBackground, NoneGivesAlphaZeroAroundAnOpaqueModel) {
  REQUIRE_INSTALLED(kBunny);
  // One sample a pixel: every pixel is the model's or the background's (with anti-aliasing the
  // silhouette's pixels are partly both, alpha between 0 and 255).
  Rgba8Image opaque = render("opaque", kBunny + " --size 120x90 --msaa 1");
  Rgba8Image clear = render("clear", kBunny + " --size 120x90 --background none --msaa 1");
  ASSERT_EQ(clear.pixels.size(), opaque.pixels.size());
  EXPECT_EQ(channel(clear, 0, 0, 3), 0);
  EXPECT_EQ(channel(clear, 119, 89, 3), 0);
  EXPECT_EQ(channel(opaque, 0, 0, 3), 255);
  EXPECT_EQ(channel(clear, 60, 45, 3), 255);
  // The model's pixels are as on an opaque background; only the background changed.
  int model = 0;
  for (std::size_t i = 0; i < clear.pixels.size(); i += 4) {
    if (clear.pixels[i + 3] == 0) continue;
    ++model;
    EXPECT_EQ(clear.pixels[i + 3], 255);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(clear.pixels[i + c], opaque.pixels[i + c]) << i / 4;
  }
  EXPECT_GT(model, 120 * 90 / 10);
}

// A half-transparent square over nothing: alpha 128 and the material's own color (straight
// alpha), not the color darkened by the coverage (premultiplied) that it is over black.
TEST(CliBackground, NoneWritesStraightAlphaForBlendedMaterials) {
  const fs::path input = fresh_test_dir("facet_cli_view_", "half_input");
  std::ofstream(input / "half.mtl") << "newmtl half\nKd 1 0.5 0\nd 0.5\n";
  std::ofstream(input / "half.obj") << "mtllib half.mtl\nusemtl half\n"
                                       "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
  const std::string args = (input / "half.obj").string() + " --size 64x64 --shading unlit";
  Rgba8Image clear = render("half_clear", args + " --background none");
  Rgba8Image black = render("half_black", args + " --background 0,0,0");
  EXPECT_NEAR(channel(clear, 32, 32, 3), 128, 1);
  EXPECT_EQ(channel(clear, 32, 32, 0), 255);       // linear 1 -> sRGB 255
  EXPECT_NEAR(channel(clear, 32, 32, 1), 188, 1);  // linear 0.5 -> sRGB 188
  EXPECT_EQ(channel(clear, 32, 32, 2), 0);
  EXPECT_NEAR(channel(black, 32, 32, 0), 188, 1);  // over black: half of it
  EXPECT_EQ(channel(black, 32, 32, 3), 255);
  EXPECT_EQ(channel(clear, 0, 0, 3), 0);
}

TEST(CliDebugView, OverdrawAndTileBinsReplaceTheShadedImage) {
  REQUIRE_INSTALLED(kBunny);
  const std::string args = kBunny + " --size 160x120";
  Rgba8Image shaded = render("shaded", args);
  Rgba8Image overdraw = render("overdraw", args + " --debug-view overdraw");
  Rgba8Image bins = render("tile_bins", args + " --debug-view tile_bins");
  // Overdraw counts triangles: black where none covered the pixel, colored over the bunny.
  for (int c = 0; c < 3; ++c) EXPECT_EQ(channel(overdraw, 0, 0, c), 0);
  EXPECT_GT(
      channel(overdraw, 80, 60, 0) + channel(overdraw, 80, 60, 1) + channel(overdraw, 80, 60, 2),
      0);
  EXPECT_GT(differing_pixels(shaded, overdraw), 160 * 120 / 2);
  // Tile bins tint and outline the shaded image: different, but not everywhere.
  const int tinted = differing_pixels(shaded, bins);
  EXPECT_GT(tinted, 160 * 120 / 20);
}

// Cameras.gltf's camera 1 is orthographic (xmag = ymag = 1): it renders, parallel.
TEST(CliCameras, OrthographicCameraFromTheFile) {
  REQUIRE_INSTALLED(kCamerasGltf);
  Rgba8Image perspective = render("camera0", kCamerasGltf + " --camera 0 --size 64x64");
  Rgba8Image parallel = render("camera1", kCamerasGltf + " --camera 1 --size 64x64");
  EXPECT_GT(differing_pixels(perspective, parallel), 64);
}

}  // namespace
}  // namespace facet::test
