// Textures and samplers against hand-computed values: nearest picks, bilinear weights, wrap
// modes, the mip chain and its box filter, level-of-detail selection, trilinear blending,
// sRGB decoding, and reading image files (PNG/PPM written by facet, a hand-made HDR).
#include "facet/texture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/color.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "support/render_helpers.hpp"
#include "support/srgb_reference.hpp"
#include "support/texture_reference.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

constexpr float kEps = 1e-5f;

// A linear (not sRGB) RGBA8 texture whose red channel holds `red`, given BOTTOM row first (the
// way v counts, so tests read like the uv plane); green = 0, blue = 255 - red, alpha 255.
std::shared_ptr<Texture> red_texture(int width, int height, const std::vector<int>& red) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const int value = red[j * width + i];
      std::uint8_t* p = &rgba[(static_cast<std::size_t>(height - 1 - j) * width + i) * 4];
      p[0] = static_cast<std::uint8_t>(value);
      p[1] = 0;
      p[2] = static_cast<std::uint8_t>(255 - value);
      p[3] = 255;
    }
  }
  return Texture::from_rgba8(width, height, std::move(rgba), false, "red");
}

Sampler make_sampler(Filter filter, Wrap wrap = Wrap::repeat) { return {filter, wrap, wrap}; }

float red_at(const Texture& t, const Sampler& s, float u, float v, float lod = 0.0f) {
  return t.sample(s, {u, v}, lod).r;
}

// --- nearest and bilinear ---------------------------------------------------------------

TEST(Sampler, NearestPicksTheTexelContainingUv) {
  // 4x4, value = 10 * (row from the bottom) + column.
  std::vector<int> red(16);
  for (int i = 0; i < 16; ++i) red[i] = 10 * (i / 4) + i % 4;
  auto t = red_texture(4, 4, red);
  const Sampler s = make_sampler(Filter::nearest);
  EXPECT_FLOAT_EQ(red_at(*t, s, 0.01f, 0.01f), 0 / 255.0f);   // bottom-left
  EXPECT_FLOAT_EQ(red_at(*t, s, 0.99f, 0.01f), 3 / 255.0f);   // bottom-right
  EXPECT_FLOAT_EQ(red_at(*t, s, 0.01f, 0.99f), 30 / 255.0f);  // top-left
  EXPECT_FLOAT_EQ(red_at(*t, s, 0.30f, 0.55f), 21 / 255.0f);  // texel (1, 2)
  EXPECT_FLOAT_EQ(red_at(*t, s, 0.50f, 0.50f), 22 / 255.0f);  // a corner: the upper-right texel
}

TEST(Sampler, VZeroIsTheBottomRowOfTheImage) {
  // Stored top row first: row 0 red 200, row 1 red 100. v near 0 must read row 1.
  std::vector<std::uint8_t> rgba = {200, 0, 0, 255, 100, 0, 0, 255};
  auto t = Texture::from_rgba8(1, 2, rgba, false);
  const Sampler s = make_sampler(Filter::nearest);
  EXPECT_FLOAT_EQ(red_at(*t, s, 0.5f, 0.1f), 100 / 255.0f);
  EXPECT_FLOAT_EQ(red_at(*t, s, 0.5f, 0.9f), 200 / 255.0f);
  EXPECT_FLOAT_EQ(t->texel(0, 0, 0).r, 200 / 255.0f);  // texel() uses stored rows
}

// 2x2 with A B on the bottom row and C D on top.
std::shared_ptr<Texture> abcd() { return red_texture(2, 2, {0, 51, 102, 255}); }

