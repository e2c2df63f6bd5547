// Stage: output, tone mapping a row at a time (see tone_map_row.hpp). Highway compiles this file
// once per SIMD target; the frame fetches the chosen target's kernel (pipeline/kernels.hpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/output/tone_map_row.cpp"
#include "pipeline/output/tone_map_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using FloatTag = hn::ScalableTag<float>;
using Vec = hn::Vec<FloatTag>;

// Floats in the widest vector of any target.
constexpr int kMaxFloatLanes = HWY_MAX_BYTES / sizeof(float);

struct Rgb {
  Vec r, g, b;
};

// x * (1 - t) + y * t, as GLSL's mix.
HWY_INLINE Vec Mix(FloatTag df, Vec x, Vec y, Vec t) {
  return hn::Add(hn::Mul(x, hn::Sub(hn::Set(df, 1.0f), t)), hn::Mul(y, t));
}

// Khronos PBR Neutral (github.com/KhronosGroup/ToneMapping, PBR_Neutral): colors whose
// brightest channel stays under 0.76 keep their hue and value (less a small offset that
// darkens the deepest shadows a little, at most 0.04); brighter ones are compressed toward
// white, desaturating as they go, and reach it only at infinity.
HWY_INLINE Rgb PbrNeutral(FloatTag df, Rgb c) {
  constexpr float kStart = 0.8f - 0.04f, kDesaturation = 0.15f, kD = 1.0f - kStart;
  const Vec toe_end = hn::Set(df, 0.08f);
  const Vec lowest = hn::Min(c.r, hn::Min(c.g, c.b));
  const Vec toe = hn::Sub(lowest, hn::Mul(hn::Mul(hn::Set(df, 6.25f), lowest), lowest));
  const Vec offset = hn::IfThenElse(hn::Lt(lowest, toe_end), toe, hn::Set(df, 0.04f));
  c = {hn::Sub(c.r, offset), hn::Sub(c.g, offset), hn::Sub(c.b, offset)};
  const Vec peak = hn::Max(c.r, hn::Max(c.g, c.b));
  const auto compressed = hn::Ge(peak, hn::Set(df, kStart));
  // Most of an image lies below the knee: such vectors skip the compression, whose lanes they
  // would not take anyway.
  if (hn::AllFalse(df, compressed)) return c;
  // Below the start the divisions are not used: their divisor is kept away from zero.
  const Vec safe_peak = hn::Max(peak, hn::Set(df, kStart));
  const Vec one = hn::Set(df, 1.0f);
  const Vec new_peak =
      hn::Sub(one, hn::Div(hn::Set(df, kD * kD),
                           hn::Sub(hn::Add(safe_peak, hn::Set(df, kD)), hn::Set(df, kStart))));
  const Vec ratio = hn::Div(new_peak, safe_peak);
  const Vec fade = hn::Sub(
      one, hn::Div(one, hn::Add(hn::Mul(hn::Set(df, kDesaturation), hn::Sub(safe_peak, new_peak)),
                                one)));
  const auto map = [&](Vec v) {
    return hn::IfThenElse(compressed, Mix(df, hn::Mul(v, ratio), new_peak, fade), v);
  };
  return {map(c.r), map(c.g), map(c.b)};
}

