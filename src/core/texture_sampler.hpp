// Texture lookups at given levels of detail, any number at once: what Texture::sample does for
// one, and what callers with many lookups of one texture (environment lookups of a batch of
// pixels) call directly. Compiled for every SIMD target Highway supports (texture_sampler.cpp,
// on the filtering of texture_sample-inl.h); every target gives the same bits.
#pragma once

#include "core/simd_target.hpp"
#include "facet/texture.hpp"

namespace facet {

// rgba[i] = linear RGBA of `texture` sampled with `sampler` at (u[i], v[i]) and level of detail
// lod[i] (Texture::sample), for i in [0, count).
using SampleAtKernel = void (*)(const Texture& texture, const Sampler& sampler, const float* u,
                                const float* v, const float* lod, int count, float (*rgba)[4]);
SampleAtKernel sample_at_kernel(SimdTarget target);

}  // namespace facet
