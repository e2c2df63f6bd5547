// Stage: raster, the SIMD part (see block_raster.hpp). Highway compiles this file once per SIMD
// target (foreach_target.h re-includes it) and HWY_DYNAMIC_DISPATCH picks the best target the
// CPU has at the first call; tests force each target in turn and expect identical images.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/block_raster.cpp"
#include "pipeline/block_raster.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include "pipeline/setup.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A block row is 8 pixels: one vector on AVX2 and AVX-512 (which then uses 256-bit vectors),
// two on SSE4 and on EMU128 (Highway's portable fallback, plain C++ on four-lane arrays).
using FloatTag = hn::CappedTag<float, kBlockSize>;
using IntTag = hn::RebindToSigned<FloatTag>;

void CoverBlock(const BlockInput& in, BlockFragments& out) {
  const FloatTag df;
  const IntTag di;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const SetupTriangle& t = *in.triangle;
  const auto zero = hn::Zero(di);
  const auto x_begin = hn::Set(di, in.x_begin), x_end = hn::Set(di, in.x_end);
  float varying_rows[kMaxVaryings];
  std::uint64_t mask = 0;
  for (int y = in.y_begin; y < in.y_end; ++y) {
    // Per-row plane values, exactly as evaluate_row() computes them for the scalar path; only
    // once a pixel of the row is covered (depth), and passes the depth test (the others): in a
    // partly covered block, many rows have none.
    const float py = in.py0 + static_cast<float>(y);
    bool have_z_row = false, have_rows = false;
    float z_row = 0.0f, inv_w_row = 0.0f;
    const float* depth_row = in.depth + static_cast<std::ptrdiff_t>(y) * in.depth_stride;
    for (int x = 0; x < kBlockSize; x += lanes) {
      const auto column = hn::Iota(di, x);
      // Outside some edge when any of the three is negative: test the sign of their OR.
      auto edges = hn::Set(di, 0);
      for (int i = 0; i < 3; ++i) {
        const auto e =
            hn::Add(hn::Set(di, in.e[i] + in.b[i] * y), hn::Mul(hn::Set(di, in.a[i]), column));
        edges = hn::Or(edges, e);
      }
      const auto inside = hn::AndNot(
          hn::Lt(edges, zero), hn::And(hn::Not(hn::Lt(column, x_begin)), hn::Lt(column, x_end)));
      auto pass = hn::RebindMask(df, inside);
      if (hn::AllFalse(df, pass)) continue;
      if (!have_z_row) z_row = evaluate_row(t.z, t.ref_y, py), have_z_row = true;
      const int lane0 = y * kBlockSize + x;
      // (px - ref_x), then plane = row + dx * (px - ref_x): evaluate_in_row() lane by lane.
      const auto relative_x =
          hn::Sub(hn::Iota(df, in.px0 + static_cast<float>(x)), hn::Set(df, t.ref_x));
      const auto z = hn::Add(hn::Set(df, z_row), hn::Mul(hn::Set(df, t.z.dx), relative_x));
      if (in.depth_test) {
        pass = hn::And(pass, hn::Lt(z, hn::LoadU(df, depth_row + x)));  // NaN fails
        if (hn::AllFalse(df, pass)) continue;
      }
      if (!in.interpolate) {
        std::uint8_t bits = 0;
        hn::StoreMaskBits(df, pass, &bits);
        mask |= static_cast<std::uint64_t>(bits) << lane0;
        hn::Store(z, df, out.z + lane0);
        continue;
      }
      if (!have_rows) {
        inv_w_row = evaluate_row(t.inv_w, t.ref_y, py);
        for (int k = 0; k < in.varyings; ++k) {
          varying_rows[k] = evaluate_row(in.varying_planes[k], t.ref_y, py);
        }
        have_rows = true;
      }
      std::uint8_t bits = 0;
      hn::StoreMaskBits(df, pass, &bits);
      mask |= static_cast<std::uint64_t>(bits) << lane0;
      hn::Store(z, df, out.z + lane0);
      const auto inv_w =
          hn::Add(hn::Set(df, inv_w_row), hn::Mul(hn::Set(df, t.inv_w.dx), relative_x));
      const auto w = hn::Div(hn::Set(df, 1.0f), inv_w);
      hn::Store(w, df, out.w + lane0);
      for (int k = 0; k < in.varyings; ++k) {
        const auto v_over_w = hn::Add(hn::Set(df, varying_rows[k]),
                                      hn::Mul(hn::Set(df, in.varying_planes[k].dx), relative_x));
        hn::Store(hn::Mul(v_over_w, w), df, out.v[k] + lane0);
      }
    }
  }
  out.mask = mask;
}

void InterpolatePixels(const SetupTriangle& t, const Plane* planes, int varyings, int first,
                       int count, const std::int16_t* xs, const std::int16_t* ys, float* w,
                       float (*v)[kBlockPixels]) {
  const FloatTag df;
  const IntTag di;
  const hn::Rebind<std::int16_t, FloatTag> d16;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const auto half = hn::Set(df, 0.5f);
  for (int j = first; j < first + count; j += lanes) {
    // (p - ref) of the pixel centres, as evaluate_row / evaluate_in_row take them.
    const auto px = hn::Add(hn::ConvertTo(df, hn::PromoteTo(di, hn::LoadU(d16, xs + j))), half);
    const auto py = hn::Add(hn::ConvertTo(df, hn::PromoteTo(di, hn::LoadU(d16, ys + j))), half);
    const auto relative_x = hn::Sub(px, hn::Set(df, t.ref_x));
    const auto relative_y = hn::Sub(py, hn::Set(df, t.ref_y));
    auto evaluate = [&](const Plane& p) HWY_ATTR {
      const auto row = hn::Add(hn::Set(df, p.at_ref), hn::Mul(hn::Set(df, p.dy), relative_y));
      return hn::Add(row, hn::Mul(hn::Set(df, p.dx), relative_x));
    };
    const auto clip_w = hn::Div(hn::Set(df, 1.0f), evaluate(t.inv_w));
    hn::StoreU(clip_w, df, w + j);
    for (int k = 0; k < varyings; ++k)
      hn::StoreU(hn::Mul(evaluate(planes[k]), clip_w), df, v[k] + j);
  }
}

const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(CoverBlock);
HWY_EXPORT(TargetName);
HWY_EXPORT(InterpolatePixels);

void interpolate_pixels(const SetupTriangle& t, const Plane* varying_planes, int varyings,
                        int first, int count, const std::int16_t* x, const std::int16_t* y,
                        float* w, float (*v)[kBlockPixels]) {
  HWY_DYNAMIC_DISPATCH(InterpolatePixels)(t, varying_planes, varyings, first, count, x, y, w, v);
}

void cover_block(const BlockInput& in, BlockFragments& out) {
  HWY_DYNAMIC_DISPATCH(CoverBlock)(in, out);
}

const char* simd_target_name() { return HWY_DYNAMIC_DISPATCH(TargetName)(); }

}  // namespace facet::pipeline
#endif  // HWY_ONCE