TEST(Sampler, BilinearHitsTexelCentresExactly) {
  auto t = abcd();
  const Sampler s = make_sampler(Filter::bilinear);
  // Texel centres are at (i + 0.5) / size: uv = 0.5 / width is texel 0, no blending.
  EXPECT_NEAR(red_at(*t, s, 0.25f, 0.25f), 0.0f, kEps);
  EXPECT_NEAR(red_at(*t, s, 0.75f, 0.25f), 0.2f, kEps);
  EXPECT_NEAR(red_at(*t, s, 0.25f, 0.75f), 0.4f, kEps);
  EXPECT_NEAR(red_at(*t, s, 0.75f, 0.75f), 1.0f, kEps);
}

TEST(Sampler, BilinearWeightsByHand) {
  auto t = abcd();
  const Sampler s = make_sampler(Filter::bilinear);
  // Centre: all four at 1/4 -> (0 + 0.2 + 0.4 + 1) / 4.
  EXPECT_NEAR(red_at(*t, s, 0.5f, 0.5f), 0.4f, kEps);
  // uv (0.375, 0.625): x = 0.375 * 2 - 0.5 = 0.25, y = 0.625 * 2 - 0.5 = 0.75.
  // bottom = 0.75 A + 0.25 B = 0.05; top = 0.75 C + 0.25 D = 0.55; 0.25 bottom + 0.75 top.
  EXPECT_NEAR(red_at(*t, s, 0.375f, 0.625f), 0.425f, kEps);
  // Blue is 255 - red in every texel, so it blends to 1 - red: the weights sum to one.
  EXPECT_NEAR(t->sample(s, {0.375f, 0.625f}).b, 1.0f - 0.425f, kEps);
  EXPECT_NEAR(t->sample(s, {0.375f, 0.625f}).a, 1.0f, kEps);
}

TEST(Sampler, BilinearAcrossTheEdgeFollowsTheWrapMode) {
  auto t = abcd();
  // u = 0: x = -0.5, halfway between texel -1 and texel 0 of the bottom row.
  EXPECT_NEAR(red_at(*t, make_sampler(Filter::bilinear, Wrap::repeat), 0.0f, 0.25f), 0.1f, kEps);
  EXPECT_NEAR(red_at(*t, make_sampler(Filter::bilinear, Wrap::clamp_to_edge), 0.0f, 0.25f), 0.0f,
              kEps);
  EXPECT_NEAR(red_at(*t, make_sampler(Filter::bilinear, Wrap::mirrored_repeat), 0.0f, 0.25f), 0.0f,
              kEps);
  // v = 1: halfway between the top row and, with repeat, the bottom row: (C + A) / 2.
  EXPECT_NEAR(red_at(*t, make_sampler(Filter::bilinear, Wrap::repeat), 0.25f, 1.0f), 0.2f, kEps);
}

// --- wrap modes -------------------------------------------------------------------------

// 4x1 and 1x4 strips with texels 0, 1, 2, 3 (times 50) from left / from the bottom.
struct WrapCase {
  float coordinate;
  int repeat, clamp, mirror;  // the texel each mode picks
};

// OpenGL 4.6 §8.14.2: repeat i mod 4; clamp to [0, 3]; mirrored repeat 0123 3210 0123 ...
const WrapCase kWrapCases[] = {
    {-0.25f, 3, 0, 0},  // texel -1
    {-0.60f, 1, 0, 2},  // texel -3
    {-1.10f, 3, 0, 3},  // texel -5
    {1.25f, 1, 3, 2},   // texel 5
    {2.75f, 3, 3, 3},   // texel 11
    {0.40f, 1, 1, 1},   // inside: texel 1 for every mode
};

TEST(Sampler, WrapModesOutsideZeroToOne) {
  auto horizontal = red_texture(4, 1, {0, 50, 100, 150});
  auto vertical = red_texture(1, 4, {0, 50, 100, 150});
  const Wrap modes[] = {Wrap::repeat, Wrap::clamp_to_edge, Wrap::mirrored_repeat};
  for (const WrapCase& c : kWrapCases) {
    const int expected[] = {c.repeat, c.clamp, c.mirror};
    for (int m = 0; m < 3; ++m) {
      const Sampler s = make_sampler(Filter::nearest, modes[m]);
      const float want = static_cast<float>(expected[m] * 50) / 255.0f;
      EXPECT_FLOAT_EQ(red_at(*horizontal, s, c.coordinate, 0.5f), want)
          << "u " << c.coordinate << " mode " << m;
      EXPECT_FLOAT_EQ(red_at(*vertical, s, 0.5f, c.coordinate), want)
          << "v " << c.coordinate << " mode " << m;
    }
  }
}

