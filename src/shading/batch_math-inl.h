// Per-target vector helpers shared by the SIMD shading kernels (shade_batch.cpp, vertex_batch.cpp,
// light_batch-inl.h, shadow_batch-inl.h and bench/scenes/glmark2_batch.cpp): included inside each
// file's HWY_NAMESPACE, once per target, the Highway "-inl.h" way (the guard below toggles with
// HWY_TARGET_TOGGLE). Each helper is glm's operation (dot, cross, normalize, reflect) or
// std::min/max, lane by lane, with the same IEEE operations in the same order.
#if defined(FACET_SHADING_BATCH_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_BATCH_MATH_INL_H_
#undef FACET_SHADING_BATCH_MATH_INL_H_
#else
#define FACET_SHADING_BATCH_MATH_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>

#include "core/color.hpp"
#include "core/portable_math.hpp"
#include "core/truncate_in_range-inl.h"
#include "shading/shade_batch.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace simd = facet::simd::HWY_NAMESPACE;

// Eight lanes at most, as in texel_batch.cpp: batches are often a few pixels.
using BatchTag = hn::CappedTag<float, 8>;
using BatchV = hn::Vec<BatchTag>;

struct Vec3V {
  BatchV x, y, z;
};

HWY_INLINE Vec3V Load3(const float (*v)[kShadeBatch], int slot, int j) {
  const BatchTag d;
  return {hn::Load(d, v[slot] + j), hn::Load(d, v[slot + 1] + j), hn::Load(d, v[slot + 2] + j)};
}

// Load3's counterpart: v into slots slot .. slot + 2 at pixel j.
HWY_INLINE void Store3(const Vec3V& v, float (*out)[kShadeBatch], int slot, int j) {
  const BatchTag d;
  hn::Store(v.x, d, out[slot] + j);
  hn::Store(v.y, d, out[slot + 1] + j);
  hn::Store(v.z, d, out[slot + 2] + j);
}

HWY_INLINE Vec3V Set3(const glm::vec3& v) {
  const BatchTag d;
  return {hn::Set(d, v.x), hn::Set(d, v.y), hn::Set(d, v.z)};
}

// glm::dot: (x*x' + y*y') + z*z'.
HWY_INLINE BatchV Dot(const Vec3V& a, const Vec3V& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}

HWY_INLINE Vec3V Scale(const Vec3V& v, BatchV s) {
  return {hn::Mul(v.x, s), hn::Mul(v.y, s), hn::Mul(v.z, s)};
}

HWY_INLINE Vec3V Negate(const Vec3V& v) { return {hn::Neg(v.x), hn::Neg(v.y), hn::Neg(v.z)}; }

// glm::cross(a, b).
HWY_INLINE Vec3V Cross(const Vec3V& a, const Vec3V& b) {
  return {hn::Sub(hn::Mul(a.y, b.z), hn::Mul(b.y, a.z)),
          hn::Sub(hn::Mul(a.z, b.x), hn::Mul(b.z, a.x)),
          hn::Sub(hn::Mul(a.x, b.y), hn::Mul(b.x, a.y))};
}

// glm::reflect(i, n): i - (n * dot(n, i)) * 2.
HWY_INLINE Vec3V Reflect(const Vec3V& i, const Vec3V& n) {
  const BatchV n_dot_i = Dot(n, i);
  const BatchV two = hn::Set(BatchTag(), 2.0f);
  return {hn::Sub(i.x, hn::Mul(hn::Mul(n.x, n_dot_i), two)),
          hn::Sub(i.y, hn::Mul(hn::Mul(n.y, n_dot_i), two)),
          hn::Sub(i.z, hn::Mul(hn::Mul(n.z, n_dot_i), two))};
}

// glm::normalize: v * (1 / sqrt(|v|^2)), NaN for a zero vector as in glm.
HWY_INLINE Vec3V Normalize(const Vec3V& v) {
  const BatchTag d;
  return Scale(v, hn::Div(hn::Set(d, 1.0f), hn::Sqrt(Dot(v, v))));
}

// safe_normalize(): the same, or zero where |v|^2 is not positive.
HWY_INLINE Vec3V SafeNormalize(const Vec3V& v) {
  const BatchTag d;
  const BatchV length_squared = Dot(v, v);
  const auto positive = hn::Gt(length_squared, hn::Zero(d));
  const BatchV inverse = hn::Div(hn::Set(d, 1.0f), hn::Sqrt(length_squared));
  return {hn::IfThenElseZero(positive, hn::Mul(v.x, inverse)),
          hn::IfThenElseZero(positive, hn::Mul(v.y, inverse)),
          hn::IfThenElseZero(positive, hn::Mul(v.z, inverse))};
}

