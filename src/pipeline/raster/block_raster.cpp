// Stage: raster, the SIMD part (see block_raster.hpp). Highway compiles this file once per SIMD
// target (foreach_target.h re-includes it); the frame fetches the chosen target's kernel
// (pipeline/kernels.hpp); tests force each target in turn and expect identical images.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/raster/block_raster.cpp"
#include "pipeline/raster/block_raster.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <type_traits>

#include "core/simd_target.hpp"
#include "pipeline/setup/fixed_point.hpp"
#include "pipeline/setup/sample_positions.hpp"
#include "pipeline/setup/setup.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A block row is 8 pixels: one vector on AVX2 and AVX-512 (which then uses 256-bit vectors),
// two on SSE4 and on EMU128 (Highway's portable fallback, plain C++ on four-lane arrays).
using FloatTag = hn::CappedTag<float, kBlockSize>;
using IntTag = hn::RebindToSigned<FloatTag>;

// CoverBlock, with kCoversBlock (BlockInput::covers_block) known, and the count of varyings
// where kVaryings is not negative.
template <bool kCoversBlock, int kVaryings>
HWY_INLINE void CoverRows(const BlockInput& in, BlockFragments& out) {
  const int varyings = kVaryings >= 0 ? kVaryings : in.varyings;
  const FloatTag df;
  const IntTag di;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const SetupTriangle& t = *in.triangle;
  const auto zero = hn::Zero(di);
  const auto x_begin = hn::Set(di, in.x_begin), x_end = hn::Set(di, in.x_end);
  float varying_rows[kMaxVaryings];
  // A covered block's rows are mostly all drawn: for the few varyings of the unrolled forms, its
  // planes' row values (evaluate_row's, the same operations) for every row at once, a row a
  // lane, rather than row by row. (With many varyings, reading them back a row at a time costs
  // more than it saves.)
  constexpr bool kAllRows = kCoversBlock && kVaryings >= 0;
  alignas(32) float z_rows[kBlockSize], inv_w_rows[kBlockSize];
  alignas(32) float varying_row_values[kAllRows ? kVaryings : 1][kBlockSize];
  if constexpr (kAllRows) {
    for (int r = 0; r < kBlockSize; r += lanes) {
      const auto relative_y =
          hn::Sub(hn::Iota(df, in.py0 + static_cast<float>(r)), hn::Set(df, t.ref_y));
      auto rows = [&](const Plane& p, float* out_rows) HWY_ATTR {
        hn::Store(hn::Add(hn::Set(df, p.at_ref), hn::Mul(hn::Set(df, p.dy), relative_y)), df,
                  out_rows + r);
      };
      rows(t.z, z_rows);
      if (!in.interpolate) continue;
      rows(t.inv_w, inv_w_rows);
      for (int k = 0; k < varyings; ++k) rows(in.varying_planes[k], varying_row_values[k]);
    }
  }
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
      auto pass = hn::FirstN(df, static_cast<std::size_t>(lanes));  // every lane
      if constexpr (!kCoversBlock) {
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
        pass = hn::RebindMask(df, inside);
        if (hn::AllFalse(df, pass)) continue;
      }
      if constexpr (kAllRows) {
        z_row = z_rows[y];
      } else if (!have_z_row) {
        z_row = evaluate_row(t.z, t.ref_y, py), have_z_row = true;
      }
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
      if constexpr (kAllRows) {
        inv_w_row = inv_w_rows[y];
        for (int k = 0; k < varyings; ++k) varying_rows[k] = varying_row_values[k][y];
      } else if (!have_rows) {
        inv_w_row = evaluate_row(t.inv_w, t.ref_y, py);
        for (int k = 0; k < varyings; ++k) {
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
      for (int k = 0; k < varyings; ++k) {
        const auto v_over_w = hn::Add(hn::Set(df, varying_rows[k]),
                                      hn::Mul(hn::Set(df, in.varying_planes[k].dx), relative_x));
        hn::Store(hn::Mul(v_over_w, w), df, out.v[k] + lane0);
      }
    }
  }
  out.mask = mask;
}

// CoverRows for the block's kind. Its loops over the varyings are unrolled for two to six of
// them (textured unlit models, Gouraud, glmark2's models), whose rows otherwise spend much of
// their time on the loops' bounds.
template <int kVaryings>
HWY_INLINE void CoverRowsOf(const BlockInput& in, BlockFragments& out) {
  if (in.covers_block) {
    CoverRows<true, kVaryings>(in, out);
  } else {
    CoverRows<false, kVaryings>(in, out);
  }
}

