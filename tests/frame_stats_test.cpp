// The frame's timings (FrameStats) add up: each stage within the frame, the resolve a part of
// raster + shade + resolve, measured from the tiles' own timings (renderer_impl.hpp's tick
// counts), whatever the thread count.
#include <gtest/gtest.h>

#include "facet/renderer.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

TEST(FrameStats, TheResolveIsAPartOfTheRasterAndEveryStageOfTheFrame) {
  for (int threads : {1, 3}) {
    RenderSettings settings;
    settings.threads = threads;
    Renderer renderer(settings);
    Material material;
    material.shading = ShadingModel::unlit;
    // A quad amid empty tiles: some tiles resolve what was drawn, the others their clear.
    const Mesh quad = soup_quad(-0.5f, -0.5f, 0.5f, 0.5f, -5.0f);
    Framebuffer target(640, 480);
    renderer.begin_frame(test_camera(640, 480), Lighting{});
    renderer.draw(quad, material);
    renderer.finish(target);
    const FrameStats& stats = renderer.stats();
    EXPECT_GT(stats.ms_resolve, 0.0) << threads << " threads";
    EXPECT_LT(stats.ms_resolve, stats.ms_raster) << threads << " threads";
    EXPECT_LE(stats.ms_geometry + stats.ms_binning + stats.ms_raster, stats.ms_total)
        << threads << " threads";
  }
}

}  // namespace
}  // namespace facet::test
