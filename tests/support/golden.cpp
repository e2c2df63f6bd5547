// Golden-image comparison (see golden.hpp).
#include "support/golden.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

struct Comparison {
  long outliers = 0;  // pixels with a channel beyond the tolerance
  int max_delta = 0;  // largest channel difference anywhere
  Rgba8Image diff;    // outliers red, small differences yellow, the rest the golden dimmed
};

Comparison compare(const Rgba8Image& actual, const Rgba8Image& golden, Tolerance tolerance) {
  Comparison c;
  c.diff = golden;
  for (std::size_t i = 0; i < golden.pixels.size(); i += 4) {
    int delta = 0;
    for (int ch = 0; ch < 4; ++ch) {
      delta = std::max(delta, std::abs(int(actual.pixels[i + ch]) - int(golden.pixels[i + ch])));
    }
    c.max_delta = std::max(c.max_delta, delta);
    std::uint8_t* d = &c.diff.pixels[i];
    if (delta > tolerance.max_channel_delta) {
      ++c.outliers;
      d[0] = 255, d[1] = 0, d[2] = 0;
    } else if (delta > 0) {
      d[0] = 255, d[1] = 255, d[2] = 0;
    } else {
      int grey = (d[0] + d[1] + d[2]) / 12;
      d[0] = d[1] = d[2] = static_cast<std::uint8_t>(grey);
    }
    d[3] = 255;
  }
  return c;
}

bool write_png(const Rgba8Image& image, const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGBA;
  return png_image_write_to_file(&png, path.c_str(), 0, image.pixels.data(), 0, nullptr) != 0;
}

bool updating_goldens() {
  const char* value = std::getenv("FACET_UPDATE_GOLDENS");
  return value && std::string(value) == "1";
}

}  // namespace

void expect_matches_golden(const std::string& rendered_path, const std::string& golden_name,
                           Tolerance tolerance) {
  expect_matches_golden_in(FACET_GOLDEN_DIR, rendered_path, golden_name, tolerance);
}

void expect_matches_golden_in(const std::string& golden_dir, const std::string& rendered_path,
                              const std::string& golden_name, Tolerance tolerance) {
  const fs::path output = rendered_path;
  const fs::path golden_path = fs::path(golden_dir) / (golden_name + ".png");
  const std::string model = golden_name;

  if (updating_goldens()) {
    fs::copy_file(output, golden_path, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "FACET_UPDATE_GOLDENS=1: wrote " << golden_path.string()
                 << " (look at it before committing)";
  }

  ASSERT_TRUE(fs::exists(golden_path))
      << golden_path.string() << " is missing; create it with FACET_UPDATE_GOLDENS=1";
  Rgba8Image actual = read_png(output.string());
  Rgba8Image golden = read_png(golden_path.string());
  ASSERT_EQ(actual.width, golden.width) << output.string();
  ASSERT_EQ(actual.height, golden.height) << output.string();

  Comparison c = compare(actual, golden, tolerance);
  const long allowed =
      static_cast<long>(tolerance.max_outlier_fraction * golden.width * golden.height);
  if (c.outliers > allowed) {
    const fs::path diff_path = fs::path(::testing::TempDir()) / (model + ".diff.png");
    bool wrote = write_png(c.diff, diff_path.string());
    ADD_FAILURE() << model << ": " << c.outliers << " pixels differ by more than "
                  << tolerance.max_channel_delta << " levels (allowed " << allowed
                  << "), max difference " << c.max_delta << "\n  render: " << output.string()
                  << "\n  golden: " << golden_path.string()
                  << "\n  diff:   " << (wrote ? diff_path.string() : "(could not write diff image)")
                  << "\n  (red: beyond tolerance, yellow: within it)";
  }
}

}  // namespace facet::test
