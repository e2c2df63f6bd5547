// The procedural sky (an Environment without an image) on vectors of directions: its only
// implementation, for the background (pipeline/output/sky_row.cpp), the reflections and light of
// the shading kernels (environment_batch-inl.h) and the irradiance harmonics of a sky
// (sky_batch.cpp). Included inside each file's HWY_NAMESPACE, the Highway "-inl.h" way; every
// target computes the same IEEE operations in the same order (no fused multiply-add), which
// tests/support/sky_reference.hpp writes out in scalar code for the tests.
#if defined(FACET_SHADING_SKY_GRADIENT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_SKY_GRADIENT_INL_H_
#undef FACET_SHADING_SKY_GRADIENT_INL_H_
#else
#define FACET_SHADING_SKY_GRADIENT_INL_H_
#endif

#include <hwy/highway.h>

#include "facet/light.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The sky's radiance (its gradient times the environment's intensity) in unit directions whose
// upward (y) component is `up`: from the horizon toward the zenith above it, t = sqrt(up), and
// toward the ground below it, four times as steeply, t = sqrt(min(-up 4, 1)) (square roots widen
// the bright band at the horizon, as a real sky looks); glm::mix's a (1 - t) + b t. Each lane
// takes the square root of its own side's argument only, and picks its side's far color before
// the one mix: the same operations, per lane, as a mix toward each side and a choice after.
template <class D>
HWY_INLINE void SkyRadiance(D d, const Environment& env, hn::Vec<D> up, hn::Vec<D> rgb[3]) {
  const hn::Vec<D> one = hn::Set(d, 1.0f);
  const auto above = hn::Ge(up, hn::Zero(d));
  const hn::Vec<D> below_t = hn::Mul(hn::Neg(up), hn::Set(d, 4.0f));
  const hn::Vec<D> t =
      hn::Sqrt(hn::IfThenElse(above, up, hn::IfThenElse(hn::Lt(one, below_t), one, below_t)));
  const hn::Vec<D> one_minus_t = hn::Sub(one, t);
  const hn::Vec<D> intensity = hn::Set(d, env.intensity);
  for (int c = 0; c < 3; ++c) {
    const hn::Vec<D> far =
        hn::IfThenElse(above, hn::Set(d, env.sky_zenith[c]), hn::Set(d, env.ground[c]));
    rgb[c] = hn::Mul(hn::Add(hn::Mul(hn::Set(d, env.sky_horizon[c]), one_minus_t), hn::Mul(far, t)),
                     intensity);
  }
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_SKY_GRADIENT_INL_H_
