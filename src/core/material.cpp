// Names of shading models and cull modes, as the command line spells them.
#include "facet/material.hpp"

#include <array>
#include <utility>

namespace facet {
namespace {

constexpr std::array<std::pair<ShadingModel, std::string_view>, 13> kShadingNames{{
    {ShadingModel::unlit, "unlit"},
    {ShadingModel::vertex_color, "vertex_color"},
    {ShadingModel::flat, "flat"},
    {ShadingModel::lambert, "lambert"},
    {ShadingModel::gouraud, "gouraud"},
    {ShadingModel::phong, "phong"},
    {ShadingModel::blinn_phong, "blinn_phong"},
    {ShadingModel::pbr, "pbr"},
    {ShadingModel::depth, "depth"},
    {ShadingModel::normals, "normals"},
    {ShadingModel::texcoords, "texcoords"},
    {ShadingModel::wireframe, "wireframe"},
    {ShadingModel::wire_overlay, "wire_overlay"},
}};

constexpr std::array<std::pair<CullMode, std::string_view>, 3> kCullNames{{
    {CullMode::back, "back"},
    {CullMode::front, "front"},
    {CullMode::none, "none"},
}};

template <class Enum, std::size_t N>
std::string_view name_of(const std::array<std::pair<Enum, std::string_view>, N>& names, Enum e) {
  for (const auto& [value, name] : names) {
    if (value == e) return name;
  }
  return "?";
}

template <class Enum, std::size_t N>
bool parse(const std::array<std::pair<Enum, std::string_view>, N>& names, std::string_view text,
           Enum& out) {
  for (const auto& [value, name] : names) {
    if (name == text) {
      out = value;
      return true;
    }
  }
  return false;
}

constexpr std::array<std::pair<AlphaMode, std::string_view>, 4> kAlphaNames{{
    {AlphaMode::opaque, "opaque"},
    {AlphaMode::mask, "mask"},
    {AlphaMode::blend, "blend"},
    {AlphaMode::additive, "additive"},
}};

}  // namespace

std::vector<std::string_view> shading_model_names() {
  std::vector<std::string_view> names;
  for (const auto& entry : kShadingNames) names.push_back(entry.second);
  return names;
}

std::string_view to_string(AlphaMode mode) { return name_of(kAlphaNames, mode); }

std::string_view to_string(ShadingModel model) { return name_of(kShadingNames, model); }
std::string_view to_string(CullMode mode) { return name_of(kCullNames, mode); }
bool parse_shading_model(std::string_view name, ShadingModel& out) {
  return parse(kShadingNames, name, out);
}
bool parse_cull_mode(std::string_view name, CullMode& out) { return parse(kCullNames, name, out); }

}  // namespace facet
