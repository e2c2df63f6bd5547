// Hidden work skipped: a tile's bin starts at the last triangle that hides everything before
// it, small bins skip per 8x8 block what a later triangle hides there
// (pipeline/raster/occlusion.cpp), and 8x8 blocks behind what is drawn are rejected (raster.hpp).
// All must leave every pixel as drawing everything would.
#include "pipeline/raster/occlusion.hpp"

#include <gtest/gtest.h>

#include "facet/renderer.hpp"
#include "pipeline/bin/bin.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 160, kHeight = 96;

struct Layer {
  Mesh mesh;
  glm::vec4 color;
};

// Draws the layers in order, each an unlit single color; returns the image and the stats.
// Small tiles by default, so that most of them lie off the quads' diagonals.
Framebuffer draw_layers(const std::vector<Layer>& layers, FrameStats* stats, int tile_size = 16) {
  RenderSettings settings;
  settings.tile_size = tile_size;
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  for (const Layer& layer : layers) {
    Material material;
    material.shading = ShadingModel::unlit;
    material.base_color = layer.color;
    renderer.draw(layer.mesh, material);
  }
  renderer.finish(fb);
  if (stats) *stats = renderer.stats();
  return fb;
}

// Full-screen quads (at 60 degrees the view at depth d spans about +-0.58 d vertically).
Layer full_screen(float z, glm::vec4 color) {
  const float half = -z * 2.0f;
  return {soup_quad(-half, -half, half, half, z), color};
}

TEST(Occlusion, BackToFrontLayersShadeLittleMoreThanTheFrontOne) {
  std::vector<Layer> layers;
  for (int i = 0; i < 6; ++i) {
    layers.push_back(full_screen(-10.0f + i, {0.1f * i, 0.5f, 1.0f - 0.1f * i, 1.0f}));
  }
  FrameStats stats;
  Framebuffer fb = draw_layers(layers, &stats);
  Framebuffer front = draw_layers({layers.back()}, nullptr);
  EXPECT_EQ(fb.rgba8(), front.rgba8());
  EXPECT_EQ(fb.depth(), front.depth());
  // All six layers would be 6 * pixels; only tiles a quad's diagonal crosses keep them all.
  const std::uint64_t pixels = std::uint64_t{kWidth} * kHeight;
  EXPECT_LT(stats.pixels_shaded, 3 * pixels);
  EXPECT_GE(stats.pixels_shaded, pixels);
}

// With large tiles every tile but two lies on a quad's diagonal, where neither of its triangles
// covers the tile: there the skipping works block by block, and only the blocks the diagonal
// crosses shade every layer.
TEST(Occlusion, BackToFrontLayersInLargeTilesShadeTheDiagonalBlocksOnly) {
  std::vector<Layer> layers;
  for (int i = 0; i < 6; ++i) {
    layers.push_back(full_screen(-10.0f + i, {0.1f * i, 0.5f, 1.0f - 0.1f * i, 1.0f}));
  }
  FrameStats stats;
  Framebuffer fb = draw_layers(layers, &stats, 64);
  Framebuffer front = draw_layers({layers.back()}, nullptr, 64);
  EXPECT_EQ(fb.rgba8(), front.rgba8());
  EXPECT_EQ(fb.depth(), front.depth());
  // Tile by tile: four of six tiles would shade all six layers, over 4 times the pixels.
  const std::uint64_t pixels = std::uint64_t{kWidth} * kHeight;
  EXPECT_LT(stats.pixels_shaded, 2 * pixels);
  EXPECT_GE(stats.pixels_shaded, pixels);
}

TEST(Occlusion, FrontToBackLayersGiveTheFrontOne) {
  std::vector<Layer> layers;
  for (int i = 0; i < 6; ++i) layers.push_back(full_screen(-4.0f - i, {0.15f * i, 1, 0, 1}));
  FrameStats stats;
  Framebuffer fb = draw_layers(layers, &stats);
  Framebuffer front = draw_layers({layers.front()}, nullptr);
  EXPECT_EQ(fb.rgba8(), front.rgba8());
  EXPECT_EQ(fb.depth(), front.depth());
  EXPECT_EQ(stats.pixels_shaded, std::uint64_t{kWidth} * kHeight);
}

