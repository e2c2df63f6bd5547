// Stage: output, the MSAA resolve's average (see sample_average_row.hpp). Highway compiles this
// file once per SIMD target; the frame fetches the chosen target's kernel (pipeline/kernels.hpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/output/sample_average_row.cpp"
#include "pipeline/output/sample_average_row.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void AverageSamplesRow(const glm::vec4* colors, const glm::vec4* others, int samples,
                       const std::uint8_t* split, int count, glm::vec4* out) {
  const hn::CappedTag<float, 4> d;  // one RGBA color a vector (a channel on HWY_SCALAR)
  const hn::RebindToSigned<decltype(d)> di;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto inverse = hn::Set(d, 1.0f / static_cast<float>(samples));
  constexpr int kGroup = 8;
  for (int x = 0; x < count;) {
    // Eight pixels none of which is split are copied: most of a frame of large triangles.
    std::uint64_t any_split = 1;
    if (x + kGroup <= count) std::memcpy(&any_split, split + x, kGroup);
    if (any_split == 0) {
      if (out != colors) std::memcpy(out + x, colors + x, kGroup * sizeof(glm::vec4));
      x += kGroup;
      continue;
    }
    // Otherwise selects rather than branches: along small triangles' edges, which pixels are
    // split is as good as random.
    for (const int end = std::min(x + kGroup, count); x < end; ++x) {
      const auto differ = hn::RebindMask(d, hn::Ne(hn::Set(di, split[x]), hn::Zero(di)));
      const float* rest = &others[static_cast<std::ptrdiff_t>(x) * (samples - 1)].x;
      for (int channel = 0; channel < 4; channel += lanes) {
        const auto alike = hn::LoadU(d, &colors[x].x + channel);
        auto sum = alike;
        for (int s = 1; s < samples; ++s) {
          sum = hn::Add(sum, hn::LoadU(d, rest + (s - 1) * 4 + channel));
        }
        hn::StoreU(hn::IfThenElse(differ, hn::Mul(sum, inverse), alike), d, &out[x].x + channel);
      }
    }
  }
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(AverageSamplesRow);

AverageSamplesRowKernel average_samples_row_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(AverageSamplesRow)[target];
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
