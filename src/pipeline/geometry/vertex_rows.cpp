// Stage: vertex transform, its results stored per vertex (see vertex_rows.hpp). Highway
// compiles this file once per SIMD target (foreach_target.h re-includes it). Products are the
// scalar code's single multiplications, so every target stores the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/geometry/vertex_rows.cpp"
#include "pipeline/geometry/vertex_rows.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Eight lanes: 256-bit vectors where a target has them (AVX2, AVX-512); the transpose below is
// written for two 128-bit halves, so narrower targets store element by element.
using RowTag = hn::CappedTag<float, 8>;
constexpr bool kTransposes =
    HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128 && hn::MaxLanes(RowTag()) == 8;

#if HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
// r[i] = row i of an 8 x 8 matrix of 32-bit values becomes column i (AVX's unpack, shuffle,
// permute sequence).
template <class D>
HWY_INLINE void Transpose8x8(D d, hn::Vec<D> r[8]) {
  const hn::Repartition<std::uint64_t, D> d64;
  const auto pairs = [&](hn::Vec<D> a, hn::Vec<D> b, bool upper) {
    return upper
               ? hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, a), hn::BitCast(d64, b)))
               : hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, a), hn::BitCast(d64, b)));
  };
  hn::Vec<D> t[8], s[8];
  for (int i = 0; i < 4; ++i) {
    t[2 * i] = hn::InterleaveLower(d, r[2 * i], r[2 * i + 1]);
    t[2 * i + 1] = hn::InterleaveUpper(d, r[2 * i], r[2 * i + 1]);
  }
  // s[4h + c]: columns c and c + 4 of rows 4h ... 4h + 3.
  for (int h = 0; h < 2; ++h) {
    s[4 * h + 0] = pairs(t[4 * h], t[4 * h + 2], false);
    s[4 * h + 1] = pairs(t[4 * h], t[4 * h + 2], true);
    s[4 * h + 2] = pairs(t[4 * h + 1], t[4 * h + 3], false);
    s[4 * h + 3] = pairs(t[4 * h + 1], t[4 * h + 3], true);
  }
  for (int c = 0; c < 4; ++c) {
    r[c] = hn::ConcatLowerLower(d, s[4 + c], s[c]);
    r[c + 4] = hn::ConcatUpperUpper(d, s[4 + c], s[c]);
  }
}
#endif

void StoreProjected(const VertexPass& pass, std::size_t count, ProjectedVertex* out) {
  static_assert(sizeof(ProjectedVertex) == 8 * sizeof(float));
  std::size_t j = 0;
#if HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
  if constexpr (kTransposes) {
    const RowTag d;
    const hn::RebindToSigned<RowTag> di;
    const auto not_scalar = hn::Set(di, static_cast<std::int32_t>(~kScalarScreen));
    for (; j + 8 <= count; j += 8) {
      // ProjectedVertex's fields in order, eight vertices each.
      hn::Vec<RowTag> r[8] = {
          hn::Load(d, pass.x + j),
          hn::Load(d, pass.y + j),
          hn::Load(d, pass.w + j),
          hn::BitCast(d,
                      hn::And(hn::Load(di, reinterpret_cast<const std::int32_t*>(pass.codes) + j),
                              not_scalar)),
          hn::BitCast(d, hn::Load(di, pass.sx + j)),
          hn::BitCast(d, hn::Load(di, pass.sy + j)),
          hn::Load(d, pass.depth + j),
          hn::Load(d, pass.inv_w + j)};
      Transpose8x8(d, r);
      for (int i = 0; i < 8; ++i) hn::StoreU(r[i], d, reinterpret_cast<float*>(out + j + i));
    }
  }
#endif
  for (; j < count; ++j) {
    ProjectedVertex& p = out[j];
    p.clip_x = pass.x[j], p.clip_y = pass.y[j], p.clip_w = pass.w[j];
    p.codes = pass.codes[j] & ~kScalarScreen;
    p.screen = {pass.sx[j], pass.sy[j], pass.depth[j], pass.inv_w[j]};
  }
}

void StoreOverW(const float (*values)[kVertexPass], const float* inv_w, std::size_t count,
                int varyings, float* out) {
  std::size_t j = 0;
  const auto n = static_cast<std::size_t>(varyings);
#if HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
  if constexpr (kTransposes) {
    const RowTag d;
    const std::size_t blocks = (n + 7) / 8;  // of eight varyings
    // Each vertex's row is stored as whole vectors, reaching up to 7 floats past its end: into
    // the next vertices' rows, which are stored after it. So the group's last vertex must not
    // reach past the last row.
    for (; n > 0 && j + 8 <= count && (j + 7) * n + 8 * blocks <= count * n; j += 8) {
      hn::Vec<RowTag> rows[2][8];
      for (std::size_t b = 0; b < blocks; ++b) {
        for (std::size_t i = 0; i < 8; ++i) {
          const std::size_t k = 8 * b + i;
          rows[b][i] = k < n ? hn::Load(d, values[k] + j) : hn::Zero(d);
        }
        Transpose8x8(d, rows[b]);
      }
      for (std::size_t i = 0; i < 8; ++i) {
        const auto scale = hn::Set(d, inv_w[j + i]);
        for (std::size_t b = 0; b < blocks; ++b) {
          hn::StoreU(hn::Mul(rows[b][i], scale), d, out + (j + i) * n + 8 * b);
        }
      }
    }
  }
#endif
  for (; j < count; ++j) {
    for (std::size_t k = 0; k < n; ++k) out[j * n + k] = values[k][j] * inv_w[j];
  }
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(StoreProjected);
HWY_EXPORT(StoreOverW);

StoreProjectedKernel store_projected_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(StoreProjected)[target];
}

StoreOverWKernel store_over_w_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(StoreOverW)[target];
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