TEST(Occlusion, NearerSurfacesDrawnEarlierStayVisible) {
  // A small near quad first, then a full-screen far one, then a tilted full-screen one that
  // is nearer than the small quad on its left and farther on its right.
  Layer small{soup_quad(-0.5f, -0.5f, 0.5f, 0.5f, -3.0f), {1, 0, 0, 1}};
  Layer far_wall = full_screen(-20.0f, {0, 0, 1, 1});
  Layer tilted{soup({{-40, -40, -1.0f},
                     {40, -40, -30.0f},
                     {40, 40, -30.0f},
                     {-40, -40, -1.0f},
                     {40, 40, -30.0f},
                     {-40, 40, -1.0f}}),
               {0, 1, 0, 1}};
  Framebuffer fb = draw_layers({small, far_wall, tilted}, nullptr);
  // The same picture drawn nearest-first can hide nothing early (no later triangle is nearer).
  Framebuffer expected = draw_layers({tilted, small, far_wall}, nullptr);
  EXPECT_EQ(fb.rgba8(), expected.rgba8());
  EXPECT_EQ(fb.depth(), expected.depth());
  // And the small red quad does show somewhere (the comparison is not between empty images).
  bool red = false;
  for (std::size_t i = 0; i < fb.rgba8().size(); i += 4) red |= fb.rgba8()[i] == 255;
  EXPECT_TRUE(red);
}

// A layered scene in two orders, nearest last (what the bin skipping acts on) and nearest first
// (where nothing can be skipped): with every layer at its own depth, the images must agree.
// Frame sizes that leave partial tiles, the smallest, the default and the largest tile size (the
// last two look for hidden work per block in bins this small), and layers of
// every kind the skipping must respect: alpha-masked, lines, and plain opaque.
TEST(Occlusion, LayerOrderDoesNotMatterWithMaskedLayersLinesAndPartialTiles) {
  constexpr int kOddWidth = 203, kOddHeight = 117;
  Mesh far_wall = soup_quad(-100, -100, 100, 100, -30.0f);
  // A masked layer whose vertex alpha runs from 0 to 1: the left part is cut out.
  Mesh masked = soup_quad(-30, -30, 30, 30, -20.0f);
  masked.colors = {{1, 1, 1, 0}, {1, 1, 1, 1}, {1, 1, 1, 1},
                   {1, 1, 1, 0}, {1, 1, 1, 1}, {1, 1, 1, 0}};
  Mesh lines;
  lines.topology = Topology::lines;
  // Behind both front layers everywhere (a line level with a surface wins by its depth bias
  // when drawn second, so the two orders would differ for reasons of their own).
  lines.positions = {{-20, -5, -27}, {20, 5, -27}, {-20, 5, -27}, {20, -5, -27}};
  Mesh front = soup_quad(-40, -40, 40, 40, -5.0f);
  // Tilted: nearer than everything at the left, but not in front of all of it to the right.
  Mesh tilted = soup({{-40, -40, -4.0f},
                      {40, -40, -25.0f},
                      {40, 40, -25.0f},
                      {-40, -40, -4.0f},
                      {40, 40, -25.0f},
                      {-40, 40, -4.0f}});
  auto material = [](glm::vec4 color, AlphaMode alpha) {
    Material m;
    m.shading = ShadingModel::unlit;
    m.base_color = color;
    m.alpha_mode = alpha;
    m.use_vertex_colors = true;
    return m;
  };
  const Material wall_m = material({0, 0, 1, 1}, AlphaMode::opaque);
  const Material masked_m = material({1, 0, 0, 1}, AlphaMode::mask);
  const Material lines_m = material({1, 1, 0, 1}, AlphaMode::opaque);
  const Material front_m = material({0, 1, 0, 1}, AlphaMode::opaque);
  for (const Mesh* last : {&front, &tilted}) {
    for (int tile : {16, 64, 128}) {
      RenderSettings settings;
      settings.tile_size = tile;
      auto render = [&](bool nearest_last) {
        Renderer renderer(settings);
        Framebuffer fb(kOddWidth, kOddHeight);
        renderer.begin_frame(test_camera(kOddWidth, kOddHeight));
        if (!nearest_last) renderer.draw(*last, front_m);
        renderer.draw(far_wall, wall_m);
        renderer.draw(masked, masked_m);
        renderer.draw(lines, lines_m);
        if (nearest_last) renderer.draw(*last, front_m);
        renderer.finish(fb);
        return fb;
      };
      Framebuffer nearest_last = render(true), nearest_first = render(false);
      ASSERT_EQ(nearest_last.rgba8(), nearest_first.rgba8()) << "tile " << tile;
      ASSERT_EQ(nearest_last.depth(), nearest_first.depth()) << "tile " << tile;
    }
  }
}

