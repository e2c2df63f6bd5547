// The shading stage's SIMD kernels for one target, fetched once per frame (core/simd_target.hpp)
// and reached by every draw through FrameUniforms::kernels (uniforms.hpp); and BatchForm, how
// the built-in models call theirs.
#pragma once

#include "core/simd_target.hpp"
#include "core/texture_sampler.hpp"
#include "shading/shade_batch.hpp"
#include "shading/texel_batch.hpp"
#include "shading/vertex_batch.hpp"

namespace facet::shading {

struct ShadingKernels {
  SimdTarget target = 0;  // for kernels outside the library (bench/scenes) to fetch theirs
  ShadeBatchKernel shade_batch = nullptr;
  FogBatchKernel fog_batch = nullptr;
  SampleBatchKernel sample_batch = nullptr;
  SampleAtKernel sample_at = nullptr;  // lookups at given levels of detail (environment images)
  GouraudVertexBatchKernel gouraud_vertex_batch = nullptr;
  GouraudLightBatchKernel gouraud_light_batch = nullptr;
};

inline ShadingKernels shading_kernels(SimdTarget target) {
  return {target,
          shade_batch_kernel(target),
          fog_batch_kernel(target),
          sample_batch_kernel(target),
          sample_at_kernel(target),
          gouraud_vertex_batch_kernel(target),
          gouraud_light_batch_kernel(target)};
}

// How the built-in models are shaded (models.hpp; the raster loop, pipeline/raster/raster.hpp,
// looks for these): the maps they read, and fragment_batch, which shades a batch of pixels and
// applies in.fog. The raster loop is compiled per model; the one batch kernel takes the model and
// fog at run time, constants of the draw that every vector of it tests the same way
// (BENCHMARKS.md, "Per-draw constants").
template <BatchModel kModel>
struct BatchForm {
  static constexpr unsigned kMapsRead = maps_read(kModel);
  static void fragment_batch(const DrawUniforms& u, const ShadeInput& in, float (*rgba)[4]) {
    u.frame->kernels->shade_batch(kModel, u, in, rgba);
  }
};

}  // namespace facet::shading
