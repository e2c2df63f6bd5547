// The shadow lookup: the share of a light reaching each of a vector of surface points (its
// ShadowMaps, shadow_map.hpp), for the batch kernels of the models lit per pixel (shade_batch.cpp)
// and per vertex (vertex_batch.cpp): a directional light's orthographic maps and a spot light's
// perspective map, whose slopes are found per lane. Percentage-closer filtering over a 4 x 4
// texel footprint, the separable tent weights (1 - fx, 1, 1, fx) of a 3 x 3 grid of bilinear
// compares, so the result moves smoothly as the point moves. Each compare is against the
// receiver's own plane extended to that texel's centre (receiver-plane depth bias: MapSlopes), so
// a plane never shadows itself however far the footprint reaches, plus the bias of
// shadow_map.hpp. Outside the map, behind a spot light or beyond the map's far plane, lit.
// Included inside each file's HWY_NAMESPACE after batch_math-inl.h, the Highway "-inl.h" way.
// Every target computes the same IEEE operations in the same order (no fused multiply-add);
// shadow_batch_test checks each lane against the lookup written out one point at a time
// (tests/support/light_reference.hpp).
#if defined(FACET_SHADING_SHADOW_BATCH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_SHADOW_BATCH_INL_H_
#undef FACET_SHADING_SHADOW_BATCH_INL_H_
#else
#define FACET_SHADING_SHADOW_BATCH_INL_H_
#endif

#include <hwy/highway.h>

#include "core/truncate_in_range-inl.h"
#include "shading/batch_math-inl.h"
#include "shading/shadow_map.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using BatchMask = hn::Mask<BatchTag>;

// depth[i]: texel i of the four at row[lane], lane by lane. Vectors of 4 or 8 lanes transpose
// the rows' loads in registers (8 lanes: lanes 0-3 in the low 128 bits, 4-7 in the high).
HWY_INLINE void FootprintRow(const float* const* row, BatchV depth[4]) {
  const BatchTag d;
  constexpr std::size_t kLanes = hn::MaxLanes(d);
#if HWY_TARGET != HWY_SCALAR  // which has no Combine or Interleave*
  if constexpr (kLanes == 4 || kLanes == 8) {
    BatchV r[4];
    if constexpr (kLanes == 8) {
      const hn::Half<BatchTag> d4;
      for (int k = 0; k < 4; ++k)
        r[k] = hn::Combine(d, hn::LoadU(d4, row[k + 4]), hn::LoadU(d4, row[k]));
    } else {
      for (int k = 0; k < 4; ++k) r[k] = hn::LoadU(d, row[k]);
    }
    const hn::Repartition<std::uint64_t, BatchTag> d64;
    const BatchV t0 = hn::InterleaveLower(d, r[0], r[1]), t1 = hn::InterleaveLower(d, r[2], r[3]);
    const BatchV t2 = hn::InterleaveUpper(d, r[0], r[1]), t3 = hn::InterleaveUpper(d, r[2], r[3]);
    depth[0] = hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, t0), hn::BitCast(d64, t1)));
    depth[1] = hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, t0), hn::BitCast(d64, t1)));
    depth[2] = hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, t2), hn::BitCast(d64, t3)));
    depth[3] = hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, t2), hn::BitCast(d64, t3)));
    return;
  }
#endif
  {
    alignas(64) float texels[kLanes * 4];
    for (std::size_t lane = 0; lane < kLanes; ++lane)
      std::memcpy(&texels[lane * 4], row[lane], sizeof(float) * 4);
    hn::LoadInterleaved4(d, texels, depth[0], depth[1], depth[2], depth[3]);
  }
}

// MapSlopes, lane by lane: map_slopes() of each lane's derivatives.
struct MapSlopesV {
  Vec3V ray, slope_x, slope_y;
  BatchV texel_depth;
};

HWY_INLINE MapSlopesV SetSlopes(const MapSlopes& m) {
  return {Set3(m.ray), Set3(m.slope_x), Set3(m.slope_y), hn::Set(BatchTag(), m.texel_depth)};
}

// map_slopes(grad_x, grad_y, grad_z); glm::length is sqrt(dot(v, v)).
HWY_INLINE MapSlopesV MapSlopesOf(const Vec3V& grad_x, const Vec3V& grad_y, const Vec3V& grad_z) {
  MapSlopesV m;
  m.ray = Cross(grad_x, grad_y);
  m.slope_x = Cross(grad_z, grad_y);
  m.slope_y = Cross(grad_x, grad_z);
  m.texel_depth = hn::Div(hn::Abs(Dot(grad_z, m.ray)),
                          hn::Mul(hn::Sqrt(Dot(m.ray, m.ray)), hn::Sqrt(Dot(grad_x, grad_x))));
  return m;
}