// A tile whose first triangle writes all its pixels is not cleared to the clear color
// (occlusion.hpp's hides_clear); wherever a pixel is left, the clear must show. One large
// triangle, drawn by one thread whose tile buffers go from tile to tile: the tiles its long edge
// crosses lie inside its box, and their pixels beside it must hold the clear color and depth,
// not what the last tile left there. Coverage from the overdraw counter (which always clears).
TEST(Occlusion, ClearShowsBesideAFirstTriangleThatFillsItsBoxOnly) {
  const Mesh triangle = soup({{-40, -40, -5.0f}, {40, -40, -5.0f}, {-40, 40, -5.0f}});
  const Camera camera = test_camera(kWidth, kHeight);
  const std::vector<int> covered = coverage_counts({&triangle}, camera, kWidth, kHeight);
  RenderSettings settings;
  settings.tile_size = 16;
  settings.threads = 1;
  settings.clear_color = {0.0f, 0.0f, 1.0f, 1.0f};
  const Framebuffer fb =
      render_unlit({&triangle}, camera, kWidth, kHeight, CullMode::none, settings);
  int inside = 0, outside = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const std::uint8_t* rgba = &fb.rgba8()[4 * i];
    if (covered[i] > 0) {
      ASSERT_EQ(rgba[0], 255) << "pixel " << i;  // render_unlit's white
      ASSERT_LT(fb.depth()[i], 1.0f) << "pixel " << i;
      ++inside;
    } else {
      ASSERT_EQ(rgba[0], 0) << "pixel " << i;
      ASSERT_EQ(rgba[2], 255) << "pixel " << i;
      ASSERT_EQ(fb.depth()[i], 1.0f) << "pixel " << i;
      ++outside;
    }
  }
  // Both halves of the frame are there to compare.
  EXPECT_GT(inside, kWidth * kHeight / 3);
  EXPECT_GT(outside, kWidth * kHeight / 3);
}

// Binning notes the tiles a triangle may hide whole (Frame::bin_may_hide) from its pixel box:
// the box must hold a whole tile, partial tiles at the frame's right and bottom edges included.
TEST(Occlusion, BoxHoldsATileExactlyWhenItHoldsAWholeOne) {
  pipeline::Frame frame;
  frame.tile_size = 16;
  frame.width = 203;  // 12 whole tiles and one of 11 pixels per row
  frame.height = 40;  // two whole tile rows and one of 8 pixels
  auto holds = [&](int x0, int y0, int x1, int y1) {
    return pipeline::box_holds_a_tile(frame, x0, y0, x1, y1);
  };
  EXPECT_TRUE(holds(0, 0, 15, 15));      // exactly tile (0, 0)
  EXPECT_FALSE(holds(0, 0, 14, 15));     // a column short
  EXPECT_FALSE(holds(1, 0, 16, 15));     // straddles two tiles, holds neither
  EXPECT_TRUE(holds(1, 1, 32, 32));      // tile (1, 1) inside
  EXPECT_FALSE(holds(1, 1, 30, 40));     // 30 columns, but no whole tile across
  EXPECT_TRUE(holds(192, 32, 202, 39));  // the partial corner tile, whole
  EXPECT_FALSE(holds(193, 32, 202, 39));
  EXPECT_FALSE(holds(192, 33, 202, 39));
  EXPECT_TRUE(holds(150, 20, 202, 39));  // ending at the frame's corner
}

// The per-block look is for bins of a few large triangles: at most one entry per 16 x 16 pixels
// of the tile, whatever its size, so a bin of many small triangles skips it.
TEST(Occlusion, BlockLookIsForBinsOfFewEntriesForTheirTile) {
  EXPECT_TRUE(pipeline::looks_per_block(16, 64 * 64));  // eight quads, two triangles each
  EXPECT_FALSE(pipeline::looks_per_block(17, 64 * 64));
  EXPECT_TRUE(pipeline::looks_per_block(64, 128 * 128));
  EXPECT_FALSE(pipeline::looks_per_block(65, 128 * 128));
  EXPECT_TRUE(pipeline::looks_per_block(7, 64 * 30));  // a partial tile at the frame's edge
  EXPECT_FALSE(pipeline::looks_per_block(8, 64 * 30));
}

}  // namespace
}  // namespace facet::test