void CoverBlock(const BlockInput& in, BlockFragments& out) {
  switch (in.varyings) {
    case 2:
      return CoverRowsOf<2>(in, out);
    case 3:
      return CoverRowsOf<3>(in, out);
    case 4:
      return CoverRowsOf<4>(in, out);
    case 5:
      return CoverRowsOf<5>(in, out);
    case 6:
      return CoverRowsOf<6>(in, out);
    default:
      return CoverRowsOf<-1>(in, out);
  }
}

HWY_INLINE void InterpolateRun(const SetupTriangle& t, const Plane* planes, int varyings, int first,
                               int count, const std::int16_t* xs, const std::int16_t* ys, float* z,
                               float* w, float (*v)[kBlockPixels]) {
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
    hn::StoreU(evaluate(t.z), df, z + j);
    const auto clip_w = hn::Div(hn::Set(df, 1.0f), evaluate(t.inv_w));
    hn::StoreU(clip_w, df, w + j);
    for (int k = 0; k < varyings; ++k)
      hn::StoreU(hn::Mul(evaluate(planes[k]), clip_w), df, v[k] + j);
  }
}

void InterpolatePixels(const SetupTriangle& t, const Plane* planes, int varyings, int first,
                       int count, const std::int16_t* xs, const std::int16_t* ys, float* z,
                       float* w, float (*v)[kBlockPixels]) {
  InterpolateRun(t, planes, varyings, first, count, xs, ys, z, w, v);
}

void InterpolateRuns(const InterpolationRun* runs, int run_count, const Plane* planes, int varyings,
                     const std::int16_t* xs, const std::int16_t* ys, float* z, float* w,
                     float (*v)[kBlockPixels]) {
  int first = 0;  // each run starts where the one before ends
  for (int r = 0; r < run_count; ++r) {
    const SetupTriangle& t = *runs[r].triangle;
    InterpolateRun(t, planes + t.varying_planes, varyings, first, runs[r].count, xs, ys, z, w, v);
    first += runs[r].count;
  }
}

// search(tag) with the tag of a box row `width` pixels wide: vectors of up to eight lanes for
// rows of eight pixels at most, of up to sixteen for wider ones (one vector where two of eight
// would be half empty).
template <class Search>
HWY_INLINE int SearchRowsOfWidth(int width, const Search& search) {
  if (width > kBlockSize) return search(hn::CappedTag<float, 16>());
  return search(FloatTag());
}

// The depth buffer's element: written by the depth-writing search only.
template <bool kWritesDepth>
using DepthElement = std::conditional_t<kWritesDepth, float, const float>;

