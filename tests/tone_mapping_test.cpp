// Tone mapping (RenderSettings::tone_mapping, pipeline/output/tone_map_row.hpp): the curves as
// their authors wrote them, the same bits on every SIMD target, what the renderer maps and what
// it leaves alone (the clear color, frames of display values), each sample before the average,
// and images independent of threads, tiles and targets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "facet/color.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "pipeline/output/tone_map_row.hpp"
#include "support/forced_target.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

using DVec3 = glm::dvec3;

// The curves in double precision, as published (Khronos PBR Neutral's GLSL; Hill's ACES fit
// with the 1 / 0.6 exposure), for the kernel's float results to be checked against.
DVec3 pbr_neutral(DVec3 c) {
  const double start = 0.8 - 0.04, desaturation = 0.15, d = 1.0 - start;
  const double x = std::min(c.r, std::min(c.g, c.b));
  const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  c -= offset;
  const double peak = std::max(c.r, std::max(c.g, c.b));
  if (peak < start) return c;
  const double new_peak = 1.0 - d * d / (peak + d - start);
  c *= new_peak / peak;
  const double g = 1.0 - 1.0 / (desaturation * (peak - new_peak) + 1.0);
  return c * (1.0 - g) + DVec3(new_peak) * g;
}

DVec3 aces(DVec3 c) {
  c /= 0.6;
  const glm::dmat3 in = glm::transpose(
      glm::dmat3(0.59719, 0.35458, 0.04823, 0.07600, 0.90834, 0.01566, 0.02840, 0.13383, 0.83777));
  const glm::dmat3 out = glm::transpose(glm::dmat3(1.60475, -0.53108, -0.07367, -0.10208, 1.10813,
                                                   -0.00605, -0.00327, -0.07276, 1.07602));
  const DVec3 v = in * c;
  const DVec3 a = v * (v + 0.0245786) - 0.000090537;
  const DVec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return glm::clamp(out * (a / b), 0.0, 1.0);
}

std::vector<glm::vec4> map_row(ToneMapping curve, const std::vector<glm::vec4>& colors,
                               const std::vector<float>& depth, float scale) {
  std::vector<glm::vec4> out(colors.size());
  pipeline::tone_map_row_kernel(chosen_simd_target())(
      curve, colors.data(), depth.data(), 1.0f, static_cast<int>(colors.size()), scale, out.data());
  return out;
}

TEST(ToneMapRow, FollowsTheCurvesWithTheSameBitsOnEveryTarget) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (ToneMapping curve : {ToneMapping::pbr_neutral, ToneMapping::aces}) {
    for (int round = 0; round < 40; ++round) {
      const int count = 1 + static_cast<int>(rng() % 70);  // whole vectors and a tail
      const float scale = round % 3 == 0 ? 4.0f : 1.0f;
      std::vector<glm::vec4> colors(count);
      std::vector<float> depth(count);
      for (int i = 0; i < count; ++i) {
        // Dark, mid, bright and very bright colors; alpha passes through.
        const float range = std::pow(10.0f, 4.0f * unit(rng) - 2.0f);
        colors[i] = {unit(rng) * range, unit(rng) * range, unit(rng) * range, unit(rng)};
        depth[i] = rng() % 5 == 0 ? 1.0f : 0.5f;  // 1: nothing drawn, not mapped
      }
      if (count > 3) colors[1].r = nan, colors[2].g = inf, colors[3].b = -2.0f;
      std::vector<glm::vec4> first;
      for (std::int64_t target : simd_targets()) {
        ForcedTarget forced(target);
        const std::vector<glm::vec4> mapped = map_row(curve, colors, depth, scale);
        if (first.empty()) first = mapped;
        ASSERT_EQ(std::memcmp(first.data(), mapped.data(), count * sizeof(glm::vec4)), 0)
            << hwy::TargetName(target) << ", round " << round;
      }
      for (int i = 0; i < count; ++i) {
        SCOPED_TRACE(testing::Message() << "round " << round << ", color " << i);
        const glm::vec4& in = colors[i];
        const glm::vec4& got = first[i];
        EXPECT_EQ(std::memcmp(&got.a, &in.a, sizeof(float)), 0) << "alpha unchanged";
        if (depth[i] == 1.0f) {  // the clear color: scaled, not mapped
          if (!std::isnan(in.r)) {
            EXPECT_EQ(got.r, in.r * scale);
          }
          if (!std::isnan(in.b)) {
            EXPECT_EQ(got.b, in.b * scale);
          }
          continue;
        }
        // What the kernel takes: scaled, NaN and negatives as 0, at most 65504.
        auto sane = [&](float v) {
          return std::isnan(v) ? 0.0 : std::clamp(static_cast<double>(v) * scale, 0.0, 65504.0);
        };
        const DVec3 c{sane(in.r), sane(in.g), sane(in.b)};
        const DVec3 want = curve == ToneMapping::aces ? aces(c) : pbr_neutral(c);
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(got[k], want[k], 2e-6 + 2e-5 * want[k]) << "channel " << k;
          EXPECT_GE(got[k], 0.0f);
          EXPECT_LE(got[k], 1.0f);
        }
      }
    }
  }
}

