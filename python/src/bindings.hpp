// The facet Python module's parts (python/src): each file binds one part of the API and
// module.cpp calls them in order; SceneHandle is the scene they hand each other, and
// RenderTextureHandle and TextureHandle the render textures and the textures made of them.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <shared_mutex>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/render_texture.hpp"
#include "facet/scene.hpp"

namespace facet::python {

namespace py = pybind11;

// facet.RenderTexture. A frame rendered into it (Renderer.render_to) rewrites its framebuffer
// and textures under its lock, held exclusively; everything that reads them (a readback, a
// frame whose materials sample its textures) holds it shared, with the GIL released while
// waiting. So a Python thread never sees half a frame, and two never render into it at once.
struct RenderTextureHandle {
  RenderTextureHandle(int width, int height, const RenderTextureOptions& options)
      : target(width, height, options) {}
  RenderTexture target;
  mutable std::shared_mutex mutex;
};

// facet.Scene: a facet::Scene with what the module adds. Instance ids are draw_scene's: node n's
// meshes have the id n + 1 (0 is left for "nothing").
struct SceneHandle {
  Scene scene;
  // The lights are the scene's defaults (the library's sun, or the three-point lights of a
  // file without lights): the first add_light replaces them, as `facet render --light` does.
  bool default_lights = true;
  // render() reads the scene with the GIL released, under a shared lock; every change takes it
  // exclusively, so a Python thread changing a scene another one renders waits for the frame.
  mutable std::shared_mutex mutex;
  // The render textures whose textures the scene's materials sample (each once or more): a
  // frame of the scene reads them under their locks.
  std::vector<std::shared_ptr<const RenderTextureHandle>> render_textures;
};

// facet.Texture: a texture a material samples, one of a render texture's (source, which it
// keeps alive so that scenes sampling the texture can take source's lock).
struct TextureHandle {
  std::shared_ptr<const Texture> texture;
  std::shared_ptr<const RenderTextureHandle> source;
};

// The facet object `value` holds (a copy); facet.Error naming the argument if it holds
// something else: "add_light: light must be a facet.Light, got str".
template <class T>
T object_of(py::handle value, const char* function, const char* argument, const char* type) {
  if (!py::isinstance<T>(value)) {
    throw Error(std::string(function) + ": " + argument + " must be a facet." + type + ", got " +
                std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  return value.cast<T>();
}

void bind_materials_and_lights(py::module_& m);  // material_bindings.cpp: Material, Light
void bind_camera(py::module_& m);                // camera_bindings.cpp: Camera
void bind_scene(py::module_& m);                 // scene_bindings.cpp: Scene, load
void bind_animation(py::module_& m);             // animation_bindings.cpp: AnimatedModel
void bind_render_texture(py::module_& m);        // render_texture_bindings.cpp: RenderTexture,
                                                 // Texture
void bind_render(py::module_& m);                // render_bindings.cpp: Renderer, write_png

}  // namespace facet::python