// FindBoxPixels' rows, vectors of DF's lanes at a time; e_first: the edges at the box's first
// pixel, as FindBoxPixels says. kWritesDepth (WriteBoxDepths): the pixels found take their
// depths, and their positions are not stored.
template <bool kWritesDepth, class DF>
HWY_INLINE int FindBoxRows(DF df, const SetupTriangle& t, const std::int32_t e_first[3], int x0,
                           int y0, int width, int height, DepthElement<kWritesDepth>* depth,
                           int depth_stride, bool depth_test, std::int16_t* xs, std::int16_t* ys) {
  const hn::RebindToSigned<DF> di;
  const hn::Rebind<std::int16_t, DF> d16;
  const int lanes = static_cast<int>(hn::Lanes(df));
  alignas(64) static constexpr std::int32_t kLanes[16] = {0, 1, 2,  3,  4,  5,  6,  7,
                                                          8, 9, 10, 11, 12, 13, 14, 15};
  const auto half = hn::Set(df, 0.5f);
  // In locals: the depth-writing form's stores may alias the triangle, which the compiler would
  // then read again after each.
  const Plane z_plane = t.z;
  const float ref_y = t.ref_y;
  const std::int32_t row_step[3] = {t.b[0], t.b[1], t.b[2]};
  int count = 0;
  // A box row at a time (a vector holds it but for boxes wider than a vector, which split into
  // vectors of columns).
  for (int x = 0; x < width; x += lanes) {
    const auto column = hn::Add(hn::Load(di, kLanes), hn::Set(di, x));
    const auto in_box = hn::Lt(column, hn::Set(di, width));
    hn::Vec<decltype(di)> along_row[3];
    for (int i = 0; i < 3; ++i) along_row[i] = hn::Mul(hn::Set(di, t.a[i]), column);
    const auto frame_x = hn::Add(column, hn::Set(di, x0));
    // evaluate_in_row's dx * (px - ref_x), the same for every row.
    const auto z_along_row =
        hn::Mul(hn::Set(df, t.z.dx),
                hn::Sub(hn::Add(hn::ConvertTo(df, frame_x), half), hn::Set(df, t.ref_x)));
    std::int32_t e[3] = {e_first[0], e_first[1], e_first[2]};
    for (int row = 0; row < height; ++row) {
      auto edges = hn::Zero(di);
      for (int i = 0; i < 3; ++i) edges = hn::Or(edges, hn::Add(hn::Set(di, e[i]), along_row[i]));
      for (int i = 0; i < 3; ++i) e[i] += row_step[i];
      // No branches on the masks: whether a row of a small triangle's box is covered, and
      // passes the depth test, is as good as random to the branch predictor.
      auto pass = hn::RebindMask(df, hn::AndNot(hn::Lt(edges, hn::Zero(di)), in_box));
      const int y = y0 + row;
      const float z_row = evaluate_row(z_plane, ref_y, static_cast<float>(y) + 0.5f);
      const auto z = hn::Add(hn::Set(df, z_row), z_along_row);
      auto* depth_row = depth + static_cast<std::ptrdiff_t>(row) * depth_stride + x;
      if (depth_test) pass = hn::And(pass, hn::Lt(z, hn::LoadU(df, depth_row)));  // NaN fails
      const auto n = hn::CountTrue(df, pass);
      if constexpr (kWritesDepth) {
        hn::BlendedStore(z, pass, df, depth_row);
        count += static_cast<int>(n);
        continue;
      }
      hn::StoreU(hn::DemoteTo(d16, hn::Compress(frame_x, hn::RebindMask(di, pass))), d16,
                 xs + count);
      hn::StoreU(hn::Set(d16, static_cast<std::int16_t>(y)), d16, ys + count);
      count += static_cast<int>(n);
    }
  }
  return count;
}

// The edges at the box's first pixel (x0, y0), as FindBoxPixels takes them.
void BoxEdges(const SetupTriangle& t, int x0, int y0, std::int32_t e_first[3]) {
  // Edge i at box pixel (dx, dy) is e[i] + a*dx + b*dy, as for blocks (block_raster.hpp): E
  // at the box's first pixel centre over 256, floored. With |a|, |b| <= 2^23 and dx, dy <= 63,
  // a*dx and b*dy stay within 2^29, so e clamped to +-2^30 keeps every sign and 32 bits hold
  // the sums, even for a big triangle whose box in the tile is small. (Lanes past the box's
  // width may wrap around; in_box drops them.)
  constexpr std::int64_t kClamp = std::int64_t{1} << 30;
  for (int i = 0; i < 3; ++i) {
    e_first[i] = static_cast<std::int32_t>(
        std::clamp(edge_at_centre(t, i, x0, y0) >> kSubpixelBits, -kClamp, kClamp));  // floor
  }
}

// FindBoxRows in vectors as wide as the box's rows need (SearchRowsOfWidth).
template <bool kWritesDepth>
int FindBoxRowsOfWidth(const SetupTriangle& t, int x0, int y0, int width, int height,
                       DepthElement<kWritesDepth>* depth, int depth_stride, bool depth_test,
                       std::int16_t* xs, std::int16_t* ys) {
  std::int32_t e_first[3];
  BoxEdges(t, x0, y0, e_first);
  return SearchRowsOfWidth(width, [&](auto df) HWY_ATTR {
    return FindBoxRows<kWritesDepth>(df, t, e_first, x0, y0, width, height, depth, depth_stride,
                                     depth_test, xs, ys);
  });
}

int FindBoxPixels(const SetupTriangle& t, int x0, int y0, int width, int height, const float* depth,
                  int depth_stride, bool depth_test, std::int16_t* xs, std::int16_t* ys) {
  return FindBoxRowsOfWidth<false>(t, x0, y0, width, height, depth, depth_stride, depth_test, xs,
                                   ys);
}

int WriteBoxDepths(const SetupTriangle& t, int x0, int y0, int width, int height, float* depth,
                   int depth_stride) {
  return FindBoxRowsOfWidth<true>(t, x0, y0, width, height, depth, depth_stride, true, nullptr,
                                  nullptr);
}

