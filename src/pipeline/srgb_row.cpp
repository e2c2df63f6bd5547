// Stage: output, sRGB encoding a row at a time (see srgb_row.hpp). Highway compiles this file
// once per SIMD target; HWY_DYNAMIC_DISPATCH picks the best the CPU has.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/srgb_row.cpp"
#include "pipeline/srgb_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>

#include "shading/color.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using FloatTag = hn::ScalableTag<float>;
using IntTag = hn::RebindToSigned<FloatTag>;

// Colors per step: the SIMD pass fills arrays for this many, then the lookups read them.
constexpr int kChunk = 64;

void EncodeSrgbRow(const glm::vec4* colors, int count, float scale, std::uint8_t* rgba) {
  const FloatTag df;
  const IntTag di;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const shading::SrgbTables& tables = shading::srgb_tables();
  constexpr float kBuckets = static_cast<float>(shading::SrgbTables::kBuckets);
  // Each channel's factor, (scale, scale, scale, 1) over and over: the exposure scales red,
  // green and blue, not alpha. A vector starting at float j reads it from j % 4 on, which
  // covers targets with fewer than four lanes.
  alignas(64) float factor[kChunk + 4];
  for (int j = 0; j < kChunk + 4; ++j) factor[j] = j % 4 == 3 ? 1.0f : scale;
  // Per channel: its value clamped to [0, 1] (NaN to 0), and its bucket (color.hpp).
  alignas(64) float clamped[4 * kChunk];
  alignas(64) std::int32_t bucket[4 * kChunk];
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), buckets = hn::Set(df, kBuckets);
  for (int first = 0; first < count; first += kChunk) {
    const int floats = 4 * std::min(kChunk, count - first);
    const float* in = &colors[first].x;
    int j = 0;
    for (; j + lanes <= floats; j += lanes) {
      const auto x = hn::Mul(hn::LoadU(df, in + j), hn::LoadU(df, factor + (j & 3)));
      const auto c = hn::Min(hn::IfThenElseZero(hn::Gt(x, zero), x), one);
      hn::Store(c, df, clamped + j);
      hn::Store(hn::ConvertTo(di, hn::Mul(c, buckets)), di, bucket + j);
    }
    for (; j < floats; ++j) {  // the last few, the same way
      const float x = in[j] * factor[j & 3];
      const float c = x > 0.0f ? std::min(x, 1.0f) : 0.0f;
      clamped[j] = c;
      bucket[j] = static_cast<std::int32_t>(c * kBuckets);
    }
    std::uint8_t* out = rgba + 4 * static_cast<std::ptrdiff_t>(first);
    for (int i = 0; i < floats; i += 4) {
      for (int k = i; k < i + 3; ++k) {  // the code at the bucket's start, or the next one
        const int code = tables.bucket_code[bucket[k]];
        out[k] = static_cast<std::uint8_t>(code + (clamped[k] >= tables.thresholds[code + 1]));
      }
      out[i + 3] = shading::unorm8_of_unit(clamped[i + 3]);
    }
  }
}

// Every channel as EncodeSrgbRow rounds alpha (shading::encode_unorm8), lane by lane.
void RoundUnorm8Row(const glm::vec4* colors, int count, std::uint8_t* rgba) {
  const FloatTag df;
  const IntTag di;
  const hn::Rebind<std::uint8_t, FloatTag> du8;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto codes = hn::Set(df, 255.0f), half = hn::Set(df, 0.5f);
  const float* in = &colors[0].x;
  const int floats = 4 * count;
  int j = 0;
  for (; j + lanes <= floats; j += lanes) {
    const auto x = hn::LoadU(df, in + j);
    const auto c = hn::Min(hn::IfThenElseZero(hn::Gt(x, zero), x), one);
    // A multiplication then an addition, not fused: the scalar rounding exactly.
    const auto code = hn::ConvertTo(di, hn::Add(hn::Mul(c, codes), half));
    hn::StoreU(hn::DemoteTo(du8, code), du8, rgba + j);
  }
  for (; j < floats; ++j) rgba[j] = shading::encode_unorm8(in[j]);
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(EncodeSrgbRow);
HWY_EXPORT(RoundUnorm8Row);

void encode_srgb_row(const glm::vec4* colors, int count, float scale, std::uint8_t* rgba) {
  HWY_DYNAMIC_DISPATCH(EncodeSrgbRow)(colors, count, scale, rgba);
}

void round_unorm8_row(const glm::vec4* colors, int count, std::uint8_t* rgba) {
  HWY_DYNAMIC_DISPATCH(RoundUnorm8Row)(colors, count, rgba);
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
