// Stage: setup, the SIMD part: a triangle's varying planes several at a time (see
// PlaneSolver::planes in setup.hpp). Highway compiles this file once per SIMD target
// (foreach_target.h re-includes it) and HWY_DYNAMIC_DISPATCH picks the best target the CPU has.
// Each lane does PlaneSolver::plane's double operations in the same order (no fused
// multiply-add: -ffp-contract=off, and Highway's Mul/Sub are single instructions), and float
// <-> double conversions are exact or correctly rounded, so every target gives the scalar
// planes bit for bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/setup/setup_planes.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include "pipeline/setup/setup.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::pipeline::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Solves planes [0, k) with whole vectors and returns k; the caller does the rest in scalar.
int SolvePlanes(const PlaneSolver::Coefficients& c, const float* const values[3], int count,
                Plane* out) {
#if HWY_TARGET == HWY_EMU128 || HWY_TARGET == HWY_SCALAR
  // The portable targets' DemoteTo clamps infinities to the largest float, where a C++
  // conversion (and every x86 target) gives infinity: leave them all to the scalar code.
  (void)c, (void)values, (void)count, (void)out;
  return 0;
#else
  // At most 4 doubles (a 256-bit vector): varying counts are small (up to 16), and AVX-512's
  // 8 lanes would leave most counts a long scalar tail.
  const hn::CappedTag<double, 4> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const int lanes = static_cast<int>(hn::Lanes(dd));
  const auto x1 = hn::Set(dd, c.x1), y1 = hn::Set(dd, c.y1);
  const auto x2 = hn::Set(dd, c.x2), y2 = hn::Set(dd, c.y2);
  const auto inv_det = hn::Set(dd, c.inv_det);
  int k = 0;
  for (; k + lanes <= count; k += lanes) {
    const auto value0 = hn::LoadU(df, values[0] + k);
    const auto d0 = hn::PromoteTo(dd, value0);
    const auto v1 = hn::Sub(hn::PromoteTo(dd, hn::LoadU(df, values[1] + k)), d0);
    const auto v2 = hn::Sub(hn::PromoteTo(dd, hn::LoadU(df, values[2] + k)), d0);
    const auto dx = hn::Mul(hn::Sub(hn::Mul(v1, y2), hn::Mul(v2, y1)), inv_det);
    const auto dy = hn::Mul(hn::Sub(hn::Mul(v2, x1), hn::Mul(v1, x2)), inv_det);
    // Plane is {at_ref, dx, dy}: three interleaved floats.
    hn::StoreInterleaved3(value0, hn::DemoteTo(df, dx), hn::DemoteTo(df, dy), df,
                          reinterpret_cast<float*>(out + k));
  }
  return k;
#endif
}

}  // namespace facet::pipeline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::pipeline {

static_assert(sizeof(Plane) == 3 * sizeof(float), "SolvePlanes stores planes as float triples");

HWY_EXPORT(SolvePlanes);

void PlaneSolver::planes(const float* const values[3], int count, Plane* out) const {
  const int done = HWY_DYNAMIC_DISPATCH(SolvePlanes)(c_, values, count, out);
  for (int k = done; k < count; ++k) out[k] = plane(values[0][k], values[1][k], values[2][k]);
}

}  // namespace facet::pipeline
#endif  // HWY_ONCE