// FindBoxSamples' rows, vectors of DF's lanes at a time.
template <class DF>
HWY_INLINE int FindBoxSampleRows(DF df, const SampleBoxSearch& in, std::int16_t* xs,
                                 std::int16_t* ys, std::uint16_t* masks) {
  const hn::RebindToSigned<DF> di;
  const hn::Rebind<std::int16_t, DF> d16;
  const hn::Rebind<std::uint16_t, DF> du16;
  const int lanes = static_cast<int>(hn::Lanes(df));
  const SetupTriangle& t = *in.triangle;
  const auto half = hn::Set(df, 0.5f);
  // The search's values as locals: the depth stores may alias anything they were read from, so
  // the compiler would read each again after every store.
  const int samples = in.samples, width = in.width, height = in.height;
  const bool depth_test = in.depth_test, write_depth = in.write_depth;
  const std::ptrdiff_t plane = in.plane, depth_stride = in.depth_stride;
  const Plane z_plane = t.z;
  const float ref_y = t.ref_y;
  std::int32_t e_first[3], row_step[3], step[3][kMaxSamples];
  float sample_z[kMaxSamples];
  for (int i = 0; i < 3; ++i) {
    e_first[i] = static_cast<std::int32_t>(in.e_first[i]);
    row_step[i] = t.b[i] * 16;
    for (int s = 0; s < samples; ++s) step[i][s] = static_cast<std::int32_t>(in.step[i][s]);
  }
  if (depth_test) std::copy_n(in.sample_z, samples, sample_z);
  int count = 0;
  for (int x = 0; x < width; x += lanes) {
    const auto column = hn::Iota(di, x);
    const auto in_box = hn::Lt(column, hn::Set(di, width));
    hn::Vec<decltype(di)> along_row[3];
    for (int i = 0; i < 3; ++i) {
      along_row[i] = hn::Mul(hn::Set(di, t.a[i] * 16), column);  // |a| < 2^18: no overflow
    }
    const auto frame_x = hn::Add(column, hn::Set(di, in.x0));
    // evaluate_in_row's dx * (px - ref_x), the same for every row.
    const auto z_along_row =
        hn::Mul(hn::Set(df, t.z.dx),
                hn::Sub(hn::Add(hn::ConvertTo(df, frame_x), half), hn::Set(df, t.ref_x)));
    for (int row = 0; row < height; ++row) {
      hn::Vec<decltype(di)> edge[3];
      for (int i = 0; i < 3; ++i) {
        edge[i] = hn::Add(hn::Set(di, e_first[i] + row * row_step[i]), along_row[i]);
      }
      const int y = in.y0 + row;
      const float z_row = evaluate_row(z_plane, ref_y, static_cast<float>(y) + 0.5f);
      const auto z = hn::Add(hn::Set(df, z_row), z_along_row);
      float* depth = in.depth + static_cast<std::ptrdiff_t>(row) * depth_stride + x;
      auto bits = hn::Zero(di);
      for (int s = 0; s < samples; ++s) {
        auto outside = hn::Zero(di);
        for (int i = 0; i < 3; ++i) {
          outside = hn::Or(outside, hn::Add(edge[i], hn::Set(di, step[i][s])));
        }
        auto covered = hn::RebindMask(df, hn::AndNot(hn::Lt(outside, hn::Zero(di)), in_box));
        if (depth_test) {
          const auto z_sample = hn::Add(z, hn::Set(df, sample_z[s]));
          float* plane_depth = depth + s * plane;
          covered = hn::And(covered, hn::Lt(z_sample, hn::LoadU(df, plane_depth)));
          if (write_depth) hn::BlendedStore(z_sample, covered, df, plane_depth);
        }
        bits = hn::Or(bits, hn::IfThenElseZero(hn::RebindMask(di, covered), hn::Set(di, 1 << s)));
      }
      const auto any = hn::Ne(bits, hn::Zero(di));
      const auto n = hn::CountTrue(di, any);
      hn::StoreU(hn::DemoteTo(d16, hn::Compress(frame_x, any)), d16, xs + count);
      hn::StoreU(hn::Set(d16, static_cast<std::int16_t>(y)), d16, ys + count);
      hn::StoreU(hn::DemoteTo(du16, hn::Compress(bits, any)), du16, masks + count);
      count += static_cast<int>(n);
    }
  }
  return count;
}

// FindBoxSampleRows in vectors as wide as the box's rows need (SearchRowsOfWidth).
int FindBoxSamples(const SampleBoxSearch& in, std::int16_t* xs, std::int16_t* ys,
                   std::uint16_t* masks) {
  return SearchRowsOfWidth(
      in.width, [&](auto df) HWY_ATTR { return FindBoxSampleRows(df, in, xs, ys, masks); });
}

