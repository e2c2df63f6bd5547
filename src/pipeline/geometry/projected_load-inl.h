// Per-target loading of ProjectedVertex fields by vertex index, shared by the SIMD kernels that
// read a triangle's vertices a lane per triangle (cull_batch.cpp, setup_batch.cpp): included
// inside each file's HWY_NAMESPACE, once per target, the Highway "-inl.h" way (the guard below
// toggles with HWY_TARGET_TOGGLE).
#if defined(FACET_PIPELINE_PROJECTED_LOAD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_PIPELINE_PROJECTED_LOAD_INL_H_
#undef FACET_PIPELINE_PROJECTED_LOAD_INL_H_
#else
#define FACET_PIPELINE_PROJECTED_LOAD_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "pipeline/frame.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A ProjectedVertex as 32-bit fields: its clip part (clip x, y, w, codes) from field 0, its
// screen part (x, y, z, 1 / w) from field kScreenField.
inline constexpr std::size_t kProjectedFields = 8;
inline constexpr std::size_t kScreenField = 4;
static_assert(sizeof(ProjectedVertex) == kProjectedFields * sizeof(float));
static_assert(offsetof(ProjectedVertex, screen) == kScreenField * sizeof(float));

// Fields first .. first + 3 of the vertices `index` (lane by lane) of the ProjectedVertex array
// `vertices`, as the bits of four vectors: f[k] holds field first + k.
template <class D>
HWY_INLINE void LoadProjectedFields(D d, const ProjectedVertex* vertices, std::size_t first,
                                    hn::Vec<hn::RebindToUnsigned<D>> index, hn::Vec<D> f[4]) {
  static_assert(sizeof(hn::TFromD<D>) == 4);
  const hn::RebindToUnsigned<D> du;
  const auto* fields = reinterpret_cast<const hn::TFromD<D>*>(vertices) + first;
#if HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
  constexpr std::size_t kLanes = hn::MaxLanes(D());
  if constexpr (kLanes == 4 || kLanes == 8) {
    // Each vertex's four fields loaded whole, then transposed: on this project's AVX-512
    // machine, cheaper than four gathers. pair[l] holds vertices l and, with eight lanes, l + 4.
    alignas(32) std::uint32_t at[kLanes];
    hn::Store(index, du, at);
    hn::Vec<D> pair[4];
    for (std::size_t l = 0; l < 4; ++l) {
      if constexpr (kLanes == 8) {
        const hn::Half<D> d4;
        pair[l] = hn::Combine(d, hn::LoadU(d4, fields + kProjectedFields * at[l + 4]),
                              hn::LoadU(d4, fields + kProjectedFields * at[l]));
      } else {
        pair[l] = hn::LoadU(d, fields + kProjectedFields * at[l]);
      }
    }
    const hn::Repartition<std::uint64_t, D> d64;
    const auto low01 = hn::BitCast(d64, hn::InterleaveLower(d, pair[0], pair[1]));
    const auto high01 = hn::BitCast(d64, hn::InterleaveUpper(d, pair[0], pair[1]));
    const auto low23 = hn::BitCast(d64, hn::InterleaveLower(d, pair[2], pair[3]));
    const auto high23 = hn::BitCast(d64, hn::InterleaveUpper(d, pair[2], pair[3]));
    f[0] = hn::BitCast(d, hn::InterleaveLower(d64, low01, low23));
    f[1] = hn::BitCast(d, hn::InterleaveUpper(d64, low01, low23));
    f[2] = hn::BitCast(d, hn::InterleaveLower(d64, high01, high23));
    f[3] = hn::BitCast(d, hn::InterleaveUpper(d64, high01, high23));
    return;
  }
#endif
  {  // narrower targets: lane by lane
    using T = hn::TFromD<D>;
    constexpr std::size_t kMax = hn::MaxLanes(D());
    alignas(64) std::uint32_t at[kMax];
    alignas(64) T lanes[4][kMax];
    hn::Store(index, du, at);
    for (std::size_t l = 0; l < hn::Lanes(d); ++l) {
      for (int k = 0; k < 4; ++k) {
        std::memcpy(&lanes[k][l], fields + kProjectedFields * at[l] + k, sizeof(T));
      }
    }
    for (int k = 0; k < 4; ++k) f[k] = hn::Load(d, lanes[k]);
  }
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_PIPELINE_PROJECTED_LOAD_INL_H_
