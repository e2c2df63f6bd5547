// Stage: vertex transform, the SIMD part (see vertex_pass.hpp). Highway compiles this file once per
// SIMD target (foreach_target.h re-includes it); the frame fetches the chosen target's kernel
// (pipeline/kernels.hpp). Only single IEEE operations are used (Mul, Add, Sub, Div, Sqrt; no fused
// multiply-add, -ffp-contract=off), in the scalar code's order, so every lane equals the scalar
// result on every target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/geometry/vertex_pass.cpp"
#include "pipeline/geometry/vertex_pass.hpp"

#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using FloatTag = hn::ScalableTag<float>;
using IntTag = hn::RebindToSigned<FloatTag>;
using Vec = hn::Vec<FloatTag>;
constexpr int kMaxLanes = HWY_MAX_BYTES / sizeof(float);

// Vectors of x, y and z of `valid` vec3s from p, zero-padded to a whole vector.
HWY_INLINE void Load3(FloatTag d, const glm::vec3* p, std::size_t valid, Vec& x, Vec& y, Vec& z) {
  const std::size_t lanes = hn::Lanes(d);
  if (valid >= lanes) {
    hn::LoadInterleaved3(d, &p->x, x, y, z);
    return;
  }
  alignas(64) float padded[3 * kVertexPass] = {};
  std::memcpy(padded, p, valid * sizeof(glm::vec3));
  hn::LoadInterleaved3(d, padded, x, y, z);
}

// Row r of m * (x, y, z, 1), in glm's order: (m0 x + m1 y) + (m2 z + m3 * 1).
HWY_INLINE Vec Transform4(FloatTag d, const glm::mat4& m, int r, Vec x, Vec y, Vec z) {
  const auto a = hn::Add(hn::Mul(hn::Set(d, m[0][r]), x), hn::Mul(hn::Set(d, m[1][r]), y));
  const auto b =
      hn::Add(hn::Mul(hn::Set(d, m[2][r]), z), hn::Mul(hn::Set(d, m[3][r]), hn::Set(d, 1.0f)));
  return hn::Add(a, b);
}

// Row r of m * (x, y, z), in glm's order: (m0 x + m1 y) + m2 z.
HWY_INLINE Vec Transform3(FloatTag d, const glm::mat3& m, int r, Vec x, Vec y, Vec z) {
  return hn::Add(hn::Add(hn::Mul(hn::Set(d, m[0][r]), x), hn::Mul(hn::Set(d, m[1][r]), y)),
                 hn::Mul(hn::Set(d, m[2][r]), z));
}

// The bits of `bit` where value >= 0 fails (NaN fails): outcode()'s test.
HWY_INLINE hn::Vec<IntTag> Outside(FloatTag d, Vec value, std::uint32_t bits) {
  const IntTag di;
  const auto fails = hn::Not(hn::Ge(value, hn::Zero(d)));
  return hn::IfThenElseZero(hn::RebindMask(di, fails), hn::Set(di, static_cast<int>(bits)));
}

// snap() (setup/fixed_point.hpp): pixels * 256 rounded to the nearest integer, ties to even, as
// lrint in the default rounding mode. For |v| <= 2^22, (v + 1.5 * 2^23) lands in [2^23, 2^24),
// where floats are the integers, so the addition rounds v so (1.5 * 2^23 is even) and
// subtracting it back is exact: cheaper than Round, which takes the rare lanes beyond (near
// the guard band of the largest frames). Returns the lanes outside the 32-bit integers (or
// NaN), which only vertices far beyond the guard band reach.
HWY_INLINE hn::Mask<FloatTag> Snap(FloatTag d, Vec pixels, std::int32_t* out) {
  const auto v = hn::Mul(pixels, hn::Set(d, static_cast<float>(kSubpixelScale)));
  const auto magic = hn::Set(d, 12582912.0f);
  auto rounded = hn::Sub(hn::Add(v, magic), magic);
  const auto beyond = hn::Not(hn::Le(hn::Abs(v), hn::Set(d, 4194304.0f)));
  if (!hn::AllFalse(d, beyond)) rounded = hn::IfThenElse(beyond, hn::Round(v), rounded);
  hn::Store(hn::ConvertTo(IntTag(), rounded), IntTag(), out);
  return hn::Not(hn::Lt(hn::Abs(v), hn::Set(d, 2147483520.0f)));  // the largest float below 2^31
}

