// The PNG encoder (src/core/png_encode.cpp): what it writes decodes through libpng to the
// same pixels, opaque images are stored as RGB, and the bytes do not depend on the thread count.
#include "core/png_encode.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstdint>
#include <fstream>
#include <random>
#include <vector>

#include "support/render_helpers.hpp"

namespace facet {
namespace {

std::vector<std::uint8_t> random_rgba(int width, int height, bool opaque, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) {
    // Runs of equal bytes as well as noise, so both kinds of deflate output are exercised.
    rgba[i] =
        (i / 64) % 2 ? static_cast<std::uint8_t>(random()) : static_cast<std::uint8_t>(i / 256);
    if (opaque && i % 4 == 3) rgba[i] = 255;
  }
  return rgba;
}

test::Rgba8Image decode(const std::vector<std::uint8_t>& png, const std::string& name) {
  const std::string path = ::testing::TempDir() + "png_encode_" + name + ".png";
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  return test::read_png(path);
}

// The IHDR's color type: byte 25 of the file (8 signature, 8 chunk header, 9 into IHDR).
int color_type(const std::vector<std::uint8_t>& png) { return png.at(25); }

TEST(PngEncode, DecodesToTheSamePixels) {
  // Sizes around the 64-row bands: one row, one column, a band and a bit, several bands.
  const int sizes[][2] = {{1, 1}, {5, 1}, {1, 65}, {70, 130}, {257, 64}, {33, 200}};
  for (const auto& size : sizes) {
    const int width = size[0], height = size[1];
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    for (bool opaque : {false, true}) {
      const std::vector<std::uint8_t> rgba = random_rgba(width, height, opaque, width * height);
      const std::vector<std::uint8_t> png = io::encode_png(rgba.data(), width, height);
      EXPECT_EQ(color_type(png), opaque ? 2 : 6);
      const test::Rgba8Image decoded =
          decode(png, std::to_string(width) + "x" + std::to_string(height) + (opaque ? "o" : "t"));
      ASSERT_EQ(decoded.width, width);
      ASSERT_EQ(decoded.height, height);
      EXPECT_EQ(decoded.pixels, rgba);
    }
  }
}

TEST(PngEncode, BytesAreTheSameForAnyThreadCount) {
  const int width = 300, height = 700;  // eleven bands
  const std::vector<std::uint8_t> rgba = random_rgba(width, height, false, 7);
  std::vector<std::uint8_t> serial;
  {
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    serial = io::encode_png(rgba.data(), width, height);
  }
  EXPECT_EQ(io::encode_png(rgba.data(), width, height), serial);
}

}  // namespace
}  // namespace facet
