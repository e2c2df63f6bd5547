// Distance fog's share for a vector of pixels: what the batch kernels fog their colors with
// (shade_batch.cpp), and what a planar reflection, fogged by its own pass, is kept from being
// fogged by again (planar_reflection-inl.h). Included inside each file's HWY_NAMESPACE after
// batch_math-inl.h, the Highway "-inl.h" way.
#if defined(FACET_SHADING_FOG_BATCH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_FOG_BATCH_INL_H_
#undef FACET_SHADING_FOG_BATCH_INL_H_
#else
#define FACET_SHADING_FOG_BATCH_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>

#include "facet/light.hpp"
#include "shading/batch_math-inl.h"
#include "shading/shade_batch.hpp"
#include "shading/uniforms.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::shading::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The fraction of the color that distance fog keeps at the ViewDepth (uniforms.hpp) of pixels
// j.. of `in`: (end - depth) / (end - start) or e^(-density depth) (portable_math.hpp's
// polynomial: the same bits on every CPU), clamped to [0, 1].
HWY_INLINE BatchV FogKeep(const Fog& fog, const ViewDepth& depth, const ShadeInput& in, int j) {
  const BatchTag d;
  const BatchV w = hn::Add(hn::Add(hn::Mul(hn::Set(d, depth.from_w), hn::Load(d, in.w + j)),
                                   hn::Mul(hn::Set(d, depth.from_z), hn::Load(d, in.z + j))),
                           hn::Set(d, depth.offset));
  BatchV keep;
  if (fog.mode == FogMode::linear) {
    keep =
        hn::Div(hn::Sub(hn::Set(d, fog.end), w), hn::Set(d, std::max(fog.end - fog.start, 1e-6f)));
  } else {
    keep = PortableExp(hn::Mul(hn::Set(d, -fog.density), w));
  }
  const BatchV one = hn::Set(d, 1.0f);
  return hn::IfThenElse(hn::Lt(keep, hn::Zero(d)), hn::Zero(d),
                        hn::IfThenElse(hn::Lt(one, keep), one, keep));  // std::clamp
}

}  // namespace facet::shading::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_FOG_BATCH_INL_H_