// FindBoxSamples for the triangles whose edge coefficients need more than 32 bits: the edge
// functions in doubles, exact for the integers they hold (below 2^53: the guard band bounds
// them near 2^47), one double lane per pixel; the depths in floats as in FindBoxSamples, each
// compared in double (exact for floats, so the same order). Positions and masks are stored
// for the pixels found only.
int FindBoxSamplesWide(const SampleBoxSearch& in, std::int16_t* xs, std::int16_t* ys,
                       std::uint16_t* masks) {
  const hn::CappedTag<double, kBlockSize> dd;
  const hn::Rebind<float, decltype(dd)> df;  // as many float lanes
  const int lanes = static_cast<int>(hn::Lanes(dd));
  const SetupTriangle& t = *in.triangle;
  const auto zero = hn::Zero(dd);
  alignas(64) double bits_of[kBlockSize];
  int count = 0;
  for (int x = 0; x < in.width; x += lanes) {
    const auto column = hn::Iota(dd, static_cast<double>(x));
    const auto in_box = hn::Lt(column, hn::Set(dd, static_cast<double>(in.width)));
    hn::Vec<decltype(dd)> along_row[3];
    for (int i = 0; i < 3; ++i) {
      along_row[i] = hn::Mul(hn::Set(dd, static_cast<double>(std::int64_t{t.a[i]} * 16)), column);
    }
    // evaluate_in_row's dx * (px - ref_x), the same for every row.
    const auto frame_x = hn::Iota(df, static_cast<float>(in.x0 + x));
    const auto z_along_row = hn::Mul(
        hn::Set(df, t.z.dx), hn::Sub(hn::Add(frame_x, hn::Set(df, 0.5f)), hn::Set(df, t.ref_x)));
    for (int row = 0; row < in.height; ++row) {
      hn::Vec<decltype(dd)> edge[3];
      for (int i = 0; i < 3; ++i) {
        const std::int64_t first = in.e_first[i] + std::int64_t{row} * t.b[i] * 16;
        edge[i] = hn::Add(hn::Set(dd, static_cast<double>(first)), along_row[i]);
      }
      const int y = in.y0 + row;
      const float z_row = evaluate_row(t.z, t.ref_y, static_cast<float>(y) + 0.5f);
      const auto z = hn::Add(hn::Set(df, z_row), z_along_row);
      const float* depth = in.depth + static_cast<std::ptrdiff_t>(row) * in.depth_stride + x;
      auto bits = zero;
      for (int s = 0; s < in.samples; ++s) {
        auto covered = in_box;
        for (int i = 0; i < 3; ++i) {
          const auto value = hn::Add(edge[i], hn::Set(dd, static_cast<double>(in.step[i][s])));
          covered = hn::And(covered, hn::Not(hn::Lt(value, zero)));
        }
        if (in.depth_test) {
          const auto sample_z = hn::Add(z, hn::Set(df, in.sample_z[s]));
          const auto stored = hn::LoadU(df, depth + s * in.plane);
          covered =
              hn::And(covered, hn::Lt(hn::PromoteTo(dd, sample_z), hn::PromoteTo(dd, stored)));
        }
        bits = hn::Add(bits, hn::IfThenElseZero(covered, hn::Set(dd, static_cast<double>(1 << s))));
      }
      if (hn::AllFalse(dd, hn::Ne(bits, zero))) continue;
      hn::Store(bits, dd, bits_of);
      for (int k = 0; k < lanes; ++k) {
        if (bits_of[k] == 0.0) continue;
        xs[count] = static_cast<std::int16_t>(in.x0 + x + k);
        ys[count] = static_cast<std::int16_t>(y);
        masks[count] = static_cast<std::uint16_t>(bits_of[k]);
        ++count;
      }
    }
  }
  return count;
}

const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

