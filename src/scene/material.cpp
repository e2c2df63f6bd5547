// Names of shading models and cull modes, as the command line spells them.
#include "facet/material.hpp"

#include <array>
#include <utility>

namespace facet {
namespace {

constexpr std::array<std::pair<ShadingModel, std::string_view>, 8> kShadingNames{{
    {ShadingModel::unlit, "unlit"},
    {ShadingModel::vertex_color, "vertex_color"},
    {ShadingModel::flat, "flat"},
    {ShadingModel::lambert, "lambert"},
    {ShadingModel::depth, "depth"},
    {ShadingModel::normals, "normals"},
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

}  // namespace

std::string_view to_string(ShadingModel model) { return name_of(kShadingNames, model); }
std::string_view to_string(CullMode mode) { return name_of(kCullNames, mode); }
bool parse_shading_model(std::string_view name, ShadingModel& out) {
  return parse(kShadingNames, name, out);
}
bool parse_cull_mode(std::string_view name, CullMode& out) { return parse(kCullNames, name, out); }

}  // namespace facet
