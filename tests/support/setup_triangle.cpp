// A triangle set up as raster receives it (see setup_triangle.hpp).
#include "support/setup_triangle.hpp"

#include "core/simd_target.hpp"
#include "pipeline/geometry/primitive_sink.hpp"
#include "pipeline/setup/setup_batch.hpp"

namespace facet::test {

bool set_up_triangle(const pipeline::ScreenVertex s[3], pipeline::SetupTriangle& out) {
  pipeline::Frame frame;
  frame.width = kSetupWidth, frame.height = kSetupHeight, frame.tile_size = 64;
  frame.tiles_x = kSetupWidth / 64 + 1, frame.tiles_y = kSetupHeight / 64 + 1;
  frame.triangles.resize(1);
  pipeline::GeometryChunk chunk;
  chunk.triangles = {0, 1, 0};
  pipeline::PrimitiveSink sink(frame, chunk, 0);
  pipeline::ProjectedVertex projected[3] = {};
  for (int i = 0; i < 3; ++i) projected[i].screen = s[i];
  const float no_varyings[pipeline::kOverWSlack] = {};
  const std::uint32_t index[3][1 + pipeline::kSetupBatchSlack] = {{0}, {1}, {2}};
  const std::uint32_t front[1 + pipeline::kSetupBatchSlack] = {
      pipeline::signed_area(s[0], s[1], s[2]) < 0 ? 1u : 0u};
  const pipeline::SetupBatch batch{1, {index[0], index[1], index[2]}, front};
  if (pipeline::setup_batch_kernel(chosen_simd_target())(
          batch, {sink, kSetupWidth, kSetupHeight, 0, projected, no_varyings, 0}))
    return false;
  out = frame.triangles[0];
  return true;
}

bool random_triangle(std::mt19937& rng, float size, float& cx, float& cy,
                     pipeline::SetupTriangle& out) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  cx = 100.0f + unit(rng) * (kSetupWidth - 200);
  cy = 100.0f + unit(rng) * (kSetupHeight - 200);
  pipeline::ScreenVertex s[3];
  for (auto& v : s) {
    v.x = pipeline::snap(cx + (unit(rng) - 0.5f) * size);
    v.y = pipeline::snap(cy + (unit(rng) - 0.5f) * size);
    v.z = unit(rng);
    v.inv_w = 1.0f;
  }
  return set_up_triangle(s, out);
}

}  // namespace facet::test