TEST(Sampler, WrapModesAreIndependentPerAxis) {
  auto t = abcd();
  const Sampler s{Filter::nearest, Wrap::repeat, Wrap::clamp_to_edge};
  // u 1.25 repeats to texel 0; v 1.25 clamps to the top row: C.
  EXPECT_NEAR(red_at(*t, s, 1.25f, 1.25f), 0.4f, kEps);
  // v -3.0 clamps to the bottom row; u -0.25 repeats to texel 1: B.
  EXPECT_NEAR(red_at(*t, s, -0.25f, -3.0f), 0.2f, kEps);
}

TEST(Sampler, NonFiniteInputGivesSomeTexelNotACrash) {
  auto t = abcd();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (Filter f : {Filter::nearest, Filter::bilinear, Filter::trilinear}) {
    for (Wrap w : {Wrap::repeat, Wrap::clamp_to_edge, Wrap::mirrored_repeat}) {
      for (glm::vec2 uv : {glm::vec2(nan, 0.5f), glm::vec2(inf, -inf), glm::vec2(1e30f, -1e30f)}) {
        for (float lod : {0.0f, nan, inf, -inf}) {
          const float r = t->sample(make_sampler(f, w), uv, lod).r;
          EXPECT_TRUE(r >= 0.0f && r <= 1.0f) << r;
        }
      }
    }
  }
}

// --- mipmaps ----------------------------------------------------------------------------

TEST(Texture, MipChainSizesHalveDownToOneByOne) {
  auto t = red_texture(5, 3, std::vector<int>(15, 7));
  ASSERT_EQ(t->level_count(), 3);
  EXPECT_EQ(t->level(1).width, 2);
  EXPECT_EQ(t->level(1).height, 1);
  EXPECT_EQ(t->level(2).width, 1);
  EXPECT_EQ(t->level(2).height, 1);
  EXPECT_EQ(red_texture(1, 1, {0})->level_count(), 1);
  EXPECT_EQ(red_texture(16, 4, std::vector<int>(64, 0))->level_count(), 5);  // 16, 8, 4, 2, 1
}

TEST(Texture, BoxFilterAveragesTwoByTwoBlocks) {
  // 4x2, bottom row 0 40 100 200, top row 20 60 0 4 (linear data).
  auto t = red_texture(4, 2, {0, 40, 100, 200, 20, 60, 0, 4});
  ASSERT_EQ(t->level(1).width, 2);
  ASSERT_EQ(t->level(1).height, 1);
  EXPECT_EQ(t->level(1).rgba8[0], 30);        // (0 + 40 + 20 + 60) / 4
  EXPECT_EQ(t->level(1).rgba8[4], 76);        // (100 + 200 + 0 + 4) / 4
  EXPECT_EQ(t->level(2).rgba8[0], 53);        // (30 + 76) / 2
  EXPECT_EQ(t->level(1).rgba8[2], 255 - 30);  // blue = 255 - red, averaged the same way
  // An odd side drops its last texel; a side of 1 averages only what exists.
  auto odd = red_texture(3, 1, {10, 20, 250});
  EXPECT_EQ(odd->level(1).rgba8[0], 15);
  auto column = red_texture(1, 2, {10, 22});
  EXPECT_EQ(column->level(1).rgba8[0], 16);
}

