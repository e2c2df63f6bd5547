// Lighting: any number of directional, point and spot lights, an ambient term, distance fog
// and an optional environment (reflections and sky background).
#pragma once

#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

namespace facet {

class Texture;

enum class LightType { directional, point, spot };

struct Light {
  LightType type = LightType::directional;
  glm::vec3 position{0.0f};                  // point and spot (world space)
  glm::vec3 direction{-0.4f, -1.0f, -0.6f};  // directional and spot: where the light travels
  glm::vec3 color{1.0f};                     // linear RGB
  float intensity = 1.0f;  // directional: irradiance scale; point/spot: scale at distance 1
  float range = 0.0f;      // point/spot: distance where the light fades out; 0 = unlimited
  float inner_cone_degrees = 25.0f;  // spot: full intensity inside this half-angle
  float outer_cone_degrees = 35.0f;  // spot: zero outside this half-angle
  // Whether the light casts shadows when the frame renders them (RenderSettings::shadows).
  bool casts_shadows = true;

  static Light directional(glm::vec3 direction, glm::vec3 color = glm::vec3(1.0f),
                           float intensity = 1.0f);
  static Light point(glm::vec3 position, glm::vec3 color = glm::vec3(1.0f), float intensity = 1.0f,
                     float range = 0.0f);
  static Light spot(glm::vec3 position, glm::vec3 direction, float inner_degrees,
                    float outer_degrees, glm::vec3 color = glm::vec3(1.0f), float intensity = 1.0f,
                    float range = 0.0f);
};

enum class FogMode { none, linear, exponential };

struct Fog {
  FogMode mode = FogMode::none;
  glm::vec3 color{0.6f, 0.7f, 0.8f};  // linear RGB
  float start = 10.0f;                // linear: fog begins at this view distance
  float end = 100.0f;                 // linear: fully fogged from here
  float density = 0.02f;              // exponential: factor = exp(-density * distance)
};

enum class EnvironmentProjection {
  equirectangular,  // longitude/latitude image, 2:1
  sphere_map,       // a mirrored-ball image
};

struct Environment {
  std::shared_ptr<const Texture> image;  // none: a procedural sky gradient
  EnvironmentProjection projection = EnvironmentProjection::equirectangular;
  float intensity = 1.0f;
  bool show_as_background = false;  // draw the environment (or sky gradient) behind the scene
  bool reflections = false;         // reflective materials and PBR specular sample it
  // Image-based lighting: physically based materials take their ambient light from the
  // environment, diffuse (its irradiance) and specular (blurred by roughness), instead of
  // Lighting::ambient. docs/pipeline.md, "Image-based lighting".
  bool image_based_lighting = false;
  glm::vec3 sky_zenith{0.18f, 0.35f, 0.70f};  // procedural sky, linear RGB
  glm::vec3 sky_horizon{0.75f, 0.82f, 0.90f};
  glm::vec3 ground{0.25f, 0.23f, 0.20f};
};

struct Lighting {
  std::vector<Light> lights{Light{}};      // default: one sun
  glm::vec3 ambient{0.15f, 0.15f, 0.18f};  // linear RGB added to every lit surface
  Fog fog;
  Environment environment;
};

// Three lights that make any model readable: a warm key from the upper left front, a cool
// fill from the right, a rim light from behind (all directional, relative to the view); only the
// key casts shadows.
std::vector<Light> three_point_lights(glm::vec3 view_forward, glm::vec3 view_right);

}  // namespace facet
