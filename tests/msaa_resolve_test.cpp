// The MSAA resolve of a tone-mapped tile (pipeline/output/output.cpp's average_samples): each
// pixel whose samples differ is the average, in sample order, of its samples each mapped alone
// (a sample nothing was drawn at keeps its color unmapped); a pixel whose samples are alike is
// its one color mapped. Checked bit for bit on a tile row where most pixels are split, so the
// split pixels' samples are mapped in several batches.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/frame.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/output/output.hpp"

namespace facet::test {
namespace {

using pipeline::kClearDepth;

TEST(MsaaResolve, ToneMappedSplitPixelsAverageTheirSamplesMappedOneByOne) {
  constexpr int kWidth = 128, kRows = 3, kSamples = 4;
  pipeline::Frame frame;
  const pipeline::Kernels kernels = pipeline::kernels_for(chosen_simd_target());
  frame.kernels = &kernels;
  const std::ptrdiff_t plane = static_cast<std::ptrdiff_t>(kWidth) * kRows;
  std::vector<glm::vec4> color(plane * kSamples);
  std::vector<float> depth(plane * kSamples + pipeline::kDepthSlack, kClearDepth);
  std::vector<std::uint8_t> split(plane);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> value(0.0f, 8.0f), unit(0.0f, 1.0f);
  for (auto& c : color) c = {value(rng), value(rng), value(rng), 1.0f};
  for (std::ptrdiff_t i = 0; i < plane; ++i) {
    split[i] = unit(rng) < 0.8f;
    for (int s = 0; s < kSamples; ++s) {
      if (unit(rng) < 0.7f) depth[s * plane + i] = 0.5f * unit(rng);  // else nothing drawn
    }
  }
  pipeline::TileContext tile;
  tile.frame = &frame;
  tile.x0 = 0, tile.y0 = 0, tile.x1 = kWidth, tile.y1 = kRows;
  tile.stride = kWidth;
  tile.samples = kSamples;
  tile.sample_plane = plane;
  tile.color = color.data();
  tile.sample_colors = color.data() + plane;
  tile.depth = depth.data();
  tile.split = split.data();
  pipeline::Resolve resolve;
  resolve.scale = 1.5f;
  resolve.tone_mapping = ToneMapping::pbr_neutral;
  Framebuffer target(kWidth, kRows, ColorFormat::rgba32f, DepthImage::none);
  pipeline::resolve_tile(tile, resolve, target);

  const auto mapped = [&](std::ptrdiff_t i, int s) {
    glm::vec4 out;
    kernels.tone_map_row(resolve.tone_mapping, &pipeline::sample_color(tile, i, s),
                         &depth[s * plane + i], kClearDepth, 1, resolve.scale, &out);
    return out;
  };
  int split_pixels = 0;
  for (std::ptrdiff_t i = 0; i < plane; ++i) {
    glm::vec4 want = mapped(i, 0);
    if (split[i]) {
      ++split_pixels;
      for (int s = 1; s < kSamples; ++s) want += mapped(i, s);
      want *= 1.0f / kSamples;
    }
    const float* got = target.rgba32f().data() + 4 * i;
    ASSERT_EQ(std::memcmp(got, &want.x, 3 * sizeof(float)), 0)
        << "pixel " << i << (split[i] ? " (split)" : "") << ": " << got[0] << " " << got[1] << " "
        << got[2] << " against " << want.r << " " << want.g << " " << want.b;
  }
  EXPECT_GT(split_pixels, kRows * 256 / (kSamples - 1));  // more than one batch a row
}

}  // namespace
}  // namespace facet::test