// std::max(a, b) and std::min(a, b): a unless the comparison says otherwise (NaN in a stays).
HWY_INLINE BatchV StdMax(BatchV a, BatchV b) { return hn::IfThenElse(hn::Lt(a, b), b, a); }
HWY_INLINE BatchV StdMin(BatchV a, BatchV b) { return hn::IfThenElse(hn::Lt(b, a), b, a); }

// log2 of x where it is positive and finite, log2_special(x) (portable_math.hpp) elsewhere.
HWY_INLINE BatchV WithLog2Special(BatchV x, BatchV log2) {
  const BatchTag df;
  const BatchV infinity = hn::Set(df, std::numeric_limits<float>::infinity());
  const BatchV zero_or_invalid =
      hn::IfThenElse(hn::Eq(x, hn::Zero(df)), hn::Neg(infinity),
                     hn::Set(df, std::numeric_limits<float>::quiet_NaN()));
  const BatchV result = hn::IfThenElse(hn::Gt(x, hn::Zero(df)), log2, zero_or_invalid);
  return hn::IfThenElse(hn::Eq(x, infinity), infinity, result);
}

// portable_math.hpp, lane by lane.
HWY_INLINE BatchV PortableLog2(BatchV x) {
  namespace c = portable_math;
  const BatchTag df;
  const hn::RebindToSigned<BatchTag> di;
  const auto subnormal = hn::Lt(x, hn::Set(df, c::kSmallestNormal));
  const BatchV scaled = hn::IfThenElse(subnormal, hn::Mul(x, hn::Set(df, c::kTwoTo23)), x);
  const BatchV bias = hn::IfThenElse(subnormal, hn::Set(df, 150.0f), hn::Set(df, 127.0f));
  const auto bits = hn::BitCast(di, scaled);
  BatchV e = hn::Sub(hn::ConvertTo(df, hn::ShiftRight<23>(bits)), bias);
  BatchV m =
      hn::BitCast(df, hn::Or(hn::And(bits, hn::Set(di, 0x007fffff)), hn::Set(di, 0x3f800000)));
  const auto big = hn::Gt(m, hn::Set(df, c::kSqrt2));
  m = hn::IfThenElse(big, hn::Mul(m, hn::Set(df, 0.5f)), m);
  e = hn::IfThenElse(big, hn::Add(e, hn::Set(df, 1.0f)), e);
  const BatchV one = hn::Set(df, 1.0f);
  const BatchV s = hn::Div(hn::Sub(m, one), hn::Add(m, one));
  const BatchV s2 = hn::Mul(s, s);
  BatchV poly = hn::Add(hn::Set(df, c::kLog2C5), hn::Mul(s2, hn::Set(df, c::kLog2C7)));
  poly = hn::Add(hn::Set(df, c::kLog2C3), hn::Mul(s2, poly));
  poly = hn::Add(hn::Set(df, c::kLog2C1), hn::Mul(s2, poly));
  return WithLog2Special(x, hn::Add(e, hn::Mul(s, poly)));
}

// lod_log2() of portable_math.hpp, lane by lane.
HWY_INLINE BatchV LodLog2(BatchV x) {
  namespace c = portable_math;
  const BatchTag df;
  const hn::RebindToSigned<BatchTag> di;
  const auto bits = hn::BitCast(di, x);
  const BatchV e = hn::ConvertTo(df, hn::Sub(hn::ShiftRight<23>(bits), hn::Set(di, 127)));
  const BatchV f = hn::Sub(
      hn::BitCast(df, hn::Or(hn::And(bits, hn::Set(di, 0x007fffff)), hn::Set(di, 0x3f800000))),
      hn::Set(df, 1.0f));
  BatchV poly = hn::Add(hn::Set(df, c::kLodLog2C2), hn::Mul(f, hn::Set(df, c::kLodLog2C3)));
  poly = hn::Add(hn::Set(df, c::kLodLog2C1), hn::Mul(f, poly));
  return WithLog2Special(x, hn::Add(e, hn::Mul(f, poly)));
}