TEST(ToneMapRow, PbrNeutralKeepsColorsBelowTheKneeAndRollsOffAbove) {
  // Below the knee only the offset moves a color: every channel 0.04 down.
  const std::vector<glm::vec4> kept = map_row(
      ToneMapping::pbr_neutral, {{0.5f, 0.3f, 0.2f, 1.0f}, {0.7f, 0.1f, 0.74f, 1.0f}}, {0, 0}, 1);
  EXPECT_NEAR(kept[0].r, 0.46f, 1e-6f);
  EXPECT_NEAR(kept[0].g, 0.26f, 1e-6f);
  EXPECT_NEAR(kept[1].b, 0.70f, 1e-6f);
  // Grey up a ramp to 10^4: never darker, never past 1, and past 0.99 by 30.
  float last = 0.0f;
  for (float v = 0.0f; v < 1e4f; v = v * 1.25f + 0.01f) {
    const float got = map_row(ToneMapping::pbr_neutral, {{v, v, v, 1.0f}}, {0}, 1)[0].r;
    EXPECT_GE(got, last) << v;
    EXPECT_LT(got, 1.0f) << v;
    if (v > 30.0f) {
      EXPECT_GT(got, 0.99f) << v;
    }
    last = got;
  }
}

TEST(ToneMapRow, TheInverseCurvesGiveBackWhatTheyWereShown) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 0.98f);
  for (int i = 0; i < 2000; ++i) {
    // Colors the curves show: any below PBR Neutral's knee (0.76), and near grey up to white
    // (both curves desaturate bright colors, so no bright saturated color is shown).
    const glm::vec3 grey(unit(rng));
    const glm::vec3 any{unit(rng), unit(rng), unit(rng)};
    for (ToneMapping curve : {ToneMapping::pbr_neutral, ToneMapping::aces}) {
      const glm::vec3 shown =
          curve == ToneMapping::pbr_neutral && i % 2 == 0 ? any * 0.77f : glm::mix(grey, any, 0.1f);
      const glm::vec3 linear = inverse_tone_map(curve, shown);
      const glm::vec4 back = map_row(curve, {glm::vec4(linear, 1.0f)}, {0.5f}, 1.0f)[0];
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(back[k], shown[k], 2e-4f) << i << ", channel " << k;
      }
      // A bright saturated color the curve never shows: a color it shows of that hue.
      const glm::vec3 unshown =
          inverse_tone_map(curve, glm::vec3(0.95f, any.y * 0.1f, any.z * 0.1f));
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(unshown, glm::vec3(0.0f))));
      EXPECT_GT(unshown.r, unshown.g);
      EXPECT_GT(unshown.r, unshown.b);
    }
  }
}

// Fog's color under a curve, exposed and mapped, shows as the fog color itself (clipped to 1)
// for colors the curve can show: the sky, greys, near-white.
TEST(ToneMapRow, FogColorUnderACurveShowsAsTheFogColor) {
  const glm::vec3 fogs[] = {{0.53f, 0.66f, 0.82f}, {0.2f, 0.2f, 0.2f}, {0.9f, 0.88f, 0.85f}};
  for (const float scale : {0.5f, 1.0f, 2.0f}) {
    for (const glm::vec3 fog : fogs) {
      EXPECT_EQ(fog_color_under(ToneMapping::none, fog, scale), fog);
      const glm::vec3 shown = glm::min(fog * scale, glm::vec3(1.0f));
      for (ToneMapping curve : {ToneMapping::pbr_neutral, ToneMapping::aces}) {
        const glm::vec3 under = fog_color_under(curve, fog, scale);
        const glm::vec4 mapped = map_row(curve, {glm::vec4(under, 1.0f)}, {0.5f}, scale)[0];
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(mapped[k], shown[k], 2e-3f) << static_cast<int>(curve) << " x" << scale;
        }
      }
    }
  }
}

// A square of one unlit, very bright color, its edges at fractions of a pixel, over a dark
// clear color.
Framebuffer render_bright_square(RenderSettings settings, glm::vec3 color,
                                 ColorFormat format = ColorFormat::rgba8_srgb) {
  constexpr int kSize = 48;
  settings.clear_color = {0.02f, 0.03f, 0.05f, 1.0f};
  Renderer renderer(settings);
  Material material;
  material.shading = ShadingModel::unlit;
  material.base_color = glm::vec4(color, 1.0f);
  material.cull = CullMode::none;
  auto quad = std::make_shared<const Mesh>(rectangle(1.0f, 1.0f));
  renderer.begin_frame(test_camera(kSize, kSize));
  renderer.draw(quad, material,
                glm::rotate(glm::translate(glm::mat4(1.0f), {0.03f, -0.02f, -2.5f}), 0.3f,
                            glm::vec3(0.0f, 0.0f, 1.0f)));
  Framebuffer fb(kSize, kSize, format);
  renderer.finish(fb);
  return fb;
}

