// Stage: shade (see shade.hpp).
#include "pipeline/shade.hpp"

#include "shading/models.hpp"

namespace facet::pipeline {

DrawPipeline pipeline_for(ShadingModel model) {
  using namespace shading;
  DrawPipeline p;
  switch (model) {
    case ShadingModel::unlit:
      p = make_pipeline<UnlitShading>();
      break;
    case ShadingModel::vertex_color:
      p = make_pipeline<VertexColorShading>();
      break;
    case ShadingModel::flat:
      p = make_pipeline<FlatShading>();
      break;
    case ShadingModel::lambert:
    case ShadingModel::gouraud:  // placeholders until the lit models land
    case ShadingModel::phong:
    case ShadingModel::blinn_phong:
    case ShadingModel::pbr:
    case ShadingModel::texcoords:
      p = make_pipeline<LambertShading>();
      break;
    case ShadingModel::depth:
      p = make_pipeline<DepthShading>();
      break;
    case ShadingModel::normals:
      p = make_pipeline<NormalsShading>();
      break;
    case ShadingModel::wireframe:
      p = make_pipeline<UnlitShading>();
      p.fills_triangles = false;
      p.draws_edges = true;
      break;
    case ShadingModel::wire_overlay:
      p = make_pipeline<WireOverlayShading>();
      break;
  }
  return p;
}

}  // namespace facet::pipeline
