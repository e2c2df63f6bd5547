// The glmark2 shading models' pixels (glmark2_shading.hpp), a batch at a time with SIMD
// (glmark2_batch.cpp, compiled for every target Highway supports): their only implementation,
// the same bits on every target.
#pragma once

#include "shading/kernels.hpp"

namespace facet::bench::glmark2 {

enum class BatchShader {
  basic_light,
  basic_light_texture,
  blinn_phong_inf,
  phong,
  cel,
  bump_poly,
  bump_normals,
  shadow_ground,
  refract_back_normal,
  refract
};

// Linear RGBA of every pixel of `in`, shaded by the formula of `shader`'s model
// (glmark2_shading.hpp), shown as an 8-bit code. No fog: glmark2 has none, and the scenes
// draw none (in.fog is not read). The textured shaders read in.base_texel, which must be
// there: their draws have the map (the scenes check it). shadow_ground looks up its material's
// base colour map itself (the frame's sample_at), at coordinates it computes per pixel, and
// refract its three maps. rgba holds kShadeBatch colors, as for shading::ShadeBatchKernel. The
// kernel for `target`: the frame's (FrameUniforms::kernels), as for the library's own kernels.
using Glmark2BatchKernel = void (*)(BatchShader shader, const shading::DrawUniforms& u,
                                    const shading::ShadeInput& in, float (*rgba)[4]);
Glmark2BatchKernel glmark2_batch_kernel(SimdTarget target);

// How a glmark2 model is shaded (see shading/kernels.hpp's BatchForm): by its kernel alone, for
// every draw and every batch size.
template <BatchShader kShader>
struct BatchForm {
  static void fragment_batch(const shading::DrawUniforms& u, const shading::ShadeInput& in,
                             float (*rgba)[4]) {
    glmark2_batch_kernel(u.frame->kernels->target)(kShader, u, in, rgba);
  }
};

}  // namespace facet::bench::glmark2
