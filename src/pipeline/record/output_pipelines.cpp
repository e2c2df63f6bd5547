// The pipelines of the extra outputs' passes (see output_pipelines.hpp).
#include "pipeline/record/output_pipelines.hpp"

#include "pipeline/record/pipeline_table.hpp"
#include "shading/output_models.hpp"

namespace facet::pipeline {
namespace {

template <bool kMasked>
using WorldNormalOutput = shading::NormalOutput<kMasked, false>;
template <bool kMasked>
using CameraNormalOutput = shading::NormalOutput<kMasked, true>;

// A model of the extra outputs, cut out at the material's alpha or drawn opaque.
template <template <bool> class Model>
DrawPipeline cut_out_or_opaque(AlphaMode alpha) {
  if (alpha == AlphaMode::mask) return make_pipeline<Model<true>, AlphaMode::mask>();
  return make_pipeline<Model<false>>();
}

}  // namespace

DrawPipeline output_pipeline(OutputPass pass, NormalSpace normals, AlphaMode alpha) {
  switch (pass) {
    case OutputPass::depth_and_instance:
      return cut_out_or_opaque<shading::DepthAndInstanceOutput>(alpha);
    case OutputPass::normals:
      return normals == NormalSpace::camera ? cut_out_or_opaque<CameraNormalOutput>(alpha)
                                            : cut_out_or_opaque<WorldNormalOutput>(alpha);
    case OutputPass::triangles:
      return cut_out_or_opaque<shading::TriangleOutput>(alpha);
    case OutputPass::albedo:
      break;
  }
  if (alpha == AlphaMode::mask) return make_pipeline<shading::AlbedoOutput, AlphaMode::mask>();
  return make_pipeline<shading::AlbedoOutput>();
}

}  // namespace facet::pipeline