HWY_INLINE BatchV PortableExp2(BatchV t) {
  namespace c = portable_math;
  const BatchTag d;
  const hn::RebindToSigned<BatchTag> di;
  const BatchV n = hn::Floor(hn::Add(t, hn::Set(d, 0.5f)));
  const BatchV f = hn::Sub(t, n);
  BatchV p = hn::Add(hn::Set(d, c::kExp2C6), hn::Mul(f, hn::Set(d, c::kExp2C7)));
  for (float k : {c::kExp2C5, c::kExp2C4, c::kExp2C3, c::kExp2C2, c::kExp2C1, 1.0f}) {
    p = hn::Add(hn::Set(d, k), hn::Mul(f, p));
  }
  const BatchV scale =
      hn::BitCast(d, hn::ShiftLeft<23>(hn::Add(hn::ConvertTo(di, n), hn::Set(di, 127))));
  const BatchV result =
      hn::IfThenElse(hn::Ge(t, hn::Set(d, c::kExp2Highest)),
                     hn::Set(d, std::numeric_limits<float>::infinity()), hn::Mul(p, scale));
  const BatchV lowest = hn::Set(d, c::kExp2Lowest);
  const BatchV below = hn::IfThenElseZero(hn::Not(hn::Lt(t, lowest)), t);  // NaN stays NaN
  return hn::IfThenElse(hn::Ge(t, lowest), result, below);
}

HWY_INLINE BatchV PortableExp(BatchV x) {
  return PortableExp2(hn::Mul(x, hn::Set(BatchTag(), portable_math::kLog2E)));
}

// portable_pow(x, s) for one s (s == 0 is the caller's: x^0 = 1): the same multiplications for
// a whole s (portable_math::is_whole_power), else the same 2^(s log2 x).
HWY_INLINE BatchV PortablePow(BatchV x, float s) {
  if (portable_math::is_whole_power(s)) {
    auto n = static_cast<std::uint32_t>(s);
    BatchV power = x;  // x^(2^k), k the bit of n looked at
    while ((n & 1u) == 0) n >>= 1, power = hn::Mul(power, power);
    BatchV result = power;
    for (n >>= 1; n != 0; n >>= 1) {
      power = hn::Mul(power, power);
      if (n & 1u) result = hn::Mul(result, power);
    }
    return result;
  }
  return PortableExp2(hn::Mul(hn::Set(BatchTag(), s), PortableLog2(x)));
}

// A map's texels for pixels j.. (ShadeInput::map_texel), a vector per channel.
HWY_INLINE void LoadTexel(const float (*texel)[4], int j, BatchV t[4]) {
  hn::LoadInterleaved4(BatchTag(), &texel[j][0], t[0], t[1], t[2], t[3]);
}

// The lanes of a Vec3V as glm vectors, for the steps done a lane at a time (environment
// lookups: a texture read per lane).
struct Lanes3 {
  alignas(64) float x[8], y[8], z[8];
  explicit Lanes3(const Vec3V& v) {
    const BatchTag d;
    hn::Store(v.x, d, x), hn::Store(v.y, d, y), hn::Store(v.z, d, z);
  }
  glm::vec3 operator[](int lane) const { return {x[lane], y[lane], z[lane]}; }
  void set(int lane, glm::vec3 v) { x[lane] = v.x, y[lane] = v.y, z[lane] = v.z; }
  Vec3V load() const {
    const BatchTag d;
    return {hn::Load(d, x), hn::Load(d, y), hn::Load(d, z)};
  }
};

// Where pixel n's color goes (ShadeInput::rgba_row_stride): a vector of 8 lanes or fewer
// starting at a multiple of its width stays within one row of 8.
HWY_INLINE float (*ColorAt(float (*rgba)[4], int row_stride, int n))[4] {
  return rgba + (n / 8) * row_stride + n % 8;
}

// Writes a vector's colors as RGBA from rgba[0] on. A batch's colors array holds kShadeBatch
// entries, a whole number of vectors (shade_batch.hpp), so the lanes past the batch's count
// write scratch entries. (A copy of just the batch's last few colors, of variable size, would
// compile to a "rep movs", slow to start.)
HWY_INLINE void StoreColors(const BatchV color[4], float (*rgba)[4]) {
  hn::StoreInterleaved4(color[0], color[1], color[2], color[3], BatchTag(), &rgba[0][0]);
}

