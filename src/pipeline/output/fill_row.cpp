// Stage: output, filling a row with one value (see fill_row.hpp). Highway compiles this file
// once per SIMD target; the frame fetches the chosen target's kernels (pipeline/kernels.hpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/output/fill_row.cpp"
#include "pipeline/output/fill_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Whole vectors, then the last few entries one at a time.
void FillFloatRow(float* out, std::ptrdiff_t count, float value) {
  const hn::ScalableTag<float> d;
  const std::ptrdiff_t lanes = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  const auto v = hn::Set(d, value);
  std::ptrdiff_t i = 0;
  for (; i + lanes <= count; i += lanes) hn::StoreU(v, d, out + i);
  for (; i < count; ++i) out[i] = value;
}

// As FillFloatRow, over the colors' channels: every vector of four or more lanes holds whole
// colors (a vector of fewer, HWY_SCALAR's, is one channel, and lanes divide 4).
void FillColorRow(glm::vec4* out, std::ptrdiff_t count, const glm::vec4& value) {
  const hn::ScalableTag<float> d;
  const std::ptrdiff_t lanes = static_cast<std::ptrdiff_t>(hn::Lanes(d));
  float* channels = &out[0].x;
  const std::ptrdiff_t total = count * 4;
  std::ptrdiff_t i = 0;
  if (lanes >= 4) {
    alignas(16) const float color[4] = {value.r, value.g, value.b, value.a};
    const auto v = hn::LoadDup128(d, color);
    for (; i + lanes <= total; i += lanes) hn::StoreU(v, d, channels + i);
  }
  for (; i < total; ++i) channels[i] = value[static_cast<int>(i % 4)];
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(FillFloatRow);
HWY_EXPORT(FillColorRow);

FillFloatRowKernel fill_float_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(FillFloatRow)[target];
}

FillColorRowKernel fill_color_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(FillColorRow)[target];
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
