// Stage: output, the environment behind the scene a row at a time (see sky_row.hpp). Highway
// compiles this file once per SIMD target; the frame fetches the chosen target's kernel
// (pipeline/kernels.hpp). The view directions follow glm's operation order, as the scalar
// statement in tests/support/sky_reference.hpp does: glm's mat4 x vec4 is (m0 x + m1 y) +
// (m2 z + m3 w), normalize is v * (1 / sqrt(dot)); no fused multiply-add.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/output/sky_row.cpp"
#include "pipeline/output/sky_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstdint>

#include "shading/environment.hpp"
#include "shading/sky_gradient-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using FloatTag = hn::CappedTag<float, 8>;
using FloatV = hn::Vec<FloatTag>;

void FillSkyRow(const SkyView& view, const Environment& env, SampleAtKernel sample_at, int x0,
                int y, int count, const float* depth, float clear_depth, glm::vec4* colors) {
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const glm::mat4& m = view.inverse_view_projection;
  const float width = static_cast<float>(view.width);
  const float ndc_y =
      1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(view.height) * 2.0f;
  // The parts of m x (ndc_x, ndc_y, 1, 1) that do not depend on x: m1 ndc_y and m2 + m3.
  float with_y[4], constant[4];
  for (int c = 0; c < 4; ++c) {
    with_y[c] = m[1][c] * ndc_y;
    constant[c] = m[2][c] * 1.0f + m[3][c] * 1.0f;
  }
  const FloatV one = hn::Set(d, 1.0f);
  alignas(32) float rgb[3][8];
  // Highway's Iota builds its lanes in memory: once, not in the loop. Whole numbers below 2^24
  // add exactly, so x0 + i + lane is the same float either way.
  const FloatV lane = hn::Iota(d, 0.0f);
  // The view directions' upward components, a pass of their own before the procedural sky's
  // colors: there the CPU overlaps the vectors' chains of divisions and square roots.
  alignas(32) float up[kMaxSkyRow + 8];
  std::uint8_t shows[kMaxSkyRow];  // per vector: 0 no sky, 1 some, 2 all
  for (int i = 0; i < count; i += lanes) {
    // Only where something shows the sky: its divisions and square roots are most of a
    // covered pixel's cost otherwise.
    bool shows_sky = false, all_sky = false;
    if (i + lanes <= count) {
      const auto sky = hn::Eq(hn::LoadU(d, depth + i), hn::Set(d, clear_depth));
      shows_sky = !hn::AllFalse(d, sky);
      all_sky = hn::AllTrue(d, sky);
    } else {
      for (int k = i; k < count; ++k) shows_sky |= depth[k] == clear_depth;
    }
    shows[i / lanes] = all_sky ? 2 : shows_sky ? 1 : 0;
    if (!shows_sky) continue;
    // ndc_x = (x + 0.5) / width * 2 - 1
    const FloatV x = hn::Add(lane, hn::Set(d, static_cast<float>(x0 + i)));
    const FloatV ndc_x = hn::Sub(
        hn::Mul(hn::Div(hn::Add(x, hn::Set(d, 0.5f)), hn::Set(d, width)), hn::Set(d, 2.0f)), one);
    FloatV far[4];
    for (int c = 0; c < 4; ++c) {
      far[c] = hn::Add(hn::Add(hn::Mul(hn::Set(d, m[0][c]), ndc_x), hn::Set(d, with_y[c])),
                       hn::Set(d, constant[c]));
    }
    FloatV dir[3];
    for (int c = 0; c < 3; ++c) {
      dir[c] = hn::Sub(hn::Div(far[c], far[3]), hn::Set(d, view.eye[c]));
    }
    const FloatV length_squared =
        hn::Add(hn::Add(hn::Mul(dir[0], dir[0]), hn::Mul(dir[1], dir[1])), hn::Mul(dir[2], dir[2]));
    const FloatV inverse_length = hn::Div(one, hn::Sqrt(length_squared));
    if (env.image) {  // unit directions, then the image's texels for the pixels it shows in
      alignas(32) float unit[3][8];
      for (int c = 0; c < 3; ++c) hn::Store(hn::Mul(dir[c], inverse_length), d, unit[c]);
      const int active = std::min(lanes, count - i);
      glm::vec3 directions[8], radiance[8];
      int shown[8], showing = 0;
      for (int k = 0; k < active; ++k) {
        if (depth[i + k] != clear_depth) continue;  // drawn over
        directions[showing] = {unit[0][k], unit[1][k], unit[2][k]};
        shown[showing++] = i + k;
      }
      static constexpr float kBaseLevel[8] = {};
      shading::image_radiance(sample_at, env, directions, kBaseLevel, showing, radiance);
      for (int n = 0; n < showing; ++n) colors[shown[n]] = glm::vec4(radiance[n], 1.0f);
      continue;
    }
    hn::Store(hn::Mul(dir[1], inverse_length), d, up + i);
  }
  if (env.image) return;
  for (int i = 0; i < count; i += lanes) {
    const int kind = shows[i / lanes];
    if (kind == 0) continue;
    FloatV color[3];
    shading::HWY_NAMESPACE::SkyRadiance(d, env, hn::Load(d, up + i), color);
    if (kind == 2) {  // most of the sky: whole vectors of it, stored as (r, g, b, 1) colors
      hn::StoreInterleaved4(color[0], color[1], color[2], one, d, &colors[i].r);
      continue;
    }
    for (int c = 0; c < 3; ++c) hn::Store(color[c], d, rgb[c]);
    const int active = std::min(lanes, count - i);
    for (int k = 0; k < active; ++k) {
      if (depth[i + k] != clear_depth) continue;  // drawn over
      glm::vec4& out = colors[i + k];
      out.r = rgb[0][k];
      out.g = rgb[1][k];
      out.b = rgb[2][k];
      out.a = 1.0f;
    }
  }
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(FillSkyRow);

SkyRowKernel sky_row_kernel(SimdTarget target) { return HWY_DISPATCH_TABLE(FillSkyRow)[target]; }

}  // namespace facet::pipeline
#endif  // HWY_ONCE
