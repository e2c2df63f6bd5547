// Float to int32 conversion, truncating, of values known to lie within int32's range: the one
// x86 instruction (cvttps2dq). Highway 1.0.3's ConvertTo adds four instructions after it to turn
// a too large value's 0x80000000 into 0x7FFFFFFF; where no value is that large they do nothing
// but cost, in inner loops such as the sampler's and the encoders'. Included
// inside each file's HWY_NAMESPACE, once per target, the Highway "-inl.h" way (the guard below
// toggles with HWY_TARGET_TOGGLE). The same bits as ConvertTo for every value in range, on every
// target: the portable ones use ConvertTo itself.
#if defined(FACET_CORE_TRUNCATE_IN_RANGE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_CORE_TRUNCATE_IN_RANGE_INL_H_
#undef FACET_CORE_TRUNCATE_IN_RANGE_INL_H_
#else
#define FACET_CORE_TRUNCATE_IN_RANGE_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace facet::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// static_cast<std::int32_t> of each lane of v (DI's float vector), every lane within
// [-2^31, 2^31).
template <class DI, class VF>
HWY_INLINE hn::Vec<DI> TruncateInRange(DI di, VF v) {
  static_assert(sizeof(hn::TFromD<DI>) == 4);
  static_assert(std::is_same_v<VF, hn::Vec<hn::RebindToFloat<DI>>>);
#if HWY_ARCH_X86 && HWY_TARGET != HWY_EMU128 && HWY_TARGET != HWY_SCALAR
  constexpr std::size_t kBytes = hn::MaxLanes(di) * 4;
  if constexpr (kBytes == 64) {
#if HWY_TARGET <= HWY_AVX3
    return hn::Vec<DI>{_mm512_cvttps_epi32(v.raw)};
#endif
  } else if constexpr (kBytes == 32) {
#if HWY_TARGET <= HWY_AVX2
    return hn::Vec<DI>{_mm256_cvttps_epi32(v.raw)};
#endif
  } else {
    return hn::Vec<DI>{_mm_cvttps_epi32(v.raw)};
  }
#endif
  return hn::ConvertTo(di, v);
}

}  // namespace facet::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_CORE_TRUNCATE_IN_RANGE_INL_H_