// to_screen() (its definition: pipeline/reference.hpp) of clip positions (x, y, z, w): the
// perspective divide and the viewport transform, the snapped screen position to sx, sy, the window
// depth and 1/w to depth, inv_w. Returns Snap's lanes outside the integers.
HWY_INLINE hn::Mask<FloatTag> ToScreen(FloatTag d, Vec x, Vec y, Vec z, Vec w, Vec width,
                                       Vec height, std::int32_t* sx, std::int32_t* sy, float* depth,
                                       float* inv_w_out) {
  const auto half = hn::Set(d, 0.5f);
  const auto inv_w = hn::Div(hn::Set(d, 1.0f), w);
  const auto ndc_x = hn::Mul(x, inv_w), ndc_y = hn::Mul(y, inv_w), ndc_z = hn::Mul(z, inv_w);
  const auto screen_x = hn::Mul(hn::Add(hn::Mul(ndc_x, half), half), width);
  const auto screen_y = hn::Mul(hn::Sub(half, hn::Mul(ndc_y, half)), height);
  const auto outside = hn::Or(Snap(d, screen_x, sx), Snap(d, screen_y, sy));
  hn::Store(hn::Add(hn::Mul(ndc_z, half), half), d, depth);
  hn::Store(inv_w, d, inv_w_out);
  return outside;
}