TEST(Texture, BoxFilterWorksInLinearSpace) {
  // Black and white sRGB texels average to linear 0.5, which is sRGB code 188, not 128.
  std::vector<std::uint8_t> rgba = {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0};
  auto t = Texture::from_rgba8(2, 2, rgba, true);
  const auto& level1 = t->level(1).rgba8;
  EXPECT_EQ(level1[0], 188);
  EXPECT_EQ(level1[0], test::encode_srgb8(0.5f));
  EXPECT_EQ(level1[3], 128);  // alpha is linear: 127.5 rounded
  EXPECT_NEAR(t->texel(1, 0, 0).r, 0.5f, 0.003f);
}

// One float a texel (depth images): read as (v, v, v, 1), its levels the averages, its data
// length checked.
TEST(Texture, OneFloatTexturesReadAsGrayAndFilterWithoutQuantizing) {
  const auto t = Texture::from_r32f(2, 2, {0.1f, 0.2f, 0.3f, 0.4f}, "depth");
  EXPECT_EQ(t->format(), Texture::Format::r32f);
  EXPECT_EQ(t->texel(0, 1, 0), glm::vec4(0.2f, 0.2f, 0.2f, 1.0f));
  EXPECT_EQ(t->level_count(), 2);
  EXPECT_NEAR(t->texel(1, 0, 0).r, 0.25f, kEps);
  EXPECT_EQ(t->texel(1, 0, 0).a, 1.0f);
  EXPECT_EQ(t->sample(make_sampler(Filter::nearest), {0.75f, 0.25f}),
            glm::vec4(0.4f, 0.4f, 0.4f, 1.0f));
  try {
    Texture::from_r32f(2, 2, {0.1f, 0.2f, 0.3f}, "depth");
    FAIL() << "a short image was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "depth: texture data has 3 values, 2x2 needs 4");
  }
}

TEST(Texture, FloatTexturesFilterWithoutQuantizing) {
  std::vector<float> rgba = {0.1f, 2.0f, 0, 1, 0.2f, 4.0f, 0, 1,
                             0.3f, 6.0f, 0, 1, 0.4f, 8.0f, 0, 1};
  auto t = Texture::from_rgba32f(2, 2, rgba);
  EXPECT_EQ(t->format(), Texture::Format::rgba32f);
  EXPECT_NEAR(t->texel(1, 0, 0).r, 0.25f, kEps);
  EXPECT_NEAR(t->texel(1, 0, 0).g, 5.0f, kEps);  // HDR values above 1 survive
}

// The reference sampler's level of detail (support/texture_reference.hpp), which the SIMD
// sampler's matches bit for bit (texel_batch_test).
TEST(Sampler, LodFromDerivatives) {
  auto t = red_texture(8, 4, std::vector<int>(32, 0));
  const auto lod = [&](glm::vec2 dx, glm::vec2 dy) { return test::reference_lod(*t, dx, dy); };
  // One texel per pixel -> level 0; four texels per pixel -> level 2.
  EXPECT_NEAR(lod({1.0f / 8, 0}, {0, 1.0f / 4}), 0.0f, kEps);
  EXPECT_NEAR(lod({4.0f / 8, 0}, {0, 1.0f / 4}), 2.0f, kEps);
  EXPECT_NEAR(lod({1.0f / 8, 0}, {0, 4.0f / 4}), 2.0f, kEps);   // the larger edge wins
  EXPECT_NEAR(lod({0.5f / 8, 0}, {0, 0.5f / 4}), -1.0f, kEps);  // magnification
  // Length, not max; to within the thousandth of a level that the level of detail promises off
  // powers of 2.
  EXPECT_NEAR(lod({3.0f / 8, 4.0f / 4}, {0, 0}), std::log2(5.0f), 1e-3f);
}

