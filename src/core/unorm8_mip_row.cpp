// 8-bit unorm mip rows (see unorm8_mip_row.hpp). Highway compiles this file once per SIMD
// target; callers fetch the chosen target's kernel.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/unorm8_mip_row.cpp"
#include "core/unorm8_mip_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <bit>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace facet::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One texel from two pairs: two source texels (8 bytes) are one 64-bit word, whose channels r, b
// and g, a are summed in 16-bit lanes (the largest sum, 1022, fits with room to spare).
HWY_INLINE std::uint32_t HalveTexel(const std::uint8_t* top, const std::uint8_t* bottom) {
  static_assert(std::endian::native == std::endian::little, "texels loaded as 64-bit words");
  constexpr std::uint64_t kLanes = 0x00FF00FF00FF00FFull;
  std::uint64_t t, b;
  std::memcpy(&t, top, 8);
  std::memcpy(&b, bottom, 8);
  const std::uint64_t rb = (t & kLanes) + (b & kLanes);
  const std::uint64_t ga = ((t >> 8) & kLanes) + ((b >> 8) & kLanes);
  // The left texel's sums plus the right one's, in the low 32 bits.
  const auto rb_sum = static_cast<std::uint32_t>(rb + (rb >> 32));
  const auto ga_sum = static_cast<std::uint32_t>(ga + (ga >> 32));
  return (((rb_sum + 0x00020002u) >> 2) & 0x00FF00FFu) |
         ((((ga_sum + 0x00020002u) >> 2) & 0x00FF00FFu) << 8);
}

void HalveUnorm8Row(const std::uint8_t* top, const std::uint8_t* bottom, int count,
                    std::uint8_t* out) {
  int x = 0;
#if HWY_TARGET != HWY_SCALAR
  // Channels widened to 16-bit lanes, the two rows summed; a texel's four sums are then one
  // 64-bit lane, and the even and odd lanes (left and right texels) add up.
  const hn::ScalableTag<std::uint16_t> d16;
  const hn::Rebind<std::uint8_t, decltype(d16)> d8;
  const hn::Repartition<std::uint64_t, decltype(d16)> d64;
  const hn::RebindToSigned<decltype(d16)> di16;
  const int bytes = static_cast<int>(hn::Lanes(d8));  // of each row, twice per step
  const int step = bytes / 4;                         // texels out per step
  const auto rounding = hn::Set(d16, 2);
  for (; x + step <= count; x += step) {
    const std::uint8_t* t = top + 8 * x;
    const std::uint8_t* b = bottom + 8 * x;
    const auto low = hn::BitCast(
        d64, hn::Add(hn::PromoteTo(d16, hn::LoadU(d8, t)), hn::PromoteTo(d16, hn::LoadU(d8, b))));
    const auto high = hn::BitCast(d64, hn::Add(hn::PromoteTo(d16, hn::LoadU(d8, t + bytes)),
                                               hn::PromoteTo(d16, hn::LoadU(d8, b + bytes))));
    const auto sums = hn::Add(hn::BitCast(d16, hn::ConcatEven(d64, high, low)),
                              hn::BitCast(d16, hn::ConcatOdd(d64, high, low)));
    const auto average = hn::ShiftRight<2>(hn::Add(sums, rounding));  // at most 255
    hn::StoreU(hn::DemoteTo(d8, hn::BitCast(di16, average)), d8, out + 4 * x);
  }
#endif
  for (; x < count; ++x) {
    const std::uint32_t texel = HalveTexel(top + 8 * x, bottom + 8 * x);
    std::memcpy(out + 4 * x, &texel, 4);
  }
}

}  // namespace facet::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet {

HWY_EXPORT(HalveUnorm8Row);

HalveUnorm8RowKernel halve_unorm8_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(HalveUnorm8Row)[target];
}

}  // namespace facet
#endif  // HWY_ONCE