// ACES filmic, Stephen Hill's fit of the ACES reference rendering and sRGB output transforms
// (github.com/TheRealMJP/BakingLab, ACES.hlsl), with the 1 / 0.6 exposure three.js and the
// Khronos glTF viewer give it so that mid grey stays near mid grey. Contrast rises and
// saturated highlights shift toward white; values are clamped to [0, 1].
HWY_INLINE Rgb AcesFilmic(FloatTag df, Rgb c) {
  // The input transform (sRGB to the fit's space) with the 1 / 0.6 folded in would round
  // differently from applying them in turn, which is what is documented: both are applied.
  const Vec boost = hn::Set(df, 1.0f / 0.6f);
  c = {hn::Mul(c.r, boost), hn::Mul(c.g, boost), hn::Mul(c.b, boost)};
  const auto row = [&](float x, float y, float z, const Rgb& v) {
    return hn::Add(hn::Add(hn::Mul(hn::Set(df, x), v.r), hn::Mul(hn::Set(df, y), v.g)),
                   hn::Mul(hn::Set(df, z), v.b));
  };
  const Rgb in{row(0.59719f, 0.35458f, 0.04823f, c), row(0.07600f, 0.90834f, 0.01566f, c),
               row(0.02840f, 0.13383f, 0.83777f, c)};
  const auto fit = [&](Vec v) {
    const Vec a =
        hn::Sub(hn::Mul(v, hn::Add(v, hn::Set(df, 0.0245786f))), hn::Set(df, 0.000090537f));
    const Vec b =
        hn::Add(hn::Mul(v, hn::Add(hn::Mul(hn::Set(df, 0.983729f), v), hn::Set(df, 0.4329510f))),
                hn::Set(df, 0.238081f));
    return hn::Div(a, b);
  };
  const Rgb fitted{fit(in.r), fit(in.g), fit(in.b)};
  const auto clamp = [&](Vec v) { return hn::Min(hn::Max(v, hn::Zero(df)), hn::Set(df, 1.0f)); };
  return {clamp(row(1.60475f, -0.53108f, -0.07367f, fitted)),
          clamp(row(-0.10208f, 1.10813f, -0.00605f, fitted)),
          clamp(row(-0.00327f, -0.07276f, 1.07602f, fitted))};
}

void ToneMapRow(ToneMapping curve, const glm::vec4* colors, const float* depth, float clear_depth,
                int count, float scale, glm::vec4* out) {
  const FloatTag df;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const Vec factor = hn::Set(df, scale), zero = hn::Zero(df), largest = hn::Set(df, 65504.0f);
  const Vec clear = hn::Set(df, clear_depth);
  // The colors left after the whole vectors are mapped from copies padded with zeros, into a
  // buffer of which only their own values are kept: every color goes through the same lanes.
  alignas(64) float padded_in[4 * kMaxFloatLanes];
  alignas(64) float padded_out[4 * kMaxFloatLanes];
  alignas(64) float padded_depth[kMaxFloatLanes];
  for (int first = 0; first < count; first += lanes) {
    const int n = std::min(lanes, count - first);
    const float* in = &colors[first].x;
    float* to = &out[first].x;
    const float* z = depth != nullptr ? depth + first : nullptr;
    if (n < lanes) {
      std::fill(std::copy_n(in, 4 * n, padded_in), padded_in + 4 * lanes, 0.0f);
      in = padded_in, to = padded_out;
      if (z != nullptr) {
        std::fill(std::copy_n(z, n, padded_depth), padded_depth + lanes, 0.0f);
        z = padded_depth;
      }
    }
    Vec r, g, b, a;
    hn::LoadInterleaved4(df, in, r, g, b, a);
    const Rgb scaled{hn::Mul(r, factor), hn::Mul(g, factor), hn::Mul(b, factor)};
    const auto sane = [&](Vec v) {
      return hn::Min(hn::IfThenElseZero(hn::Gt(v, zero), v), largest);
    };
    const Rgb c{sane(scaled.r), sane(scaled.g), sane(scaled.b)};
    Rgb mapped = curve == ToneMapping::aces ? AcesFilmic(df, c) : PbrNeutral(df, c);
    if (z != nullptr) {
      const auto nothing_drawn = hn::Eq(hn::LoadU(df, z), clear);
      mapped = {hn::IfThenElse(nothing_drawn, scaled.r, mapped.r),
                hn::IfThenElse(nothing_drawn, scaled.g, mapped.g),
                hn::IfThenElse(nothing_drawn, scaled.b, mapped.b)};
    }
    hn::StoreInterleaved4(mapped.r, mapped.g, mapped.b, a, df, to);
    if (n < lanes) std::copy_n(padded_out, 4 * n, &out[first].x);
  }
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(ToneMapRow);

ToneMapRowKernel tone_map_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(ToneMapRow)[target];
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
