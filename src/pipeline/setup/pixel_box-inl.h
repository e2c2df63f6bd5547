// Per-target pixel boxes of triangles a lane each, shared by the SIMD kernels that compute them
// (setup_batch.cpp, and cull_batch.cpp, which drops the triangles whose box is empty before
// setup): included inside each file's HWY_NAMESPACE, once per target, the Highway "-inl.h" way
// (the guard below toggles with HWY_TARGET_TOGGLE). The same centres as setup.hpp's
// first_centre_at_or_after and last_centre_at_or_before.
#if defined(FACET_PIPELINE_PIXEL_BOX_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_PIPELINE_PIXEL_BOX_INL_H_
#undef FACET_PIPELINE_PIXEL_BOX_INL_H_
#else
#define FACET_PIPELINE_PIXEL_BOX_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>

#include "pipeline/setup/fixed_point.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Along one axis, the pixels [first, last] whose centres (under MSAA: some sample, up to `reach`
// fixed-point units from the centre) a span [lo, hi] of fixed-point coordinates may cover,
// clamped to [0, last_pixel]; first > last when there are none. Coordinates lie in the guard
// band, so the sums stay inside 32 bits.
template <class D>
struct PixelSpans {
  hn::Vec<D> first, last;
};
template <class D>
HWY_INLINE PixelSpans<D> SpanPixels(D d, hn::Vec<D> lo, hn::Vec<D> hi, hn::Vec<D> reach,
                                    hn::Vec<D> last_pixel) {
  // First centre at or after lo - reach: floor((lo - reach + 127) / 256); last at or before
  // hi + reach: floor((hi + reach - 128) / 256).
  const auto first = hn::ShiftRight<kSubpixelBits>(
      hn::Add(hn::Sub(lo, reach), hn::Set(d, kSubpixelScale - 1 - kHalfPixel)));
  const auto last =
      hn::ShiftRight<kSubpixelBits>(hn::Sub(hn::Add(hi, reach), hn::Set(d, kHalfPixel)));
  return {hn::Max(hn::Zero(d), first), hn::Min(last_pixel, last)};
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_PIPELINE_PIXEL_BOX_INL_H_
