// Scene options (see scene_options.hpp).
#include "scene_options.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <optional>

#include "arguments.hpp"
#include "camera_numbers.hpp"
#include "facet/error.hpp"
#include "facet/import.hpp"
#include "facet/procedural.hpp"
#include "facet/texture.hpp"
#include "facet/worlds.hpp"
#include "model_import.hpp"

namespace facet::cli {
namespace {

std::vector<float> numbers(const std::string& flag, const std::string& text, std::size_t first) {
  std::vector<float> out;
  std::size_t start = 0;
  std::size_t index = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    std::string item = text.substr(start, end == std::string::npos ? end : end - start);
    if (index++ >= first) {
      try {
        std::size_t used = 0;
        float value = std::stof(item, &used);
        if (used != item.size() || !std::isfinite(value)) throw std::invalid_argument(item);
        out.push_back(value);
      } catch (const std::exception&) {
        throw Error(flag + ": '" + item + "' is not a number in '" + text + "'");
      }
    }
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

// --light dir,DX,DY,DZ[,R,G,B[,I]] | point,X,Y,Z[,R,G,B[,I]] |
//         spot,X,Y,Z,DX,DY,DZ[,INNER,OUTER[,R,G,B[,I]]]
Light parse_light(const std::string& text) {
  std::string kind = text.substr(0, text.find(','));
  std::vector<float> v =
      text.find(',') == std::string::npos ? std::vector<float>{} : numbers("--light", text, 1);
  auto color_at = [&](std::size_t i, Light& l) {
    if (v.size() >= i + 3) l.color = {v[i], v[i + 1], v[i + 2]};
    if (v.size() >= i + 4) l.intensity = v[i + 3];
  };
  Light light;
  if (kind == "dir" && v.size() >= 3 && v.size() <= 7) {
    light = Light::directional({v[0], v[1], v[2]});
    color_at(3, light);
  } else if (kind == "point" && v.size() >= 3 && v.size() <= 7) {
    light = Light::point({v[0], v[1], v[2]});
    color_at(3, light);
  } else if (kind == "spot" && v.size() >= 6 && v.size() <= 12) {
    light = Light::spot({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, 20.0f, 30.0f);
    if (v.size() >= 8) light.inner_cone_degrees = v[6], light.outer_cone_degrees = v[7];
    color_at(8, light);
  } else {
    throw Error(
        "--light: expected dir,DX,DY,DZ[,R,G,B[,I]] or point,X,Y,Z[,R,G,B[,I]] or "
        "spot,X,Y,Z,DX,DY,DZ[,INNER,OUTER[,R,G,B[,I]]], got '" +
        text + "'");
  }
  // The renderer would quietly replace a zero direction and clamp the cones; say so instead.
  if (kind != "point" && glm::length(light.direction) == 0.0f)
    throw Error("--light: the direction must not be 0,0,0 in '" + text + "'");
  if (glm::any(glm::lessThan(light.color, glm::vec3(0.0f))) || light.intensity < 0.0f)
    throw Error("--light: color and intensity must not be negative in '" + text + "'");
  if (kind == "spot" &&
      !(light.inner_cone_degrees >= 0.0f && light.inner_cone_degrees <= light.outer_cone_degrees &&
        light.outer_cone_degrees <= 90.0f)) {
    throw Error("--light: spot cones need 0 <= INNER <= OUTER <= 90 degrees in '" + text + "'");
  }
  return light;
}

// --fog linear[,START,END] | exp[,DENSITY]; defaults from the scene's size.
Fog parse_fog(const std::string& text, const Scene& scene) {
  std::string kind = text.substr(0, text.find(','));
  std::vector<float> v =
      text.find(',') == std::string::npos ? std::vector<float>{} : numbers("--fog", text, 1);
  Bounds b = scene.bounds();
  float size = b.empty() ? 10.0f : glm::length(b.max - b.min);
  float distance = glm::length(scene.camera.eye - scene.camera.target);
  Fog fog;
  if (kind == "linear" && (v.empty() || v.size() == 2)) {
    fog.mode = FogMode::linear;
    fog.start = v.empty() ? std::max(distance - size * 0.5f, 0.0f) : v[0];
    fog.end = v.empty() ? distance + size * 0.5f : v[1];
    if (!(fog.end > fog.start))
      throw Error("--fog: the end must be beyond the start in '" + text + "'");
  } else if (kind == "exp" && v.size() <= 1) {
    fog.mode = FogMode::exponential;
    fog.density = v.empty() ? 1.5f / std::max(distance, 1e-3f) : v[0];
    if (!(fog.density > 0.0f)) throw Error("--fog: density must be positive in '" + text + "'");
  } else {
    throw Error("--fog: expected linear[,START,END] or exp[,DENSITY], got '" + text + "'");
  }
  return fog;
}

void apply_texture(const SceneOptions& o, Scene& scene) {
  auto texture = load_texture(*o.texture, true);
  TextureProjection projection = TextureProjection::spherical;
  if (o.projection) {
    if (*o.projection == "spherical")
      projection = TextureProjection::spherical;
    else if (*o.projection == "cylindrical")
      projection = TextureProjection::cylindrical;
    else if (*o.projection == "planar")
      projection = TextureProjection::planar;
    else
      throw Error("--projection: expected spherical, cylindrical or planar, got '" + *o.projection +
                  "'");
  }
  for (auto& mesh : scene.meshes) {
    if (!mesh->texcoords.empty() && !o.projection) continue;  // keep the file's coordinates
    Mesh projected = *mesh;
    glm::vec3 low(1e30f), high(-1e30f);
    for (const glm::vec3& p : projected.positions) low = glm::min(low, p), high = glm::max(high, p);
    project_texcoords(projected, projection, (low + high) * 0.5f);
    mesh = std::make_shared<const Mesh>(std::move(projected));
  }
  for (auto& material : scene.materials) {
    material.base_color_map.texture = texture;
    material.base_color_map.transform = glm::mat3(1.0f);
  }
  scene.textures.push_back(texture);
}

EnvironmentProjection parse_environment_projection(const std::string& text) {
  if (text == "equirectangular") return EnvironmentProjection::equirectangular;
  if (text == "sphere") return EnvironmentProjection::sphere_map;
  throw Error("--env-projection: expected equirectangular or sphere, got '" + text + "'");
}

void apply_environment(const SceneOptions& o, Scene& scene) {
  Environment& env = scene.lighting.environment;
  if (*o.environment != "sky") env.image = load_texture(*o.environment, true);
  if (o.environment_projection)
    env.projection = parse_environment_projection(*o.environment_projection);
  env.reflections = true;
  env.show_as_background = true;
  env.image_based_lighting = true;  // it lights PBR materials, as f3d's --hdri does
}

// The framing --up AXIS, --azimuth and --elevation describe; each value checked.
Framing requested_framing(const SceneOptions& o) {
  Framing framing;
  if (o.up) framing.up = parse_up_axis(*o.up).value_or(framing.up);
  if (o.azimuth) {
    if (!std::isfinite(*o.azimuth)) throw Error("--azimuth: must be a finite number of degrees");
    framing.azimuth_degrees = *o.azimuth;
  }
  if (o.elevation) {
    if (!(std::abs(*o.elevation) <= 90.0f))
      throw Error("--elevation: must be within -90 .. 90 degrees (90 looks straight down)");
    framing.elevation_degrees = *o.elevation;
  }
  return framing;
}

// A moved camera gets near and far planes that fit the scene from where it now stands.
void fit_clip_planes(const Scene& scene, Camera& camera) {
  Bounds b = scene.bounds();
  if (b.empty()) return;
  float radius = std::max(glm::length(b.max - b.min) * 0.5f, 1e-6f);
  float distance = glm::length(camera.eye - b.centre());
  camera.near_plane = std::max(distance - radius * 1.5f, radius * 0.001f);
  camera.far_plane = distance + radius * 2.0f;
}

}  // namespace

void add_allow_outside_paths_flag(CLI::App& command, bool& allow_outside_paths) {
  command.add_flag("--allow-outside-paths", allow_outside_paths,
                   "Let the model read textures and other files outside its own folder (default: "
                   "refused with a warning, as missing)");
}

void add_import_timeout_option(CLI::App& command, double& seconds) {
  command.add_option("--import-timeout", seconds,
                     "Seconds assimp may take to read the model (OBJ, STL, 3DS, FBX, COLLADA, "
                     "OFF, ...) before it is stopped and the import fails (default: 60; 0: no "
                     "limit)");
}

void add_scene_options(CLI::App& cmd, SceneOptions& o, std::vector<std::string>* models) {
  if (models) {
    cmd.add_option("model", *models,
                   "Model files to draw (OBJ, glTF/GLB, PLY, STL, 3DS, FBX, DAE, OFF, .d, ...); "
                   "several, or folders, draw one image each into -o FOLDER/");
  } else {
    cmd.add_option("model", o.model,
                   "Model file to draw (OBJ, glTF/GLB, PLY, STL, 3DS, FBX, DAE, OFF, .d, ...)");
  }
  cmd.add_option(
      "--scene", o.scene,
      "Built-in scene instead of a model: " + joined(builtin_scene_names()) + " (default: shapes)");
  cmd.add_option("--eye", o.eye, "Camera position x,y,z (default: framed automatically)");
  cmd.add_option("--target", o.target, "Point the camera looks at x,y,z (default: the centre)");
  cmd.add_option("--up", o.up,
                 "The model's up axis, +X, -X, +Y, -Y, +Z or -Z: the automatic view keeps it up "
                 "(default: +Y); or the camera's up direction x,y,z, which rolls the view");
  cmd.add_option("--azimuth", o.azimuth,
                 "Turn the automatic view about the up axis by DEG, counter-clockwise seen from "
                 "above (180: the other side)");
  cmd.add_option("--elevation", o.elevation,
                 "The automatic view's angle above the horizon in degrees, -90 .. 90 (90: from "
                 "straight above; default: about 24)");
  cmd.add_option(
      "--fov", o.fov,
      "Vertical field of view in degrees, (0, 180) (default: the scene's; 50 for shapes)");
  cmd.add_option("--near", o.near_plane,
                 "Near clip distance, > 0 (default: from the scene's size)");
  cmd.add_option("--far", o.far_plane,
                 "Far clip distance, > near (default: from the scene's size)");
  cmd.add_option("--camera", o.camera_index, "Use the model file's camera number N (0-based)");
  cmd.add_option("--shading", o.shading,
                 "Shading model for every material: " + joined(shading_model_names()) +
                     " (default: each material's own)");
  cmd.add_option("--cull", o.cull,
                 "Face culling: back, front or none (default: each material's, back)");
  cmd.add_option("--light", o.lights,
                 "Add a light (repeatable; replaces the default lights): dir,DX,DY,DZ[,R,G,B[,I]], "
                 "point,X,Y,Z[,R,G,B[,I]] or spot,X,Y,Z,DX,DY,DZ[,INNER,OUTER[,R,G,B[,I]]]")
      ->allow_extra_args(false);  // one light per --light: a model path after it stays the model
  cmd.add_option("--env", o.environment,
                 "Environment image (equirectangular or sphere map) for reflections, the "
                 "background and the light of PBR materials (image-based lighting), or 'sky' for "
                 "a procedural sky gradient");
  cmd.add_option("--env-projection", o.environment_projection,
                 "equirectangular (default) or sphere");
  cmd.add_option("--fog", o.fog,
                 "Distance fog: linear[,START,END] or exp[,DENSITY] (default: off)");
  cmd.add_option("--fog-color", o.fog_color,
                 "Fog color r,g,b in [0, 1], sRGB (default: the background)");
  cmd.add_option(
      "--texture", o.texture,
      "Image to put on every material (with --projection for models without texture coordinates)");
  cmd.add_option("--projection", o.projection,
                 "Texture projection: spherical (default), cylindrical or planar");
  cmd.add_option("--reflectivity", o.reflectivity,
                 "Mirror reflectivity in [0, 1] for every material (needs --env)");
  cmd.add_option("--point-size", o.point_size,
                 "Side of each point of a point cloud in pixels, (0, 256] (default: 3)");
  add_allow_outside_paths_flag(cmd, o.allow_outside_paths);
  cmd.add_option("--animation", o.animation,
                 "The glTF model's animation N (0-based) that --time or --frames samples "
                 "(default: 0; alone, sampled at time 0)");
  add_import_timeout_option(cmd, o.import_timeout);
}

Scene build_scene(const SceneOptions& o) {
  if (!o.model.empty() && o.scene) throw Error("give a model file or --scene, not both");
  // Values of flags that only act with another flag are still checked, so a typo never passes
  // silently (and fails before the model is imported).
  glm::vec3 fog_color = o.fog_color ? parse_color("--fog-color", *o.fog_color) : glm::vec3(0.0f);
  if (o.environment_projection) parse_environment_projection(*o.environment_projection);
  if (o.animation && o.model.empty())
    throw Error("--animation: picks an animation of a model file, not of a built-in scene");
  Scene scene;
  if (o.model.empty()) {
    scene = make_builtin_scene(o.scene.value_or("shapes"));
  } else {
    ImportOptions import;
    import.allow_outside_paths = o.allow_outside_paths;
    import.animation = o.animation.value_or(0);
    import.time = o.model_time;
    import.import_time_limit_seconds = o.import_timeout;
    scene = import_model(o.model, import);
  }
  if (changes_framing(o)) {
    scene.framing = requested_framing(o);
    scene.camera = frame_scene(scene, 16.0f / 9.0f, *scene.framing);
    // Import lit the model from the view it framed; the lights follow the new view (a
    // built-in scene keeps its own, a file's lights stay where the file puts them).
    if (!o.model.empty() && !scene.has_file_lights)
      scene.lighting.lights = three_point_lights(scene.camera.forward(), scene.camera.right());
  }
  if (o.shading) {
    ShadingModel model;
    if (!parse_shading_model(*o.shading, model)) {
      throw Error("--shading: unknown model '" + *o.shading + "' (" +
                  joined(shading_model_names()) + ")");
    }
    for (auto& material : scene.materials) material.shading = model;
  }
  if (o.cull) {
    CullMode mode;
    if (!parse_cull_mode(*o.cull, mode)) {
      throw Error("--cull: unknown mode '" + *o.cull + "' (back, front, none)");
    }
    for (auto& material : scene.materials) material.cull = mode;
  }
  if (!o.lights.empty()) {
    scene.lighting.lights.clear();
    for (const auto& text : o.lights) scene.lighting.lights.push_back(parse_light(text));
  }
  if (o.texture) apply_texture(o, scene);
  if (o.environment) apply_environment(o, scene);
  if (o.reflectivity) {
    if (!(*o.reflectivity >= 0.0f && *o.reflectivity <= 1.0f)) {
      throw Error("--reflectivity: must be in [0, 1]");
    }
    for (auto& material : scene.materials) material.reflectivity = *o.reflectivity;
  }
  if (o.point_size) {
    if (!(*o.point_size > 0.0f && *o.point_size <= Material::kMaxPointSize)) {
      throw Error("--point-size: must be in (0, 256] pixels");
    }
    for (auto& material : scene.materials) material.point_size = *o.point_size;
  }
  if (o.fog) {
    scene.lighting.fog = parse_fog(*o.fog, scene);
    if (o.fog_color) scene.lighting.fog.color = fog_color;
  }
  return scene;
}

std::optional<glm::vec3> parse_up_axis(const std::string& text) {
  std::string axis = text;
  float sign = 1.0f;
  if (!axis.empty() && (axis[0] == '+' || axis[0] == '-')) {
    sign = axis[0] == '-' ? -1.0f : 1.0f;
    axis.erase(0, 1);
  }
  if (axis.size() != 1) return std::nullopt;
  switch (axis[0]) {
    case 'x':
    case 'X':
      return glm::vec3(sign, 0.0f, 0.0f);
    case 'y':
    case 'Y':
      return glm::vec3(0.0f, sign, 0.0f);
    case 'z':
    case 'Z':
      return glm::vec3(0.0f, 0.0f, sign);
    default:
      return std::nullopt;
  }
}

bool changes_framing(const SceneOptions& o) {
  return (o.up && parse_up_axis(*o.up)) || o.azimuth || o.elevation;
}

Camera build_camera(const SceneOptions& o, const Scene& scene, float aspect) {
  if ((o.azimuth || o.elevation) && (o.camera_index || o.eye || o.target)) {
    throw Error(std::string(o.azimuth ? "--azimuth" : "--elevation") +
                ": turns the automatic view, so not with --camera, --eye or --target");
  }
  Camera camera = scene_camera(scene, aspect);
  if (o.camera_index) {
    int n = *o.camera_index;
    if (n < 0 || n >= static_cast<int>(scene.cameras.size())) {
      throw Error("--camera: the file has " + std::to_string(scene.cameras.size()) +
                  " camera(s), there is no camera " + std::to_string(n));
    }
    camera = scene.cameras[n];
  }
  if (o.eye) camera.eye = parse_vec3("--eye", *o.eye);
  if (o.target) camera.target = parse_vec3("--target", *o.target);
  if (o.up) {
    if (auto axis = parse_up_axis(*o.up)) {
      // The automatic view keeps the axis up already; a placed camera is turned to it.
      if (o.camera_index || o.eye || o.target) camera.up = *axis;
    } else {
      camera.up = parse_vec3("--up", *o.up);
    }
  }
  if (o.fov) camera.fov_y_degrees = *o.fov;
  if ((o.eye || o.target) && !o.camera_index) fit_clip_planes(scene, camera);
  if (o.near_plane) camera.near_plane = *o.near_plane;
  if (o.far_plane) camera.far_plane = *o.far_plane;
  // The image's aspect, whatever the camera had: cameras here come from files and the framing,
  // never from intrinsics, whose aspect belongs to their calibration (camera.hpp).
  camera.aspect = aspect;
  check_camera_numbers(o, scene, camera);  // values that overflow or draw nothing, by flag
  try {
    camera.validate();
  } catch (const Error& e) {
    // Name the flags, not the library's field names.
    throw Error(std::string(e.what()) + " (check --eye, --target, --up, --fov, --near, --far)");
  }
  return camera;
}

}  // namespace facet::cli