void WriteSampleColors(const SampleColorWrite& to, const float (*colors)[4], const std::int16_t* xs,
                       const std::int16_t* ys, const std::uint16_t* masks, int count) {
  const hn::CappedTag<float, 4> d;  // one RGBA color a vector (a channel on HWY_SCALAR)
  const hn::RebindToSigned<decltype(d)> di;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto one = hn::Set(d, 1.0f);
  const int others = to.samples - 1;
  const unsigned all = (1u << to.samples) - 1;
  for (int n = 0; n < count; ++n) {
    const std::ptrdiff_t pixel =
        static_cast<std::ptrdiff_t>(ys[n] - to.y0) * to.stride + (xs[n] - to.x0);
    const auto was_split = hn::RebindMask(d, hn::Ne(hn::Set(di, to.split[pixel]), hn::Zero(di)));
    const auto bits = hn::Set(di, masks[n]);
    auto covered = [&](int s) HWY_ATTR {
      return hn::RebindMask(d, hn::Ne(hn::And(bits, hn::Set(di, 1 << s)), hn::Zero(di)));
    };
    for (int channel = 0; channel < 4; channel += lanes) {
      float* at = to.color + pixel * 4 + channel;
      float* rest = to.others + pixel * others * 4 + channel;  // sample s at rest + (s - 1) * 4
      auto value = hn::LoadU(d, colors[n] + channel);
      const auto alpha = hn::RebindMask(d, hn::Eq(hn::Iota(di, channel), hn::Set(di, 3)));
      value = hn::IfThenElse(alpha, one, value);
      const auto first = hn::LoadU(d, at);
      hn::StoreU(hn::IfThenElse(covered(0), value, first), d, at);
      for (int s = 1; s <= others; ++s) {
        float* sample = rest + (s - 1) * 4;
        const auto kept = hn::IfThenElse(was_split, hn::LoadU(d, sample), first);
        hn::StoreU(hn::IfThenElse(covered(s), value, kept), d, sample);
      }
    }
    to.split[pixel] = masks[n] != all;
  }
}

bool BlockSamplesInFront(const float* z, const float* sample_z, int samples, const float* depth,
                         std::ptrdiff_t stride, std::ptrdiff_t plane) {
  const FloatTag df;
  const int lanes = static_cast<int>(hn::Lanes(df));
  auto in_front = hn::Eq(hn::Zero(df), hn::Zero(df));  // every lane true
  for (int s = 0; s < samples; ++s) {
    const auto step = hn::Set(df, sample_z[s]);
    const float* plane_depth = depth + s * plane;
    for (int row = 0; row < kBlockSize; ++row) {
      for (int x = 0; x < kBlockSize; x += lanes) {
        const auto sample = hn::Add(hn::LoadU(df, z + row * kBlockSize + x), step);
        in_front = hn::And(in_front, hn::Lt(sample, hn::LoadU(df, plane_depth + row * stride + x)));
      }
    }
  }
  return hn::AllTrue(df, in_front);
}

void WriteBlockSampleDepths(const float* z, const float* sample_z, int samples, float* depth,
                            std::ptrdiff_t stride, std::ptrdiff_t plane) {
  const FloatTag df;
  const int lanes = static_cast<int>(hn::Lanes(df));
  for (int s = 0; s < samples; ++s) {
    const auto step = hn::Set(df, sample_z[s]);
    float* plane_depth = depth + s * plane;
    for (int row = 0; row < kBlockSize; ++row) {
      for (int x = 0; x < kBlockSize; x += lanes) {
        hn::StoreU(hn::Add(hn::LoadU(df, z + row * kBlockSize + x), step), df,
                   plane_depth + row * stride + x);
      }
    }
  }
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(CoverBlock);
HWY_EXPORT(TargetName);
HWY_EXPORT(InterpolatePixels);
HWY_EXPORT(InterpolateRuns);
HWY_EXPORT(FindBoxPixels);
HWY_EXPORT(WriteBoxDepths);
HWY_EXPORT(FindBoxSamples);
HWY_EXPORT(FindBoxSamplesWide);
HWY_EXPORT(WriteSampleColors);
HWY_EXPORT(BlockSamplesInFront);
HWY_EXPORT(WriteBlockSampleDepths);

const char* simd_target_name() { return HWY_DISPATCH_TABLE(TargetName)[chosen_simd_target()](); }

RasterKernels raster_kernels(SimdTarget index) {
  return {HWY_DISPATCH_TABLE(CoverBlock)[index],
          HWY_DISPATCH_TABLE(InterpolatePixels)[index],
          HWY_DISPATCH_TABLE(InterpolateRuns)[index],
          HWY_DISPATCH_TABLE(FindBoxPixels)[index],
          HWY_DISPATCH_TABLE(WriteBoxDepths)[index],
          HWY_DISPATCH_TABLE(FindBoxSamples)[index],
          HWY_DISPATCH_TABLE(FindBoxSamplesWide)[index],
          HWY_DISPATCH_TABLE(WriteSampleColors)[index],
          HWY_DISPATCH_TABLE(BlockSamplesInFront)[index],
          HWY_DISPATCH_TABLE(WriteBlockSampleDepths)[index]};
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
