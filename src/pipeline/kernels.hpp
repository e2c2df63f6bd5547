// Every SIMD kernel of the pipeline for one target, fetched once per frame when the frame runs
// (frame_run.cpp) from the target Highway has chosen (core/simd_target.hpp): the stages call
// through these pointers, never through HWY_DYNAMIC_DISPATCH, so one frame runs on one target
// and a target a test forces is followed from the next frame on.
#pragma once

#include "core/simd_target.hpp"
#include "core/srgb_row.hpp"
#include "pipeline/geometry/cull_batch.hpp"
#include "pipeline/geometry/vertex_pass.hpp"
#include "pipeline/geometry/vertex_rows.hpp"
#include "pipeline/output/fill_row.hpp"
#include "pipeline/output/sample_average_row.hpp"
#include "pipeline/output/sky_row.hpp"
#include "pipeline/output/tone_map_row.hpp"
#include "pipeline/raster/block_raster.hpp"
#include "pipeline/setup/setup_batch.hpp"
#include "shading/kernels.hpp"

namespace facet::pipeline {

struct Kernels {
  VertexPassKernel vertex_pass = nullptr;
  ProjectToScreenKernel project_to_screen = nullptr;
  StoreProjectedKernel store_projected = nullptr;
  StoreOverWKernel store_over_w = nullptr;
  CullKernel cull = nullptr;
  SetupBatchKernel setup = nullptr;
  RasterKernels raster{};
  SkyRowKernel sky_row = nullptr;
  shading::EncodeSrgbRowKernel encode_srgb_row = nullptr;
  shading::EncodeSrgbRowKnowingKernel encode_srgb_row_knowing = nullptr;
  shading::RoundUnorm8RowKernel round_unorm8_row = nullptr;
  ToneMapRowKernel tone_map_row = nullptr;
  AverageSamplesRowKernel average_samples_row = nullptr;
  FillFloatRowKernel fill_float_row = nullptr;
  FillColorRowKernel fill_color_row = nullptr;
  shading::ShadingKernels shading;
};

inline Kernels kernels_for(SimdTarget target) {
  return {vertex_pass_kernel(target),
          project_to_screen_kernel(target),
          store_projected_kernel(target),
          store_over_w_kernel(target),
          cull_kernel(target),
          setup_batch_kernel(target),
          raster_kernels(target),
          sky_row_kernel(target),
          shading::encode_srgb_row_kernel(target),
          shading::encode_srgb_row_knowing_kernel(target),
          shading::round_unorm8_row_kernel(target),
          tone_map_row_kernel(target),
          average_samples_row_kernel(target),
          fill_float_row_kernel(target),
          fill_color_row_kernel(target),
          shading::shading_kernels(target)};
}

}  // namespace facet::pipeline
