// facet.Material and facet.Light: the small value types a scene is made of. Each field is read
// and written through one checked setter, which the keyword constructor uses too, so a bad
// value fails the same way whichever path it takes ("Material: roughness must be in [0, 1]").
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "array_conversion.hpp"
#include "bindings.hpp"
#include "facet/error.hpp"
#include "facet/light.hpp"
#include "facet/material.hpp"

namespace facet::python {
namespace {

std::string joined(const std::vector<std::string_view>& names) {
  std::string text;
  for (std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

constexpr std::array<AlphaMode, 4> kAlphaModes{AlphaMode::opaque, AlphaMode::mask, AlphaMode::blend,
                                               AlphaMode::additive};

std::vector<std::string_view> alpha_mode_names() {
  std::vector<std::string_view> names;
  for (AlphaMode mode : kAlphaModes) names.push_back(to_string(mode));
  return names;
}

std::string text(py::handle value, const Argument& argument) {
  if (!py::isinstance<py::str>(value)) {
    throw Error(argument.text() + " must be a string, got " +
                std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  return value.cast<std::string>();
}

float in_unit_range(py::handle value, const Argument& argument) {
  const float v = number(value, argument);
  if (!(v >= 0.0f && v <= 1.0f)) {
    throw Error(argument.text() + " must be in [0, 1], got " + std::to_string(v));
  }
  return v;
}

float non_negative(py::handle value, const Argument& argument) {
  const float v = number(value, argument);
  if (v < 0.0f) throw Error(argument.text() + " must not be negative, got " + std::to_string(v));
  return v;
}

template <class Vec>
Vec color_in_unit_range(Vec c, const Argument& argument) {
  for (int i = 0; i < Vec::length(); ++i) {
    if (!(c[i] >= 0.0f && c[i] <= 1.0f)) {
      throw Error(argument.text() + " must be in [0, 1] (linear), got " + to_text(c));
    }
  }
  return c;
}

glm::vec3 non_negative_color(py::handle value, const Argument& argument) {
  const glm::vec3 c = vec3(value, argument);
  if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) {
    throw Error(argument.text() + " must not be negative, got " + to_text(c));
  }
  return c;
}

// One field of facet.Material: its Python name, how it is read, how it is checked and written.
struct MaterialField {
  const char* name;
  py::object (*get)(const Material&);
  void (*set)(Material&, py::handle);
};

const std::array<MaterialField, 16> kMaterialFields{{
    {"base_color", [](const Material& m) -> py::object { return to_tuple(m.base_color); },
     [](Material& m, py::handle v) {
       m.base_color =
           color_in_unit_range(rgba(v, {"Material", "base_color"}), {"Material", "base_color"});
     }},
    {"shading",
     [](const Material& m) -> py::object { return py::str(std::string(to_string(m.shading))); },
     [](Material& m, py::handle v) {
       const std::string name = text(v, {"Material", "shading"});
       if (!parse_shading_model(name, m.shading)) {
         throw Error("Material: shading must be one of " + joined(shading_model_names()) +
                     ", got '" + name + "'");
       }
     }},
    {"metallic", [](const Material& m) -> py::object { return to_python(m.metallic); },
     [](Material& m, py::handle v) {
       m.metallic = in_unit_range(v, {"Material", "metallic"});
     }},
    {"roughness", [](const Material& m) -> py::object { return to_python(m.roughness); },
     [](Material& m, py::handle v) {
       m.roughness = in_unit_range(v, {"Material", "roughness"});
     }},
    {"specular_color", [](const Material& m) -> py::object { return to_tuple(m.specular_color); },
     [](Material& m, py::handle v) {
       m.specular_color = color_in_unit_range(vec3(v, {"Material", "specular_color"}),
                                              {"Material", "specular_color"});
     }},
    {"shininess", [](const Material& m) -> py::object { return to_python(m.shininess); },
     [](Material& m, py::handle v) {
       m.shininess = non_negative(v, {"Material", "shininess"});
     }},
    {"emissive", [](const Material& m) -> py::object { return to_tuple(m.emissive); },
     [](Material& m, py::handle v) {
       m.emissive = non_negative_color(v, {"Material", "emissive"});
     }},
    {"reflectivity", [](const Material& m) -> py::object { return to_python(m.reflectivity); },
     [](Material& m, py::handle v) {
       m.reflectivity = in_unit_range(v, {"Material", "reflectivity"});
     }},
    {"reflects_scene", [](const Material& m) -> py::object { return py::bool_(m.reflects_scene); },
     [](Material& m, py::handle v) {
       if (!py::isinstance<py::bool_>(v)) throw Error("Material: reflects_scene must be a bool");
       m.reflects_scene = v.cast<bool>();
     }},
    {"casts_shadows", [](const Material& m) -> py::object { return py::bool_(m.casts_shadows); },
     [](Material& m, py::handle v) {
       if (!py::isinstance<py::bool_>(v)) throw Error("Material: casts_shadows must be a bool");
       m.casts_shadows = v.cast<bool>();
     }},
    {"use_vertex_colors",
     [](const Material& m) -> py::object { return py::bool_(m.use_vertex_colors); },
     [](Material& m, py::handle v) {
       if (!py::isinstance<py::bool_>(v)) throw Error("Material: use_vertex_colors must be a bool");
       m.use_vertex_colors = v.cast<bool>();
     }},
    {"alpha_mode",
     [](const Material& m) -> py::object { return py::str(std::string(to_string(m.alpha_mode))); },
     [](Material& m, py::handle v) {
       const std::string name = text(v, {"Material", "alpha_mode"});
       for (AlphaMode mode : kAlphaModes) {
         if (to_string(mode) == name) {
           m.alpha_mode = mode;
           return;
         }
       }
       throw Error("Material: alpha_mode must be one of " + joined(alpha_mode_names()) + ", got '" +
                   name + "'");
     }},
    {"alpha_cutoff", [](const Material& m) -> py::object { return to_python(m.alpha_cutoff); },
     [](Material& m, py::handle v) {
       m.alpha_cutoff = in_unit_range(v, {"Material", "alpha_cutoff"});
     }},
    {"cull",
     [](const Material& m) -> py::object { return py::str(std::string(to_string(m.cull))); },
     [](Material& m, py::handle v) {
       const std::string name = text(v, {"Material", "cull"});
       if (!parse_cull_mode(name, m.cull)) {
         throw Error("Material: cull must be one of back, front, none, got '" + name + "'");
       }
     }},
    {"wire_color", [](const Material& m) -> py::object { return to_tuple(m.wire_color); },
     [](Material& m, py::handle v) {
       m.wire_color =
           color_in_unit_range(rgba(v, {"Material", "wire_color"}), {"Material", "wire_color"});
     }},
    {"name", [](const Material& m) -> py::object { return py::str(m.name); },
     [](Material& m, py::handle v) {
       m.name = text(v, {"Material", "name"});
     }},
}};

const MaterialField& material_field(std::string_view name) {
  for (const MaterialField& field : kMaterialFields) {
    if (field.name == name) return field;
  }
  throw Error("Material: no field '" + std::string(name) + "'");  // a bug here, not the user's
}

void bind_material(py::module_& m) {
  py::class_<Material> material(m, "Material", R"doc(
How a mesh is shaded. Every field has a keyword of the same name. Colors are linear RGB(A)
floats: base_color, specular_color and wire_color in [0, 1], emissive any non-negative
value. A Material is copied into the scene by Scene.add_mesh: changing it later
changes nothing already added.

shading: one of facet.SHADING_MODELS ("lambert" by default; "unlit", "flat", "phong",
"blinn_phong", "gouraud", "pbr", ...). metallic and roughness are read by "pbr";
specular_color and shininess by the Phong models. reflects_scene: a flat mesh that mirrors the
scene (a floor, water; the Renderer's reflections): Phong models mix it in by reflectivity, PBR
takes it as the light from the mirror direction. casts_shadows: off for a surface with nothing
seen beneath it (water, the floor at the bottom of a world): the shadow maps skip it.
use_vertex_colors multiplies base_color by the mesh's colors. alpha_mode: opaque, mask
(alpha_cutoff), blend, additive. cull: back (the default; front faces are counter-clockwise),
front, none.)doc");
  const Material defaults;
  material.def(
      py::init([](py::object base_color, py::object shading, py::object metallic,
                  py::object roughness, py::object specular_color, py::object shininess,
                  py::object emissive, py::object reflectivity, py::object reflects_scene,
                  py::object casts_shadows, py::object use_vertex_colors, py::object alpha_mode,
                  py::object alpha_cutoff, py::object cull, py::object wire_color,
                  py::object name) {
        Material out;
        const std::array<std::pair<const char*, py::object*>, 16> values{{
            {"base_color", &base_color},
            {"shading", &shading},
            {"metallic", &metallic},
            {"roughness", &roughness},
            {"specular_color", &specular_color},
            {"shininess", &shininess},
            {"emissive", &emissive},
            {"reflectivity", &reflectivity},
            {"reflects_scene", &reflects_scene},
            {"casts_shadows", &casts_shadows},
            {"use_vertex_colors", &use_vertex_colors},
            {"alpha_mode", &alpha_mode},
            {"alpha_cutoff", &alpha_cutoff},
            {"cull", &cull},
            {"wire_color", &wire_color},
            {"name", &name},
        }};
        for (const auto& [field, value] : values) material_field(field).set(out, *value);
        return out;
      }),
      py::arg("base_color") = to_tuple(defaults.base_color),
      py::arg("shading") = std::string(to_string(defaults.shading)), py::kw_only(),
      py::arg("metallic") = defaults.metallic, py::arg("roughness") = defaults.roughness,
      py::arg("specular_color") = to_tuple(defaults.specular_color),
      py::arg("shininess") = defaults.shininess, py::arg("emissive") = to_tuple(defaults.emissive),
      py::arg("reflectivity") = defaults.reflectivity,
      py::arg("reflects_scene") = defaults.reflects_scene,
      py::arg("casts_shadows") = defaults.casts_shadows,
      py::arg("use_vertex_colors") = defaults.use_vertex_colors,
      py::arg("alpha_mode") = std::string(to_string(defaults.alpha_mode)),
      py::arg("alpha_cutoff") = defaults.alpha_cutoff,
      py::arg("cull") = std::string(to_string(defaults.cull)),
      py::arg("wire_color") = to_tuple(defaults.wire_color), py::arg("name") = defaults.name);
  for (const MaterialField& field : kMaterialFields) {
    material.def_property(
        field.name, [get = field.get](const Material& self) { return get(self); },
        [set = field.set](Material& self, py::handle value) { set(self, value); });
  }
  material.def("__repr__", [](const Material& self) {
    std::string text = "facet.Material(";
    for (const MaterialField& field : kMaterialFields) {
      text += std::string(field.name) + "=" + std::string(py::repr(field.get(self))) + ", ";
    }
    return text.substr(0, text.size() - 2) + ")";
  });
  m.attr("SHADING_MODELS") = py::tuple(py::cast(shading_model_names()));
}

// Checks what the renderer would otherwise quietly mend (as `facet render --light` does).
Light checked(Light light, const char* function) {
  const Argument where{function, "direction"};
  if (light.type != LightType::point && glm::length(light.direction) == 0.0f) {
    throw Error(where.text() + " must not be (0, 0, 0)");
  }
  if (light.color.r < 0.0f || light.color.g < 0.0f || light.color.b < 0.0f) {
    throw Error(std::string(function) + ": color must not be negative");
  }
  if (light.intensity < 0.0f)
    throw Error(std::string(function) + ": intensity must not be negative");
  if (light.range < 0.0f) {
    throw Error(std::string(function) + ": range must not be negative (0 is unlimited)");
  }
  if (light.type == LightType::spot &&
      !(light.inner_cone_degrees >= 0.0f && light.inner_cone_degrees <= light.outer_cone_degrees &&
        light.outer_cone_degrees <= 90.0f)) {
    throw Error(std::string(function) +
                ": the cones need 0 <= inner_cone <= outer_cone <= 90 degrees");
  }
  return light;
}

std::string light_type_name(LightType type) {
  switch (type) {
    case LightType::directional:
      return "directional";
    case LightType::point:
      return "point";
    case LightType::spot:
      return "spot";
  }
  return "?";
}

void bind_light(py::module_& m) {
  py::class_<Light> light(m, "Light", R"doc(
A light: made by Light.directional, Light.point or Light.spot and given to Scene.add_light.
Colors are linear RGB; positions and directions in world space; intensity scales the color
(point and spot: at distance 1); range is where a point or spot light fades out (0: never).)doc");
  light
      .def_static(
          "directional",
          [](py::handle direction, py::handle color, py::handle intensity) {
            constexpr const char* kName = "Light.directional";
            return checked(Light::directional(vec3(direction, {kName, "direction"}),
                                              vec3(color, {kName, "color"}),
                                              number(intensity, {kName, "intensity"})),
                           kName);
          },
          py::arg("direction"), py::arg("color") = py::make_tuple(1.0, 1.0, 1.0),
          py::arg("intensity") = 1.0,
          "A light from infinitely far away travelling along direction.")
      .def_static(
          "point",
          [](py::handle position, py::handle color, py::handle intensity, py::handle range) {
            constexpr const char* kName = "Light.point";
            return checked(
                Light::point(vec3(position, {kName, "position"}), vec3(color, {kName, "color"}),
                             number(intensity, {kName, "intensity"}),
                             number(range, {kName, "range"})),
                kName);
          },
          py::arg("position"), py::arg("color") = py::make_tuple(1.0, 1.0, 1.0),
          py::arg("intensity") = 1.0, py::arg("range") = 0.0,
          "A light shining every way from position.")
      .def_static(
          "spot",
          [](py::handle position, py::handle direction, py::handle inner_cone,
             py::handle outer_cone, py::handle color, py::handle intensity, py::handle range) {
            constexpr const char* kName = "Light.spot";
            return checked(
                Light::spot(
                    vec3(position, {kName, "position"}), vec3(direction, {kName, "direction"}),
                    number(inner_cone, {kName, "inner_cone"}),
                    number(outer_cone, {kName, "outer_cone"}), vec3(color, {kName, "color"}),
                    number(intensity, {kName, "intensity"}), number(range, {kName, "range"})),
                kName);
          },
          py::arg("position"), py::arg("direction"), py::arg("inner_cone") = 25.0,
          py::arg("outer_cone") = 35.0, py::arg("color") = py::make_tuple(1.0, 1.0, 1.0),
          py::arg("intensity") = 1.0, py::arg("range") = 0.0,
          "A cone of light from position along direction: full inside inner_cone degrees "
          "(half-angle), none outside outer_cone.")
      .def_property_readonly("type", [](const Light& l) { return light_type_name(l.type); })
      .def_property_readonly("position", [](const Light& l) { return to_tuple(l.position); })
      .def_property_readonly("direction", [](const Light& l) { return to_tuple(l.direction); })
      .def_property_readonly("color", [](const Light& l) { return to_tuple(l.color); })
      .def_property_readonly("intensity", [](const Light& l) { return to_python(l.intensity); })
      .def_property_readonly("range", [](const Light& l) { return to_python(l.range); })
      .def_property_readonly("inner_cone",
                             [](const Light& l) { return to_python(l.inner_cone_degrees); })
      .def_property_readonly("outer_cone",
                             [](const Light& l) { return to_python(l.outer_cone_degrees); })
      .def("__repr__", [](const Light& l) {
        std::ostringstream out;
        out << "facet.Light." << light_type_name(l.type) << "(";
        if (l.type != LightType::directional) out << "position=" << to_text(l.position) << ", ";
        if (l.type != LightType::point) out << "direction=" << to_text(l.direction) << ", ";
        if (l.type == LightType::spot) {
          out << "inner_cone=" << l.inner_cone_degrees << ", outer_cone=" << l.outer_cone_degrees
              << ", ";
        }
        out << "color=" << to_text(l.color) << ", intensity=" << l.intensity;
        if (l.type != LightType::directional) out << ", range=" << l.range;
        out << ")";
        return out.str();
      });
}

}  // namespace

void bind_materials_and_lights(py::module_& m) {
  bind_material(m);
  bind_light(m);
}

}  // namespace facet::python
