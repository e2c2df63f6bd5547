// The table of specialised pipelines (see pipeline_table.hpp).
#include "pipeline/record/pipeline_table.hpp"

#include <algorithm>

#include "shading/lit_models.hpp"
#include "shading/models.hpp"

namespace facet::pipeline {
namespace {

// Every alpha mode of one shading model.
template <class Shading>
DrawPipeline with_alpha(AlphaMode alpha) {
  switch (alpha) {
    case AlphaMode::mask:
      return make_pipeline<Shading, AlphaMode::mask>();
    case AlphaMode::blend:
      return make_pipeline<Shading, AlphaMode::blend>();
    case AlphaMode::additive:
      return make_pipeline<Shading, AlphaMode::additive>();
    default:
      return make_pipeline<Shading, AlphaMode::opaque>();
  }
}

bool gray(glm::vec3 color) { return color.r == color.g && color.g == color.b; }

// Whether every channel of the light a Gouraud vertex gets from the lights has the same bits
// (GouraudLayout): each light's color (its radiance is color x intensity, scaled by the same
// attenuation and shadow in each channel) and the specular color are gray.
bool lights_gray(const Lighting& lighting, const Material& material) {
  return gray(material.specular_color) &&
         std::all_of(lighting.lights.begin(), lighting.lights.end(),
                     [](const Light& light) { return gray(light.color); });
}

}  // namespace

void draw_depth_alone(DrawRecord& draw) {
  static const DrawPipeline depth_alone = make_pipeline<shading::DepthOnlyShading>();
  draw.pipeline = depth_alone;
  draw.material.base_color_map = {};
  draw.material.emissive_map = {};
}

DrawPipeline pipeline_for(ShadingModel model, AlphaMode alpha) {
  using namespace shading;
  switch (model) {
    case ShadingModel::unlit:
      return with_alpha<UnlitShading>(alpha);
    case ShadingModel::vertex_color:
      return with_alpha<VertexColorShading>(alpha);
    case ShadingModel::flat:
      return with_alpha<FlatShading>(alpha);
    case ShadingModel::lambert:
      return with_alpha<LambertShading>(alpha);
    case ShadingModel::gouraud:
      return with_alpha<GouraudShading>(alpha);
    case ShadingModel::phong:
      return with_alpha<PhongShading>(alpha);
    case ShadingModel::blinn_phong:
      return with_alpha<BlinnPhongShading>(alpha);
    case ShadingModel::pbr:
      return with_alpha<PbrShading>(alpha);
    case ShadingModel::wire_overlay:
      return with_alpha<WireOverlayShading>(alpha);
    // Debug views show data: always opaque.
    case ShadingModel::depth:
      return make_pipeline<DepthShading>();
    case ShadingModel::normals:
      return make_pipeline<NormalsShading>();
    case ShadingModel::texcoords:
      return make_pipeline<TexcoordShading>();
    case ShadingModel::wireframe: {
      DrawPipeline p = make_pipeline<UnlitShading>();
      p.fills_triangles = false;
      p.draws_edges = true;
      return p;
    }
  }
  return make_pipeline<LambertShading>();
}

DrawPipeline pipeline_for(const Material& material, const Mesh& mesh, const Lighting& lighting,
                          bool shadowed) {
  // Points are unlit and take their color at setup (primitive.cpp): the vertex stage only needs
  // their positions, so they get the model with the fewest varyings to compute.
  if (mesh.topology == Topology::points) return make_pipeline<shading::ConstantColorUnlitShading>();
  const bool vertex_colored = material.use_vertex_colors && !mesh.colors.empty();
  if (material.shading == ShadingModel::gouraud && !vertex_colored && !material.base_color_map &&
      !material.emissive_map) {
    // Opaque draws only: each alpha mode is another instance of the raster loop.
    if (material.alpha_mode == AlphaMode::opaque && lights_gray(lighting, material)) {
      return make_pipeline<shading::GrayLightGouraudShading>();
    }
    return with_alpha<shading::ConstantColorGouraudShading>(material.alpha_mode);
  }
  if (material.shading == ShadingModel::unlit && !vertex_colored) {
    return with_alpha<shading::ConstantColorUnlitShading>(material.alpha_mode);
  }
  if (material.shading == ShadingModel::lambert && material.cull != CullMode::none &&
      shading::all_directional(lighting.lights) && !shadowed) {
    return with_alpha<shading::UnpositionedLambertShading>(material.alpha_mode);
  }
  return pipeline_for(material.shading, material.alpha_mode);
}

}  // namespace facet::pipeline