void RunVertexPass(const VertexPassInput& in, std::size_t first, std::size_t count,
                   VertexPass& out) {
  const FloatTag d;
  const IntTag di;
  const std::size_t lanes = hn::Lanes(d);
  const glm::mat4& mvp = in.model_view_projection;
  const auto zero = hn::Zero(d);
  const auto width = hn::Set(d, static_cast<float>(in.width));
  const auto height = hn::Set(d, static_cast<float>(in.height));
  for (std::size_t j = 0; j < count; j += lanes) {
    const std::size_t valid = count - j;
    Vec px, py, pz;
    Load3(d, in.positions + first + j, valid, px, py, pz);
    const auto x = Transform4(d, mvp, 0, px, py, pz), y = Transform4(d, mvp, 1, px, py, pz);
    const auto z = Transform4(d, mvp, 2, px, py, pz), w = Transform4(d, mvp, 3, px, py, pz);
    hn::Store(x, d, out.x + j), hn::Store(y, d, out.y + j);
    hn::Store(z, d, out.z + j), hn::Store(w, d, out.w + j);

    // The unit world normal: normal_matrix * n, divided by its length when that is positive.
    Vec nx = zero, ny = zero, nz = zero;
    if (in.normals) {
      Vec mx, my, mz;
      Load3(d, in.normals + first + j, valid, mx, my, mz);
      nx = Transform3(d, in.normal_matrix, 0, mx, my, mz);
      ny = Transform3(d, in.normal_matrix, 1, mx, my, mz);
      nz = Transform3(d, in.normal_matrix, 2, mx, my, mz);
      const auto length =
          hn::Sqrt(hn::Add(hn::Add(hn::Mul(nx, nx), hn::Mul(ny, ny)), hn::Mul(nz, nz)));
      const auto positive = hn::Gt(length, zero);
      nx = hn::IfThenElse(positive, hn::Div(nx, length), nx);
      ny = hn::IfThenElse(positive, hn::Div(ny, length), ny);
      nz = hn::IfThenElse(positive, hn::Div(nz, length), nz);
    }
    hn::Store(nx, d, out.nx + j), hn::Store(ny, d, out.ny + j), hn::Store(nz, d, out.nz + j);

    // outcode() against the frustum and the guard band (near and far are the same planes).
    auto near_far = hn::Or(Outside(d, hn::Add(z, w), kClipNear | kClipNear << kGuardCodeShift),
                           Outside(d, hn::Sub(w, z), kClipFar | kClipFar << kGuardCodeShift));
    auto sides = [&](const ClipBounds& b, int shift) {
      const auto gx_w = hn::Mul(hn::Set(d, b.gx), w), gy_w = hn::Mul(hn::Set(d, b.gy), w);
      return hn::Or(hn::Or(Outside(d, hn::Add(x, gx_w), kClipLeft << shift),
                           Outside(d, hn::Sub(gx_w, x), kClipRight << shift)),
                    hn::Or(Outside(d, hn::Add(y, gy_w), kClipBottom << shift),
                           Outside(d, hn::Sub(gy_w, y), kClipTop << shift)));
    };
    auto codes = hn::Or(near_far, hn::Or(sides(in.frustum, 0), sides(in.guard, kGuardCodeShift)));
    if (in.guard.clips_user_plane) {  // the same plane in both bounds
      const glm::vec4& p = in.guard.user_plane;
      const auto distance =
          hn::Add(hn::Add(hn::Mul(hn::Set(d, p.x), x), hn::Mul(hn::Set(d, p.y), y)),
                  hn::Add(hn::Mul(hn::Set(d, p.z), z), hn::Mul(hn::Set(d, p.w), w)));
      codes = hn::Or(codes, Outside(d, distance, kClipUser | kClipUser << kGuardCodeShift));
    }
    const auto finite = hn::And(hn::And(hn::IsFinite(x), hn::IsFinite(y)),
                                hn::And(hn::IsFinite(z), hn::IsFinite(w)));
    codes = hn::Or(codes, hn::IfThenZeroElse(hn::RebindMask(di, finite),
                                             hn::Set(di, static_cast<int>(kNotFinite))));

    const auto outside = ToScreen(d, x, y, z, w, width, height, out.sx + j, out.sy + j,
                                  out.depth + j, out.inv_w + j);
    codes = hn::Or(codes, hn::IfThenElseZero(hn::RebindMask(di, outside),
                                             hn::Set(di, static_cast<int>(kScalarScreen))));
    hn::Store(codes, di, reinterpret_cast<std::int32_t*>(out.codes) + j);
  }
}

// to_screen() of `count` clip positions: the vertices of clipped triangles and of lines.
void ProjectToScreen(const glm::vec4* clip, int count, int width, int height, ScreenVertex* out) {
  const FloatTag d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const auto width_v = hn::Set(d, static_cast<float>(width));
  const auto height_v = hn::Set(d, static_cast<float>(height));
  alignas(64) float padded[4 * kMaxLanes];
  alignas(64) std::int32_t sx[kMaxLanes], sy[kMaxLanes];
  alignas(64) float depth[kMaxLanes], inv_w[kMaxLanes];
  for (int j = 0; j < count; j += lanes) {
    const int valid = std::min(lanes, count - j);
    std::fill(std::copy_n(&clip[j].x, 4 * valid, padded), padded + 4 * lanes, 1.0f);
    Vec x, y, z, w;
    hn::LoadInterleaved4(d, padded, x, y, z, w);
    ToScreen(d, x, y, z, w, width_v, height_v, sx, sy, depth, inv_w);
    for (int k = 0; k < valid; ++k) out[j + k] = {sx[k], sy[k], depth[k], inv_w[k]};
  }
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

HWY_EXPORT(RunVertexPass);
HWY_EXPORT(ProjectToScreen);

VertexPassKernel vertex_pass_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(RunVertexPass)[target];
}

ProjectToScreenKernel project_to_screen_kernel(SimdTarget target) {
  return HWY_DISPATCH_TABLE(ProjectToScreen)[target];
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