// Row c of map.world_to_map times (p, 1): glm's mat4 x vec4, (m0 x + m1 y) + (m2 z + m3 w).
HWY_INLINE BatchV MapRow(const ShadowMap& map, int c, const Vec3V& p) {
  const BatchTag d;
  const glm::mat4& t = map.world_to_map;
  return hn::Add(hn::Add(hn::Mul(hn::Set(d, t[0][c]), p.x), hn::Mul(hn::Set(d, t[1][c]), p.y)),
                 hn::Add(hn::Mul(hn::Set(d, t[2][c]), p.z), hn::Set(d, t[3][c] * 1.0f)));
}

// The share of the light reaching the points in the lanes of `live`, of unit normals n, once
// their map coordinates m (x, y divided by w, and z) and the map's slopes there are known: the
// receiver-plane bias and the filtered compares, the same for both kinds of map. The other lanes
// give 1 (their results are not used). The 4 x 4 footprint's depths are read a lane at a time, a
// row of four texels with one load where the footprint lies within the map.
HWY_INLINE BatchV FilteredShadow(const ShadowMap& map, const BatchV m[3], const MapSlopesV& slopes,
                                 const Vec3V& n, BatchMask live) {
  const BatchTag d;
  const hn::RebindToSigned<BatchTag> di;
  const BatchV det = Dot(n, slopes.ray);
  const BatchV max_slope = hn::Mul(hn::Set(d, kMaxSlopeTexels), slopes.texel_depth);
  const BatchV min_slope = hn::Neg(max_slope);
  // The slopes where det != 0 (NaN included), std::clamp'ed; 0 elsewhere.
  const BatchMask has_det = hn::Not(hn::Eq(det, hn::Zero(d)));
  const BatchV inv_det = hn::Div(hn::Set(d, 1.0f), det);
  const auto clamp = [&](BatchV v) {
    return hn::IfThenElse(hn::Lt(v, min_slope), min_slope,
                          hn::IfThenElse(hn::Lt(max_slope, v), max_slope, v));
  };
  const BatchV slope_x =
      hn::IfThenElseZero(has_det, clamp(hn::Mul(Dot(n, slopes.slope_x), inv_det)));
  const BatchV slope_y =
      hn::IfThenElseZero(has_det, clamp(hn::Mul(Dot(n, slopes.slope_y), inv_det)));
  const BatchV bias =
      hn::Add(hn::Mul(slopes.texel_depth, hn::Set(d, kConstantBiasTexels)),
              hn::Mul(hn::Set(d, kSlopeBiasScale), hn::Add(hn::Abs(slope_x), hn::Abs(slope_y))));
  const BatchV z = hn::Sub(m[2], bias);
  const BatchV one = hn::Set(d, 1.0f);
  live = hn::And(live, hn::Lt(z, one));  // beyond the far plane (or not finite): lit
  const BatchV x0 = hn::Floor(m[0]), y0 = hn::Floor(m[1]);
  const float size_f = static_cast<float>(map.size);
  const BatchV size = hn::Set(d, size_f);
  const BatchV low = hn::Set(d, 1.0f - size_f), high = hn::Set(d, 2.0f * size_f);
  live = hn::And(live, hn::And(hn::And(hn::Ge(x0, low), hn::Lt(x0, high)),
                               hn::And(hn::Ge(y0, low), hn::Lt(y0, high))));
  if (hn::AllFalse(d, live)) return one;
  const BatchV ax = hn::Sub(m[0], x0), ay = hn::Sub(m[1], y0);
  const BatchV wx[4] = {hn::Sub(one, ax), one, one, ax};
  const BatchV wy[4] = {hn::Sub(one, ay), one, one, ay};
  const BatchV first =
      hn::Sub(hn::Sub(z, hn::Mul(slope_x, hn::Add(one, ax))), hn::Mul(slope_y, hn::Add(one, ay)));
  // The footprint's first texel (x0 - 1, y0 - 1), exact in floats (|x0| < 2^24); lanes not live
  // read texel (0, 0)'s footprint instead.
  const BatchV ix = hn::IfThenElseZero(live, hn::Sub(x0, one));
  const BatchV iy = hn::IfThenElseZero(live, hn::Sub(y0, one));
  const BatchV four = hn::Set(d, 4.0f);
  const BatchMask inside =
      hn::And(hn::And(hn::Ge(ix, hn::Zero(d)), hn::Ge(iy, hn::Zero(d))),
              hn::And(hn::Le(hn::Add(ix, four), size), hn::Le(hn::Add(iy, four), size)));
  // rows[j][lane]: where lane's texels (ix + i, iy + j), i = 0..3, lie: in the map itself, or
  // copied to `clamped` where the footprint leaves the map (clamped into it; those compares are
  // not made).
  constexpr int kMaxLanes = 8;
  alignas(64) std::int32_t first_x[kMaxLanes], first_y[kMaxLanes];
  hn::Store(simd::TruncateInRange(di, ix), di, first_x);
  hn::Store(simd::TruncateInRange(di, iy), di, first_y);
  const float* rows[4][kMaxLanes];
  float clamped[kMaxLanes][4][4];
  const int lanes = static_cast<int>(hn::Lanes(d));
  const std::ptrdiff_t stride = map.size;
  for (int lane = 0; lane < lanes; ++lane) {
    const int x = first_x[lane], y = first_y[lane];
    if (x >= 0 && y >= 0 && x + 4 <= map.size && y + 4 <= map.size) {
      const float* texel = map.depth + y * stride + x;
      for (int j = 0; j < 4; ++j) rows[j][lane] = texel + j * stride;
    } else {
      for (int j = 0; j < 4; ++j) {
        const std::ptrdiff_t row = std::clamp(y + j, 0, map.size - 1) * stride;
        for (int i = 0; i < 4; ++i) {
          clamped[lane][j][i] = map.depth[row + std::clamp(x + i, 0, map.size - 1)];
        }
        rows[j][lane] = clamped[lane][j];
      }
    }
  }
  const bool all_inside = hn::AllTrue(d, hn::Or(inside, hn::Not(live)));
  BatchMask all_see = live, any_sees = hn::Not(live);
  BatchV lit = hn::Zero(d);
  for (int j = 0; j < 4; ++j) {
    const BatchV y = hn::Add(iy, hn::Set(d, static_cast<float>(j)));
    const BatchMask row_in = hn::And(hn::Ge(y, hn::Zero(d)), hn::Lt(y, size));
    const BatchV row_start = hn::Add(first, hn::Mul(slope_y, hn::Set(d, static_cast<float>(j))));
    BatchV depth[4];
    FootprintRow(rows[j], depth);
    BatchV row = hn::Zero(d);
    for (int i = 0; i < 4; ++i) {
      BatchMask sees =
          hn::Le(hn::Add(row_start, hn::Mul(slope_x, hn::Set(d, static_cast<float>(i)))), depth[i]);
      if (!all_inside) {
        const BatchV x = hn::Add(ix, hn::Set(d, static_cast<float>(i)));
        const BatchMask in_map =
            hn::Or(inside, hn::And(row_in, hn::And(hn::Ge(x, hn::Zero(d)), hn::Lt(x, size))));
        sees = hn::Or(sees, hn::Not(in_map));
      }
      row = hn::IfThenElse(sees, hn::Add(row, wx[i]), row);
      all_see = hn::And(all_see, sees);
      any_sees = hn::Or(any_sees, sees);
    }
    lit = hn::Add(lit, hn::Mul(row, wy[j]));
  }
  const BatchV partly = hn::IfThenElseZero(any_sees, hn::Mul(lit, hn::Set(d, 1.0f / 9.0f)));
  return hn::IfThenElse(hn::Or(all_see, hn::Not(live)), one, partly);
}

