// Tiles where nothing is drawn write the clear color and depth only where the framebuffer does not
// hold them already, or into a large framebuffer with streaming stores
// (pipeline/output/framebuffer_rows.hpp), or not at all where a framebuffer that keeps its
// cleared tiles knows they hold them: a framebuffer drawn into again, whatever it held, must
// end exactly as a new one does, and the rows written either way hold the same bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "facet/renderer.hpp"
#include "pipeline/output/framebuffer_rows.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

// A small quad in the middle of the frame, cleared to `clear`, into `target` (empty tiles around
// the quad, partial ones at the edges).
void render_quad(const glm::vec4& clear, Framebuffer& target) {
  const int width = target.width(), height = target.height();
  RenderSettings settings;
  settings.clear_color = clear;
  Renderer renderer(settings);
  Material material;
  material.shading = ShadingModel::unlit;
  material.base_color = {1.0f, 0.5f, 0.0f, 1.0f};
  const Mesh quad = soup_quad(-0.5f, -0.5f, 0.5f, 0.5f, -5.0f);
  renderer.begin_frame(test_camera(width, height), Lighting{});
  renderer.draw(quad, material);
  renderer.finish(target);
}

Framebuffer fresh_render(const glm::vec4& clear, int width, int height) {
  Framebuffer target(width, height);
  render_quad(clear, target);
  return target;
}

// Each frame over what the one before left: garbage, then the other clear, then the same.
void expect_reused_ends_as_new(int width, int height) {
  const glm::vec4 blue{0.1f, 0.2f, 0.6f, 1.0f}, grey{0.5f, 0.5f, 0.5f, 1.0f};
  const Framebuffer expected_blue = fresh_render(blue, width, height);
  const Framebuffer expected_grey = fresh_render(grey, width, height);
  ASSERT_NE(expected_blue.rgba8(), expected_grey.rgba8());
  Framebuffer reused(width, height);
  std::fill(reused.rgba8().begin(), reused.rgba8().end(), std::uint8_t{0x5A});
  std::fill(reused.depth().begin(), reused.depth().end(), 0.25f);
  for (const glm::vec4* clear : {&blue, &grey, &grey, &blue}) {
    render_quad(*clear, reused);
    const Framebuffer& expected = clear == &blue ? expected_blue : expected_grey;
    ASSERT_EQ(reused.rgba8(), expected.rgba8());
    ASSERT_EQ(reused.depth(), expected.depth());
  }
}

TEST(ClearedRows, AFramebufferDrawnIntoAgainEndsAsANewOne) {
  ASSERT_FALSE(pipeline::streams_cleared_rows(200 * 150 * 4));
  expect_reused_ends_as_new(200, 150);
}

TEST(ClearedRows, ALargeFramebufferStreamedIntoAgainEndsAsANewOne) {
  // Color and depth each past the streaming threshold; rows that are no whole number of lines.
  const int width = 1503, height = 1101;
  ASSERT_TRUE(pipeline::streams_cleared_rows(static_cast<std::size_t>(width) * height * 4));
  expect_reused_ends_as_new(width, height);
}

// A quad at x (none when x is NaN) over `clear` at `exposure`, with `samples` a pixel, into
// `target` in 16-pixel tiles.
void render_quad_at(float x, const glm::vec4& clear, float exposure, int samples,
                    Framebuffer& target) {
  RenderSettings settings;
  settings.clear_color = clear;
  settings.exposure = exposure;
  settings.msaa = samples;
  settings.tile_size = 16;
  settings.threads = 2;
  Renderer renderer(settings);
  Material material;
  material.shading = ShadingModel::unlit;
  material.base_color = {1.0f, 0.5f, 0.0f, 1.0f};
  const Mesh quad = soup_quad(x - 0.4f, -0.3f, x + 0.4f, 0.5f, -5.0f);
  renderer.begin_frame(test_camera(target.width(), target.height()), Lighting{});
  if (!std::isnan(x)) renderer.draw(quad, material);
  renderer.finish(target);
}

void expect_same_images(const Framebuffer& a, const Framebuffer& b, const std::string& where) {
  EXPECT_EQ(a.rgba8(), b.rgba8()) << where;
  EXPECT_EQ(a.rgba32f(), b.rgba32f()) << where;
  EXPECT_EQ(a.depth(), b.depth()) << where;
}