TEST(Sampler, TrilinearBlendsNeighbouringLevels) {
  // 4x4 checker of 0 and 255: level 0 alternates, level 1 (2x2) and level 2 are all 128.
  std::vector<int> red(16);
  for (int i = 0; i < 16; ++i) red[i] = ((i / 4 + i % 4) % 2) * 255;
  auto t = red_texture(4, 4, red);
  const Sampler s = make_sampler(Filter::trilinear);
  const float level1 = 128 / 255.0f;
  // uv at the centre of texel (0, 0), which is 0 at level 0.
  EXPECT_NEAR(red_at(*t, s, 0.125f, 0.125f, 0.0f), 0.0f, kEps);
  EXPECT_NEAR(red_at(*t, s, 0.125f, 0.125f, -2.0f), 0.0f, kEps);  // magnified: level 0
  EXPECT_NEAR(red_at(*t, s, 0.125f, 0.125f, 0.5f), 0.5f * level1, kEps);
  EXPECT_NEAR(red_at(*t, s, 0.125f, 0.125f, 0.25f), 0.25f * level1, kEps);
  EXPECT_NEAR(red_at(*t, s, 0.125f, 0.125f, 1.0f), level1, kEps);
  EXPECT_NEAR(red_at(*t, s, 0.125f, 0.125f, 9.0f), level1, kEps);  // clamped to the last
  // Bilinear and nearest ignore the lod: always the base level.
  EXPECT_NEAR(red_at(*t, make_sampler(Filter::bilinear), 0.125f, 0.125f, 2.0f), 0.0f, kEps);
}

// The bilinear formula (OpenGL 4.6 §8.14.2) written out from texel(), in the order sample()
// rounds in, for repeat wrapping: the value sample() must give bit for bit.
glm::vec4 bilinear_by_hand(const Texture& t, int level, glm::vec2 uv) {
  const int w = t.level(level).width, h = t.level(level).height;
  const float x = uv.x * static_cast<float>(w) - 0.5f, y = uv.y * static_cast<float>(h) - 0.5f;
  const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
  const float a = x - static_cast<float>(i0), b = y - static_cast<float>(j0);
  auto at = [&](int i, int j) {  // j counts from the bottom row
    return t.texel(level, ((i % w) + w) % w, h - 1 - ((j % h) + h) % h);
  };
  const glm::vec4 bottom = at(i0, j0) * (1.0f - a) + at(i0 + 1, j0) * a;
  const glm::vec4 top = at(i0, j0 + 1) * (1.0f - a) + at(i0 + 1, j0 + 1) * a;
  return bottom * (1.0f - b) + top * b;
}

// sample() reads rgba8 textures from a linear float copy made at load, except very large ones
// (over 2^20 texels), which decode per fetch: both must give the formula's exact bits.
TEST(Sampler, BothRgba8StoragePathsGiveTheFormulaExactly) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(-2.0f, 3.0f);
  for (const auto& [width, height] : {std::pair{64, 32}, std::pair{2048, 1024}}) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
    for (auto& byte : rgba) byte = static_cast<std::uint8_t>(rng());
    const auto t = Texture::from_rgba8(width, height, rgba, true);
    const Sampler bilinear = make_sampler(Filter::bilinear);
    const Sampler trilinear = make_sampler(Filter::trilinear);
    for (int i = 0; i < 2000; ++i) {
      const glm::vec2 uv{coordinate(rng), coordinate(rng)};
      const glm::vec4 expected = bilinear_by_hand(*t, 0, uv);
      ASSERT_EQ(t->sample(bilinear, uv), expected) << width << " uv " << uv.x << ", " << uv.y;
      // Trilinear between levels 2 and 3, a quarter of the way.
      const glm::vec4 blend =
          bilinear_by_hand(*t, 2, uv) * 0.75f + bilinear_by_hand(*t, 3, uv) * 0.25f;
      ASSERT_EQ(t->sample(trilinear, uv, 2.25f), blend) << width;
    }
  }
}

// --- sRGB -------------------------------------------------------------------------------