// The lookup in an orthographic map (a directional light's) at points p: its slopes are
// the map's, the same everywhere.
HWY_INLINE BatchV OrthographicShadow(const ShadowMap& map, const Vec3V& p, const Vec3V& n,
                                     BatchMask live) {
  const BatchV m[3] = {MapRow(map, 0, p), MapRow(map, 1, p), MapRow(map, 2, p)};
  return FilteredShadow(map, m, SetSlopes(map.slopes), n, live);
}

// The lookup in a perspective map (a spot light's) at points p: x, y and z divided by w,
// lit behind the light (w not positive), and the slopes from each lane's derivatives, the
// matrix's rows less m_k times its w row, over w (the quotient rule).
HWY_INLINE BatchV PerspectiveShadow(const ShadowMap& map, const Vec3V& p, const Vec3V& n,
                                    BatchMask live) {
  const BatchTag d;
  const BatchV w = MapRow(map, 3, p);
  live = hn::And(live, hn::Gt(w, hn::Zero(d)));  // !(h.w > 0): behind the light
  if (hn::AllFalse(d, live)) return hn::Set(d, 1.0f);
  const BatchV inv_w = hn::Div(hn::Set(d, 1.0f), w);
  const BatchV m[3] = {hn::Mul(MapRow(map, 0, p), inv_w), hn::Mul(MapRow(map, 1, p), inv_w),
                       hn::Mul(MapRow(map, 2, p), inv_w)};
  const glm::mat4& t = map.world_to_map;
  Vec3V grad[3];
  for (int k = 0; k < 3; ++k) {
    // (t[i][k] - m_k * t[i][3]) * inv_w for each axis i.
    BatchV axis[3];
    for (int i = 0; i < 3; ++i) {
      axis[i] = hn::Mul(hn::Sub(hn::Set(d, t[i][k]), hn::Mul(m[k], hn::Set(d, t[i][3]))), inv_w);
    }
    grad[k] = {axis[0], axis[1], axis[2]};
  }
  return FilteredShadow(map, m, MapSlopesOf(grad[0], grad[1], grad[2]), n, live);
}

