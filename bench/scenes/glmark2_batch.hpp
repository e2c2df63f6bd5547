// The glmark2 shading models (glmark2_shading.hpp) a batch of pixels at a time with SIMD
// (glmark2_batch.cpp, compiled for every target Highway supports): the same formulas with the
// same IEEE operations in the same order, so the same bits as their fragment().
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
  bump_normals
};

// Linear RGBA of every pixel of `in`, as the shader's fragment() gives it. glmark2's shaders
// have no fog: the models decline fogged draws (BatchForm below). rgba holds kShadeBatch
// colors, as for shading::ShadeBatchKernel. The kernel for `target`: the frame's
// (FrameUniforms::kernels), as for the library's own kernels.
using Glmark2BatchKernel = void (*)(BatchShader shader, const shading::DrawUniforms& u,
                                    const shading::ShadeInput& in, float (*rgba)[4]);
Glmark2BatchKernel glmark2_batch_kernel(SimdTarget target);

// The batch hooks of a glmark2 model (see shading/kernels.hpp's BatchForm).
template <BatchShader kShader>
struct BatchForm {
  static bool batch_shades(const shading::DrawUniforms& u) {
    constexpr bool kTextured =
        kShader == BatchShader::basic_light_texture || kShader == BatchShader::bump_normals;
    return u.frame->lighting->fog.mode == FogMode::none &&
           (!kTextured || u.material->base_color_map);  // the texel comes sampled ahead
  }
  static void fragment_batch(const shading::DrawUniforms& u, const shading::ShadeInput& in,
                             float (*rgba)[4]) {
    glmark2_batch_kernel(u.frame->kernels->target)(kShader, u, in, rgba);
  }
};

}  // namespace facet::bench::glmark2