TEST(Sampler, SrgbTexelsAreDecodedWhenSampled) {
  std::vector<std::uint8_t> rgba = {188, 188, 188, 188};
  auto srgb = Texture::from_rgba8(1, 1, rgba, true);
  auto linear = Texture::from_rgba8(1, 1, rgba, false);
  const glm::vec4 s = srgb->sample(make_sampler(Filter::bilinear), {0.5f, 0.5f});
  EXPECT_NEAR(s.r, 0.5f, 0.003f);
  EXPECT_NEAR(s.a, 188 / 255.0f, kEps);  // alpha is never sRGB
  EXPECT_NEAR(linear->sample(make_sampler(Filter::nearest), {0.5f, 0.5f}).r, 188 / 255.0f, kEps);
  EXPECT_TRUE(srgb->srgb());
  EXPECT_FALSE(linear->srgb());
}

TEST(Texture, SrgbRoundTripIsExactForAllCodes) {
  for (int i = 0; i < 256; ++i) {
    const auto code = static_cast<std::uint8_t>(i);
    EXPECT_EQ(test::encode_srgb8(shading::decode_srgb8(code)), code) << i;
  }
}

// --- construction errors and the missing-texture checker ----------------------------------

TEST(Texture, BadSizesAndDataLengthsThrow) {
  EXPECT_THROW(Texture::from_rgba8(0, 1, {}, false), Error);
  EXPECT_THROW(Texture::from_rgba8(1, -1, {}, false), Error);
  EXPECT_THROW(
      Texture::from_rgba8(16385, 1, std::vector<std::uint8_t>(std::size_t{16385} * 4), false),
      Error);
  EXPECT_THROW(Texture::from_rgba8(2, 2, std::vector<std::uint8_t>(15), false), Error);
  EXPECT_THROW(Texture::from_rgba32f(1, 1, std::vector<float>(3)), Error);
  try {
    Texture::from_rgba8(2, 2, std::vector<std::uint8_t>(12), false, "wall.png");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wall.png"), std::string::npos) << e.what();
  }
  auto t = red_texture(2, 2, {0, 0, 0, 0});
  EXPECT_THROW(t->texel(0, 2, 0), Error);
  EXPECT_THROW(t->texel(2, 0, 0), Error);
}

TEST(Texture, MissingTextureIsASharedMagentaChecker) {
  auto t = missing_texture();
  ASSERT_EQ(t, missing_texture());
  EXPECT_EQ(t->width(), 64);
  EXPECT_EQ(t->height(), 64);
  EXPECT_FALSE(t->srgb());
  EXPECT_EQ(t->texel(0, 0, 0), glm::vec4(1, 0, 1, 1));
  EXPECT_EQ(t->texel(0, 7, 7), glm::vec4(1, 0, 1, 1));
  EXPECT_EQ(t->texel(0, 8, 0), glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(t->texel(0, 8, 8), glm::vec4(1, 0, 1, 1));
}

// --- reading files ----------------------------------------------------------------------

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

Framebuffer pattern(int width, int height) {
  Framebuffer fb(width, height);
  for (std::size_t i = 0; i < fb.rgba8().size(); ++i) {
    fb.rgba8()[i] = static_cast<std::uint8_t>(i * 37 + 11);
  }
  return fb;
}

TEST(Texture, LoadsAPngWrittenByFacet) {
  const fs::path dir = test::fresh_test_dir("facet_texture_", "png");
  const Framebuffer fb = pattern(5, 3);
  write_image(fb, (dir / "t.png").string());
  auto t = load_texture((dir / "t.png").string(), true);
  ASSERT_EQ(t->width(), 5);
  ASSERT_EQ(t->height(), 3);
  EXPECT_EQ(t->format(), Texture::Format::rgba8);
  EXPECT_EQ(t->level(0).rgba8, fb.rgba8());
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) EXPECT_EQ(t->texel(0, x, y), fb.pixel(x, y)) << x << "," << y;
  }
  EXPECT_EQ(t->name(), (dir / "t.png").string());
}