TEST(ToneMapping, MapsWhatIsDrawnAndLeavesTheClearColor) {
  const glm::vec3 bright{6.0f, 1.5f, 0.3f};
  RenderSettings settings;
  const Framebuffer clipped = render_bright_square(settings, bright);
  settings.tone_mapping = ToneMapping::pbr_neutral;
  const Framebuffer mapped = render_bright_square(settings, bright);
  const std::vector<float> drawn_depth{0.5f};
  const glm::vec4 want =
      map_row(ToneMapping::pbr_neutral, {glm::vec4(bright, 1.0f)}, drawn_depth, 1.0f)[0];
  const glm::vec3 want_srgb = linear_to_srgb(glm::vec3(want));
  const glm::vec4 clear_srgb{linear_to_srgb({0.02f, 0.03f, 0.05f}), 1.0f};
  int square = 0, background = 0;
  for (std::size_t p = 0; p < mapped.rgba8().size(); p += 4) {
    const std::uint8_t* m = &mapped.rgba8()[p];
    const std::uint8_t* c = &clipped.rgba8()[p];
    if (c[0] == 255) {  // the square's inside: clipped without mapping, below white with it
      ++square;
      // Half a code of rounding, and the encode's lines' distance from the curve (under 0.07
      // of a code: SrgbLines.StayWithinAFifteenthOfACodeOfTheCurve).
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(m[k], 255.0f * want_srgb[k], 0.57f) << k;
      EXPECT_LT(m[0], 255);
    } else if (std::abs(c[0] - 255.0f * clear_srgb.r) < 0.6f) {
      ++background;
      EXPECT_EQ(std::memcmp(m, c, 4), 0) << "the clear color is not mapped";
    }
  }
  EXPECT_GT(square, 100);
  EXPECT_GT(background, 100);
}

TEST(ToneMapping, EachSampleIsMappedBeforeTheAverage) {
  // A color far past white: mapped first, an edge pixel with half its samples covered is about
  // halfway between white and the background; averaged first, it would be past white and
  // mapped to nearly white.
  RenderSettings settings;
  settings.msaa = 4;
  settings.tone_mapping = ToneMapping::pbr_neutral;
  const Framebuffer fb = render_bright_square(settings, glm::vec3(200.0f));
  int between = 0;
  for (std::size_t p = 0; p < fb.rgba8().size(); p += 4) {
    const int v = fb.rgba8()[p + 1];
    if (v > 120 && v < 230) ++between;
  }
  EXPECT_GT(between, 20) << "edge pixels between the background and white";
}

TEST(ToneMapping, TheSameImageForAnyThreadsTilesAndTargets) {
  RenderSettings settings;
  settings.tone_mapping = ToneMapping::aces;
  settings.exposure = 1.5f;
  settings.msaa = 4;
  settings.threads = 1;
  const Framebuffer reference = render_shapes(ShadingModel::phong, 160, 96, settings);
  RenderSettings unmapped = settings;
  unmapped.tone_mapping = ToneMapping::none;
  EXPECT_NE(render_shapes(ShadingModel::phong, 160, 96, unmapped).rgba8(), reference.rgba8());
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int threads : {1, 3}) {
      for (int tile : {16, 64}) {
        settings.threads = threads;
        settings.tile_size = tile;
        EXPECT_EQ(render_shapes(ShadingModel::phong, 160, 96, settings).rgba8(), reference.rgba8())
            << hwy::TargetName(target) << ", " << threads << " threads, tiles of " << tile;
      }
    }
  }
}

TEST(ToneMapping, FramesOfDisplayValuesAreNotMapped) {
  RenderSettings settings;
  const Framebuffer plain = render_shapes(ShadingModel::normals, 96, 64, settings);
  settings.tone_mapping = ToneMapping::pbr_neutral;
  EXPECT_EQ(render_shapes(ShadingModel::normals, 96, 64, settings).rgba8(), plain.rgba8());
}

TEST(ToneMapping, FloatTargetsHoldTheMappedColorsAsToneMapGivesThem) {
  const glm::vec3 bright{3.0f, 0.8f, 0.2f};
  RenderSettings settings;
  settings.exposure = 0.5f;
  const Framebuffer raw = render_bright_square(settings, bright, ColorFormat::rgba32f);
  settings.tone_mapping = ToneMapping::aces;
  const Framebuffer mapped = render_bright_square(settings, bright, ColorFormat::rgba32f);
  int compared = 0;
  for (std::size_t p = 0; p < raw.rgba32f().size(); p += 4) {
    glm::vec4 c{raw.rgba32f()[p], raw.rgba32f()[p + 1], raw.rgba32f()[p + 2], raw.rgba32f()[p + 3]};
    if (c.r < 1.0f) continue;  // the background: not mapped
    // raw holds the exposure already: tone_map adds none.
    std::vector<glm::vec4> one{c};
    tone_map(ToneMapping::aces, one, 0.0f);
    EXPECT_EQ(std::memcmp(&one[0], &mapped.rgba32f()[p], sizeof(glm::vec4)), 0) << p / 4;
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

}  // namespace
}  // namespace facet::test
