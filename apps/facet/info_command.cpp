// `facet info MODEL`: a readable summary of an imported model, one fact per line, values
// aligned in a column so files can be compared at a glance.
#include "info_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "facet/import.hpp"
#include "model_import.hpp"
#include "scene_options.hpp"

namespace facet::cli {
namespace {

constexpr int kLabelWidth = 11;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string vec(glm::vec3 v) {
  return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}

void row(const std::string& label, const std::string& value) {
  std::printf("%-*s %s\n", kLabelWidth, label.c_str(), value.c_str());
}

void item(const std::string& text) { std::printf("  %s\n", text.c_str()); }

// "name" padded, so the columns after it line up.
std::string pad(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

std::string texture_name(const std::shared_ptr<const Texture>& texture) {
  if (!texture) return "-";
  std::string name = texture->name();
  if (name.rfind("embedded:", 0) == 0) return name;
  std::string file = std::filesystem::path(name).filename().string();
  return file.empty() ? "(unnamed)" : file;
}

std::string maps_of(const Material& m) {
  std::string out;
  auto add = [&](const char* what, const TextureMap& map) {
    if (!map) return;
    out += (out.empty() ? "" : ", ") + std::string(what) + " " + texture_name(map.texture);
  };
  add("base_color", m.base_color_map);
  add("normal", m.normal_map);
  add("specular", m.specular_map);
  add("metallic_roughness", m.metallic_roughness_map);
  add("occlusion", m.occlusion_map);
  add("emissive", m.emissive_map);
  return out.empty() ? "no maps" : out;
}

void print_geometry(const Scene& scene) {
  std::size_t vertices = 0, lines = 0, points = 0;
  for (const auto& mesh : scene.meshes) {
    vertices += mesh->positions.size();
    if (mesh->topology == Topology::lines) lines += mesh->primitive_count();
    if (mesh->topology == Topology::points) points += mesh->primitive_count();
  }
  row("meshes", std::to_string(scene.meshes.size()));
  row("triangles", std::to_string(scene.triangle_count()) + " (drawn, over every instance)");
  if (lines > 0) row("lines", std::to_string(lines));
  if (points > 0) row("points", std::to_string(points));
  row("vertices", std::to_string(vertices));
  row("nodes", std::to_string(scene.nodes.size()));
  Bounds b = scene.bounds();
  if (b.empty()) {
    row("bounds", "empty");
  } else {
    row("bounds", "min " + vec(b.min) + "  max " + vec(b.max) + "  size " + vec(b.max - b.min));
  }
}

void print_materials(const Scene& scene) {
  row("materials", std::to_string(scene.materials.size()));
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    std::string text = pad(std::to_string(i), 3) + pad(m.name.empty() ? "(unnamed)" : m.name, 20) +
                       pad(std::string(to_string(m.shading)), 12) + maps_of(m);
    if (m.alpha_mode != AlphaMode::opaque)
      text += ", alpha " + std::string(to_string(m.alpha_mode));
    item(text);
  }
}

void print_textures(const Scene& scene) {
  row("textures", std::to_string(scene.textures.size()));
  for (std::size_t i = 0; i < scene.textures.size(); ++i) {
    const Texture& t = *scene.textures[i];
    std::string size = std::to_string(t.width()) + "x" + std::to_string(t.height());
    item(pad(std::to_string(i), 3) + pad(texture_name(scene.textures[i]), 24) + pad(size, 11) +
         std::to_string(t.level_count()) + " mip levels" + (t.srgb() ? ", sRGB" : ""));
  }
}

std::string describe(const Light& light) {
  std::string text;
  switch (light.type) {
    case LightType::directional:
      text = pad("directional", 12) + "direction " + vec(light.direction);
      break;
    case LightType::point:
      text = pad("point", 12) + "at " + vec(light.position);
      break;
    case LightType::spot:
      text = pad("spot", 12) + "at " + vec(light.position) + " toward " + vec(light.direction) +
             ", cone " + number(light.inner_cone_degrees) + ".." +
             number(light.outer_cone_degrees) + " degrees";
      break;
  }
  text += ", color " + vec(light.color) + ", intensity " + number(light.intensity);
  if (light.range > 0.0f) text += ", range " + number(light.range);
  return text;
}

void print_lights_and_cameras(const Scene& scene) {
  if (!scene.has_file_lights) {
    row("lights", "none in the file (renders use a three-point setup)");
  } else {
    row("lights", std::to_string(scene.lighting.lights.size()));
    for (std::size_t i = 0; i < scene.lighting.lights.size(); ++i) {
      item(pad(std::to_string(i), 3) + describe(scene.lighting.lights[i]));
    }
  }
  row("cameras", scene.cameras.empty() ? "none in the file (renders frame the whole model)"
                                       : std::to_string(scene.cameras.size()));
  for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
    const Camera& c = scene.cameras[i];
    const std::string lens = c.projection_kind == Projection::orthographic
                                 ? "orthographic, " + number(c.view_height) + " units tall"
                                 : "fov " + number(c.fov_y_degrees) + " degrees";
    item(pad(std::to_string(i), 3) + "eye " + vec(c.eye) + " looking " + vec(c.forward()) + ", " +
         lens + ", aspect " + number(c.aspect));
  }
}

}  // namespace

CLI::App* add_info_command(CLI::App& app, InfoOptions& options) {
  CLI::App* command = app.add_subcommand(
      "info",
      "Print what a model file holds: meshes, triangles, materials, textures, bounds, "
      "lights, cameras");
  command->add_option("MODEL", options.model, "Model file (OBJ, glTF, PLY, STL, 3DS, FBX, .d, ...)")
      ->required();
  add_allow_outside_paths_flag(*command, options.allow_outside_paths);
  add_import_timeout_option(*command, options.import_timeout);
  return command;
}

int run_info(const InfoOptions& options) {
  // Throws facet::Error: main prints one line.
  Scene scene = import_model(options.model, options.allow_outside_paths, options.import_timeout);
  row("file", options.model);
  print_geometry(scene);
  print_materials(scene);
  print_textures(scene);
  print_lights_and_cameras(scene);
  return 0;
}

}  // namespace facet::cli