TEST(Texture, LoadsAPpmWrittenByFacet) {
  const fs::path dir = test::fresh_test_dir("facet_texture_", "ppm");
  const Framebuffer fb = pattern(4, 2);
  write_image(fb, (dir / "t.ppm").string());
  auto t = load_texture((dir / "t.ppm").string(), false);
  ASSERT_EQ(t->width(), 4);
  for (std::size_t i = 0; i < fb.rgba8().size(); ++i) {
    EXPECT_EQ(t->level(0).rgba8[i], i % 4 == 3 ? 255 : fb.rgba8()[i]) << i;  // PPM has no alpha
  }
}

TEST(Texture, LoadsHdrAsLinearFloat) {
  // Radiance RGBE, 2x1, flat scanlines: value = mantissa * 2^(exponent - 136).
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
  hdr += std::string("\x80\x80\x80\x81", 4) + std::string("\x40\x20\x10\x81", 4);
  auto t = load_texture_from_memory(reinterpret_cast<const std::uint8_t*>(hdr.data()), hdr.size(),
                                    true, "sky.hdr");
  ASSERT_EQ(t->format(), Texture::Format::rgba32f);
  EXPECT_FALSE(t->srgb());
  EXPECT_EQ(t->texel(0, 0, 0), glm::vec4(1.0f, 1.0f, 1.0f, 1.0f));
  EXPECT_EQ(t->texel(0, 1, 0), glm::vec4(0.5f, 0.25f, 0.125f, 1.0f));
}

void expect_read_error(const std::string& path, const std::string& part) {
  try {
    load_texture(path, true);
    ADD_FAILURE() << path << ": no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": cannot read image: ", 0), 0u) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

TEST(Texture, UnreadableFilesThrowNamingThePath) {
  const fs::path dir = test::fresh_test_dir("facet_texture_", "errors");
  expect_read_error((dir / "absent.png").string(), "No such file");
  expect_read_error(dir.string(), "directory");
  write_bytes(dir / "empty.png", "");
  expect_read_error((dir / "empty.png").string(), "empty");
  write_bytes(dir / "text.png", "this is not an image\n");
  expect_read_error((dir / "text.png").string(), "unknown image type");
  write_bytes(dir / "cut.png", std::string("\x89PNG\r\n\x1a\n\0\0", 10));
  expect_read_error((dir / "cut.png").string(), "");
  // PNM errors from facet's own reader have the same shape, with the line.
  write_bytes(dir / "bad.ppm", "P3\n1 1\n255\n0 0 300\n");
  expect_read_error((dir / "bad.ppm").string(), "above maxval 255 (line 4)");
}

}  // namespace
}  // namespace facet

namespace facet::shading {
namespace {

// The exact sRGB encode by the thresholds (support/srgb_reference.hpp's exact_srgb8, which
// srgb_row_test holds the library's encode to within a code) against the definition:
// round(linear_to_srgb(x) * 255) for a dense sweep of inputs, and every code's decoded value
// back to the code.
TEST(SrgbEncode, MatchesTheDefinitionEverywhere) {
  auto reference = [](float x) {
    return static_cast<int>(std::lround(linear_to_srgb(std::clamp(x, 0.0f, 1.0f)) * 255.0f));
  };
  int mismatches = 0;
  for (int i = 0; i <= 1000000; ++i) {
    float x = static_cast<float>(i) / 1000000.0f;
    if (test::exact_srgb8(x) != reference(x)) ++mismatches;
  }
  EXPECT_LE(mismatches, 2) << "only values within float rounding of a code boundary may differ";
  EXPECT_EQ(test::exact_srgb8(-1.0f), 0);
  EXPECT_EQ(test::exact_srgb8(2.0f), 255);
  EXPECT_EQ(test::exact_srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
  for (int code = 0; code < 256; ++code) EXPECT_EQ(test::exact_srgb8(decode_srgb8(code)), code);
}

}  // namespace
}  // namespace facet::shading