// Display values (models.hpp; the debug views' and glmark2's output): a value clamped to
// [0, 1] (NaN to 0), times 255, plus a half, truncated to its 8-bit code (DisplayCode), which
// DecodeDisplayCodes turns into the color the tile stores, or which a tile of codes holds
// (StorePackedCodes; StoreDisplay below chooses).
using DisplayCodes = std::int32_t (*)[kShadeBatch];
HWY_INLINE hn::Vec<hn::RebindToSigned<BatchTag>> DisplayCode(BatchV value) {
  const BatchTag d;
  const BatchV clamped =
      StdMin(hn::IfThenElseZero(hn::Gt(value, hn::Zero(d)), value), hn::Set(d, 1.0f));
  return simd::TruncateInRange(hn::RebindToSigned<BatchTag>(),
                               hn::Add(hn::Mul(clamped, hn::Set(d, 255.0f)), hn::Set(d, 0.5f)));
}
HWY_INLINE void StoreDisplayCodes(const Vec3V& rgb, int j, DisplayCodes codes) {
  const hn::RebindToSigned<BatchTag> di;
  const BatchV channel[3] = {rgb.x, rgb.y, rgb.z};
  for (int c = 0; c < 3; ++c) hn::Store(DisplayCode(channel[c]), di, codes[c] + j);
}

// The codes of a vector of display values, alpha 1 (code 255), as four bytes RGBA a pixel
// (ShadeInput::codes), from pixel j of rows row_stride apart on.
static_assert(std::endian::native == std::endian::little, "codes are stored as RGBA bytes");
HWY_INLINE void StorePackedCodes(const Vec3V& rgb, int j, int row_stride, std::uint32_t* codes) {
  const hn::RebindToUnsigned<BatchTag> du;
  const auto r = hn::BitCast(du, DisplayCode(rgb.x)), g = hn::BitCast(du, DisplayCode(rgb.y));
  const auto b = hn::BitCast(du, DisplayCode(rgb.z));
  const auto packed = hn::Or(hn::Or(r, hn::ShiftLeft<8>(g)),
                             hn::Or(hn::ShiftLeft<16>(b), hn::Set(du, 0xFF000000u)));
  hn::StoreU(packed, du, codes + (j / 8) * row_stride + j % 8);
}

// Pixel n's color (ColorAt) = its codes as display values (models.hpp),
// alpha 1, for n < count. Decoded, the sRGB table is read one channel at a time after the SIMD loop
// (scalar loads, not gathers, as in resolve); in display-referred frames, code / 255 with SIMD.
HWY_INLINE void DecodeDisplayCodes(DisplayCodes codes, int count, bool referred, int row_stride,
                                   float (*rgba)[4]) {
  if (referred) {
    const BatchTag d;
    const hn::RebindToSigned<BatchTag> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const BatchV inverse_255 = hn::Set(d, kInverse255);
    for (int j = 0; j < count; j += lanes) {
      BatchV color[4];
      for (int c = 0; c < 3; ++c) {
        color[c] = hn::Mul(hn::ConvertTo(d, hn::Load(di, codes[c] + j)), inverse_255);
      }
      color[3] = hn::Set(d, 1.0f);
      StoreColors(color, ColorAt(rgba, row_stride, j));
    }
    return;
  }
  const auto& decode = srgb_tables().decode;
  for (int n = 0; n < count; ++n) {
    float* out = *ColorAt(rgba, row_stride, n);
    for (int c = 0; c < 3; ++c) out[c] = decode[codes[c][n]];
    out[3] = 1.0f;
  }
}

// Where a batch's display values go: their codes, which FinishDisplay decodes into the colors
// once the batch is shaded; or, for a tile of codes (ShadeInput::codes), the codes packed as
// its pixels' bytes, with the same rounding.
struct DisplayOut {
  DisplayOut(const FrameUniforms& frame, const ShadeInput& in, float (*colors)[4])
      : referred(frame.display_referred),
        row_stride(in.rgba_row_stride),
        rgba(colors),
        tile_codes(in.codes) {}
  alignas(64) std::int32_t codes[3][kShadeBatch];
  bool referred;
  int row_stride;
  float (*rgba)[4];
  std::uint32_t* tile_codes;  // ShadeInput::codes
};
HWY_INLINE void StoreDisplay(const Vec3V& rgb, int j, DisplayOut& out) {
  if (out.tile_codes != nullptr) {
    StorePackedCodes(rgb, j, out.row_stride, out.tile_codes);
    return;
  }
  StoreDisplayCodes(rgb, j, out.codes);
}
HWY_INLINE void FinishDisplay(DisplayOut& out, int count) {
  if (out.tile_codes == nullptr) {
    DecodeDisplayCodes(out.codes, count, out.referred, out.row_stride, out.rgba);
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_BATCH_MATH_INL_H_