HWY_INLINE BatchV MapShadow(const ShadowMap& map, const Vec3V& p, const Vec3V& n, BatchMask live) {
  return map.perspective ? PerspectiveShadow(map, p, n, live) : OrthographicShadow(map, p, n, live);
}

// The share of the light reaching points p of unit normals n in the lanes of `wanted`, 1 in the
// others: each lane's cascade is the first whose far depth its view depth does not pass (the
// last if it passes them all), each cascade a lane picks looked up for its lanes; the lanes in
// a cascade's blend band look the next cascade up too and move toward it (ShadowMaps). Out of
// line (and of each file's own), so that the kernels' loops keep their registers for the draws
// without shadows.
static HWY_NOINLINE BatchV ShadowVisibility(const ShadowMaps& maps, const Vec3V& p, const Vec3V& n,
                                            BatchMask wanted) {
  const BatchTag d;
  BatchV visibility = hn::Set(d, 1.0f);
  if (hn::AllFalse(d, wanted)) return visibility;
  if (maps.count == 1) {
    return hn::IfThenElse(wanted, MapShadow(maps.maps[0], p, n, wanted), visibility);
  }
  const Vec3V eye = Set3(maps.eye);
  const BatchV depth =
      Dot({hn::Sub(p.x, eye.x), hn::Sub(p.y, eye.y), hn::Sub(p.z, eye.z)}, Set3(maps.forward));
  // The while loop's i: the number of leading cascades whose far depth the point is beyond.
  BatchMask beyond = wanted;
  BatchMask in_cascade[kMaxShadowCascades];
  for (int i = 0; i < maps.count; ++i) {
    if (i + 1 < maps.count) {
      const BatchMask next = hn::And(beyond, hn::Gt(depth, hn::Set(d, maps.far_depth[i])));
      in_cascade[i] = hn::AndNot(next, beyond);
      beyond = next;
    } else {
      in_cascade[i] = beyond;
    }
  }
  for (int i = 0; i < maps.count; ++i) {
    if (hn::AllFalse(d, in_cascade[i])) continue;
    BatchV v = MapShadow(maps.maps[i], p, n, in_cascade[i]);
    if (i + 1 < maps.count && maps.blend_rate[i] > 0.0f) {
      // std::min(into, 1) (which keeps a NaN, as Min need not), and Mul then Add, not MulAdd:
      // every target rounds alike.
      const BatchV one = hn::Set(d, 1.0f);
      const BatchV into =
          hn::Mul(hn::Sub(depth, hn::Set(d, maps.blend_from[i])), hn::Set(d, maps.blend_rate[i]));
      const BatchV t = hn::IfThenElse(hn::Lt(one, into), one, into);
      const BatchMask blending = hn::And(in_cascade[i], hn::Gt(t, hn::Zero(d)));
      if (!hn::AllFalse(d, blending)) {
        const BatchV next = MapShadow(maps.maps[i + 1], p, n, blending);
        v = hn::IfThenElse(blending, hn::Add(v, hn::Mul(hn::Sub(next, v), t)), v);
      }
    }
    visibility = hn::IfThenElse(in_cascade[i], v, visibility);
  }
  return visibility;
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_SHADOW_BATCH_INL_H_