// A framebuffer that keeps its cleared tiles leaves them alone where nothing is drawn again:
// each frame still ends as in a new framebuffer, as the quad moves over and off the tiles and
// the clear color and the exposure change; 8-bit and float, one sample and four.
TEST(ClearedRows, AFramebufferKeepingItsClearedTilesEndsAsANewOne) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float xs[] = {-1.0f, 1.2f, nan, 0.0f, 1.5f, nan, nan, -0.6f, -0.6f, 0.4f, nan, nan};
  for (ColorFormat format : {ColorFormat::rgba8_srgb, ColorFormat::rgba32f}) {
    for (int samples : {1, 4}) {
      Framebuffer kept(96, 64, format);
      kept.keep_cleared_tiles(true);
      for (int frame = 0; frame < static_cast<int>(std::size(xs)); ++frame) {
        const glm::vec4 clear = frame < 8 ? glm::vec4(0.1f, 0.2f, 0.6f, 1.0f) : glm::vec4(0.5f);
        const float exposure = frame < 10 ? 0.0f : 1.0f;
        Framebuffer fresh(96, 64, format);
        render_quad_at(xs[frame], clear, exposure, samples, fresh);
        render_quad_at(xs[frame], clear, exposure, samples, kept);
        ASSERT_TRUE(kept.keeps_cleared_tiles());
        expect_same_images(kept, fresh,
                           "frame " + std::to_string(frame) + ", " + std::to_string(samples) +
                               " samples, format " + std::to_string(static_cast<int>(format)));
      }
    }
  }
}

// What is written through its accessors after a render, or given it by assignment, is cleared
// again by the next render wherever it draws nothing: either forgets which tiles were cleared.
TEST(ClearedRows, AFramebufferKeepingItsClearedTilesForgetsThemWhenWritten) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const glm::vec4 clear(0.1f, 0.2f, 0.6f, 1.0f);
  Framebuffer fresh(96, 64);
  render_quad_at(nan, clear, 0.0f, 1, fresh);
  Framebuffer kept(96, 64);
  kept.keep_cleared_tiles(true);
  render_quad_at(nan, clear, 0.0f, 1, kept);  // every tile known to be cleared
  std::fill(kept.rgba8().begin(), kept.rgba8().end(), std::uint8_t{0x5A});
  render_quad_at(nan, clear, 0.0f, 1, kept);
  expect_same_images(kept, fresh, "color written");
  std::fill(kept.depth().begin(), kept.depth().end(), 0.25f);
  render_quad_at(nan, clear, 0.0f, 1, kept);
  expect_same_images(kept, fresh, "depth written");
  Framebuffer other(96, 64);
  std::fill(other.rgba8().begin(), other.rgba8().end(), std::uint8_t{0x5A});
  other.keep_cleared_tiles(true);
  kept = other;
  ASSERT_TRUE(kept.keeps_cleared_tiles());
  render_quad_at(nan, clear, 0.0f, 1, kept);
  expect_same_images(kept, fresh, "assigned");
  kept.keep_cleared_tiles(false);
  EXPECT_FALSE(kept.keeps_cleared_tiles());
}

// Rows of 4-byte values at every alignment and length up to a few cache lines, written streamed
// or not: the destination holds the row and nothing around it changes.
TEST(ClearedRows, RowsWrittenEitherWayHoldTheSameBytes) {
  std::vector<std::uint8_t> row(256);
  std::iota(row.begin(), row.end(), std::uint8_t{1});
  for (bool streaming : {false, true}) {
    for (std::size_t start = 0; start < 64; start += 4) {
      for (std::size_t bytes = 0; bytes <= 192; bytes += 4) {
        alignas(64) std::uint8_t out[256 + 64];
        std::fill(std::begin(out), std::end(out), std::uint8_t{0xEE});
        pipeline::write_cleared_row(out + start, row.data(), bytes, streaming);
        pipeline::end_streamed_rows();
        for (std::size_t b = 0; b < std::size(out); ++b) {
          const bool inside = b >= start && b < start + bytes;
          ASSERT_EQ(out[b], inside ? row[b - start] : 0xEE)
              << "byte " << b << ", start " << start << ", " << bytes << " bytes"
              << (streaming ? ", streaming" : "");
        }
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
