// facet.Scene and facet.load: scenes built from NumPy arrays (add_mesh) or read from a model file
// (facet::import_scene, as `facet render` reads it), and their lights. Arrays are checked and
// converted with the GIL held; the scene changes with it released, under the scene's lock
// (SceneHandle), so a frame another thread is rendering finishes first.
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "array_conversion.hpp"
#include "bindings.hpp"
#include "facet/error.hpp"
#include "facet/import.hpp"

namespace facet::python {
namespace {

// Runs change(scene) with the scene locked for writing; the GIL is released while it waits.
template <class Change>
auto change_scene(SceneHandle& handle, Change&& change) {
  py::gil_scoped_release release;
  std::unique_lock lock(handle.mutex);
  return change(handle);
}

std::string path_text(py::handle path, const char* function) {
  try {
    return py::str(py::module_::import("os").attr("fspath")(path));
  } catch (const py::error_already_set&) {
    throw Error(std::string(function) + ": path must be a str or an os.PathLike, got " +
                std::string(py::str(py::type::of(path).attr("__name__"))));
  }
}

std::unique_ptr<SceneHandle> load(py::handle path, py::handle crease_angle, py::handle time,
                                  py::handle animation, bool allow_outside_paths, bool fence_assimp,
                                  py::handle import_timeout, py::handle import_memory_limit) {
  ImportOptions options;
  options.crease_angle_degrees = number(crease_angle, {"load", "crease_angle"});
  if (!time.is_none()) options.time = number(time, {"load", "time"});
  options.animation = integer(animation, {"load", "animation"});
  options.allow_outside_paths = allow_outside_paths;
  options.fence_assimp = fence_assimp;
  // None: no limit (the library's "<= 0").
  options.import_time_limit_seconds =
      import_timeout.is_none() ? 0.0 : number(import_timeout, {"load", "import_timeout"});
  if (!import_memory_limit.is_none()) {
    // A float holds byte counts far past any machine's memory exactly enough for a limit.
    const double bytes = number(import_memory_limit, {"load", "import_memory_limit"});
    if (!(bytes >= 1.0))
      throw Error("load: import_memory_limit must be a positive number of bytes or None");
    options.import_memory_limit_bytes = static_cast<std::uint64_t>(bytes);
  }
  std::vector<std::string> warnings;
  options.warn = [&warnings](const std::string& warning) { warnings.push_back(warning); };
  const std::string file = path_text(path, "load");
  auto handle = std::make_unique<SceneHandle>();
  {
    py::gil_scoped_release release;
    handle->scene = import_scene(file, options);
  }
  handle->default_lights = !handle->scene.has_file_lights;
  // Problems that did not stop the import (a missing texture) as Python warnings.
  for (const std::string& warning : warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
  }
  return handle;
}

int add_mesh(SceneHandle& handle, py::handle vertices, py::handle faces, py::handle normals,
             py::handle uvs, py::handle colors, py::handle texture, py::handle material,
             py::handle pose, const std::string& name) {
  constexpr const char* kName = "add_mesh";
  Mesh mesh;
  mesh.positions = vec3_rows(vertices, {kName, "vertices"}, -1);
  const std::size_t n = mesh.positions.size();
  mesh.indices = triangle_indices(faces, {kName, "faces"}, n);
  // A mesh without indices draws its vertices as triangles: no faces must not mean that.
  if (mesh.indices.empty()) throw Error("add_mesh: faces has no triangles");
  const auto rows = static_cast<std::ptrdiff_t>(n);
  if (!normals.is_none()) mesh.normals = vec3_rows(normals, {kName, "normals"}, rows);
  if (!uvs.is_none()) mesh.texcoords = vec2_rows(uvs, {kName, "uvs"}, rows);
  if (!colors.is_none()) mesh.colors = vertex_colors(colors, {kName, "colors"}, n);
  Material look;
  if (!material.is_none()) look = object_of<Material>(material, kName, "material", "Material");
  std::shared_ptr<const Texture> image;
  std::shared_ptr<const RenderTextureHandle> render_texture;  // image's, if it is one's
  if (!texture.is_none()) {
    if (mesh.texcoords.empty()) throw Error("add_mesh: a texture needs uvs, an (N, 2) array");
    if (py::isinstance<TextureHandle>(texture)) {
      const TextureHandle& given = texture.cast<const TextureHandle&>();
      image = given.texture;
      render_texture = given.source;
      // A frame does not go on past its edges: clamped, its border texels are not blended with
      // the opposite side's where the mesh shows the texture magnified.
      look.base_color_map.sampler.wrap_u = Wrap::clamp_to_edge;
      look.base_color_map.sampler.wrap_v = Wrap::clamp_to_edge;
    } else if (py::isinstance<RenderTextureHandle>(texture)) {
      throw Error(
          "add_mesh: texture must be an image array or a facet.Texture, got a RenderTexture "
          "(its .texture or .depth_texture is one)");
    } else {
      image = texture_image(texture, {kName, "texture"});
    }
    look.base_color_map.texture = image;
  }
  const glm::mat4 transform = pose.is_none() ? glm::mat4(1.0f) : matrix4(pose, {kName, "pose"});
  try {
    mesh.validate();
  } catch (const Error& e) {
    throw Error(std::string("add_mesh: ") + e.what());
  }
  return change_scene(handle, [&](SceneHandle& h) {
    h.scene.add_object(std::move(mesh), std::move(look), transform, name);
    if (image) h.scene.textures.push_back(image);
    if (render_texture) h.render_textures.push_back(render_texture);
    return static_cast<int>(h.scene.nodes.size());  // the new node's id: its index + 1
  });
}

// {id: name} of the nodes that draw meshes; the caller holds the scene's lock.
py::dict instances(const SceneHandle& handle) {
  py::dict ids;
  for (std::size_t n = 0; n < handle.scene.nodes.size(); ++n) {
    const SceneNode& node = handle.scene.nodes[n];
    if (!node.instances.empty() || !node.coarser.empty()) ids[py::int_(n + 1)] = node.name;
  }
  return ids;
}

py::object bounds(const SceneHandle& handle) {
  std::shared_lock lock(handle.mutex);
  const Bounds b = handle.scene.bounds();
  if (b.empty()) return py::none();
  return py::make_tuple(to_tuple(b.min), to_tuple(b.max));
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<SceneHandle> scene(m, "Scene", R"doc(
What a renderer draws: meshes with their materials and poses, lights, and a default camera.

Scene() starts empty, lit by the library's default sun and ambient light; facet.load(path)
reads a model file. Every node that draws meshes has an instance id, its position among the
scene's nodes plus 1, which the "instance" output shows (0 means "nothing"): add_mesh returns
the new node's; scene.instances maps a loaded file's ids to its node names.)doc");
  scene.def(py::init<>())
      .def("add_mesh", &add_mesh, py::arg("vertices"), py::arg("faces"), py::kw_only(),
           py::arg("normals") = py::none(), py::arg("uvs") = py::none(),
           py::arg("colors") = py::none(), py::arg("texture") = py::none(),
           py::arg("material") = py::none(), py::arg("pose") = py::none(), py::arg("name") = "",
           R"doc(
Adds a triangle mesh and returns its instance id (1, 2, ...).

vertices: (N, 3) float; faces: (M, 3) integer indices into vertices, counter-clockwise seen
from the front. Optional, one row per vertex: normals (N, 3); uvs (N, 2), v up (v = 0 is the
bottom row of the texture); colors (N, 3) or (N, 4), float in [0, 1] (linear) or uint8 (sRGB).
texture: an (H, W, 3) or (H, W, 4) uint8 image (sRGB, row 0 at the top; uvs repeat it), or a
facet.Texture (a RenderTexture's, showing its latest frame; uvs outside [0, 1] take its edge),
the material's base color map; needs uvs. material: a facet.Material (default: white
Lambert). pose: a 4x4 object-to-world matrix (default: identity). Arrays are copied.)doc")
      .def(
          "add_light",
          [](SceneHandle& handle, py::handle value) {
            const Light light = object_of<Light>(value, "add_light", "light", "Light");
            change_scene(handle, [&](SceneHandle& h) {
              if (h.default_lights) h.scene.lighting.lights.clear();
              h.default_lights = false;
              h.scene.lighting.lights.push_back(light);
            });
          },
          py::arg("light"),
          "Adds a facet.Light. The first one replaces the scene's default lights (the default "
          "sun, or the three-point lights a file without lights gets); a file's own lights "
          "stay.")
      .def(
          "clear_lights",
          [](SceneHandle& handle) {
            change_scene(handle, [](SceneHandle& h) {
              h.scene.lighting.lights.clear();
              h.default_lights = false;
            });
          },
          "Removes every light (the ambient light stays).")
      .def_property_readonly(
          "lights",
          [](const SceneHandle& handle) {
            std::shared_lock lock(handle.mutex);
            return handle.scene.lighting.lights;
          },
          "The lights, as a list of copies.")
      .def_property(
          "ambient",
          [](const SceneHandle& handle) {
            std::shared_lock lock(handle.mutex);
            return to_tuple(handle.scene.lighting.ambient);
          },
          [](SceneHandle& handle, py::handle value) {
            const glm::vec3 ambient = vec3(value, {"Scene", "ambient"});
            if (ambient.r < 0.0f || ambient.g < 0.0f || ambient.b < 0.0f) {
              throw Error("Scene: ambient must not be negative");
            }
            change_scene(handle, [&](SceneHandle& h) { h.scene.lighting.ambient = ambient; });
          },
          "Linear RGB light added to every lit surface.")
      .def_property(
          "camera",
          [](const SceneHandle& handle) {
            std::shared_lock lock(handle.mutex);
            return handle.scene.camera;
          },
          [](SceneHandle& handle, py::handle value) {
            const Camera camera = object_of<Camera>(value, "Scene", "camera", "Camera");
            change_scene(handle, [&](SceneHandle& h) {
              h.scene.camera = camera;
              h.scene.framing.reset();  // a camera set by hand is kept as it is
            });
          },
          "The default view (render(scene) without a camera): for a loaded file, a camera that "
          "frames the whole model (for 16:9; render frames it again for its image's aspect, "
          "until a camera is set here).")
      .def_property_readonly(
          "cameras",
          [](const SceneHandle& handle) {
            std::shared_lock lock(handle.mutex);
            return handle.scene.cameras;
          },
          "The cameras stored in a loaded file (world space).")
      .def_property_readonly(
          "instances",
          [](const SceneHandle& handle) {
            std::shared_lock lock(handle.mutex);
            return instances(handle);
          },
          "{id: name} of every node that draws something: the ids the "
          "instance output shows.")
      .def_property_readonly("triangle_count",
                             [](const SceneHandle& handle) {
                               std::shared_lock lock(handle.mutex);
                               return handle.scene.triangle_count();
                             })
      .def_property_readonly("bounds", &bounds,
                             "((min x, y, z), (max x, y, z)) around every instance in world "
                             "space, or None for an empty scene.")
      .def("__repr__", [](const SceneHandle& handle) {
        std::shared_lock lock(handle.mutex);
        std::ostringstream out;
        out << "<facet.Scene: " << instances(handle).size() << " instances, "
            << handle.scene.triangle_count() << " triangles, "
            << handle.scene.lighting.lights.size() << " lights>";
        return out.str();
      });

  m.def("load", &load, py::arg("path"), py::arg("crease_angle") = 80.0, py::kw_only(),
        py::arg("time") = py::none(), py::arg("animation") = 0,
        py::arg("allow_outside_paths") = false, py::arg("fence_assimp") = true,
        py::arg("import_timeout") = 60.0, py::arg("import_memory_limit") = py::none(),
        R"doc(
Reads a model file into a Scene, as `facet render` does: OBJ+MTL, glTF 2.0 (.gltf/.glb), PLY,
STL, 3DS, FBX, COLLADA, OFF and .d. Meshes without normals get smooth ones, split where faces
meet at more than crease_angle degrees. The scene's camera frames the model; a file without
lights gets three lights around that view. Problems that do not stop the import (a missing
texture) are Python warnings; the rest raise facet.Error.

A glTF model is drawn at rest unless `time` (seconds) is given: then its animation number
`animation` (0-based) is sampled at that time, skins and morph targets applied; an animation the
file does not have raises facet.Error. Files the model references must lie in its folder unless
allow_outside_paths is True.

The formats assimp reads (OBJ, 3DS, FBX, COLLADA, OFF, ...) are read in a child
process (fence_assimp), limited to import_timeout seconds (None: no limit) and
import_memory_limit bytes of address space (None: half the machine's memory): a crash, a hang
or a runaway allocation inside assimp raises facet.Error naming the file instead of taking the
interpreter down. facet's own readers (glTF, PLY, STL, .d) need no fence.)doc");
}

}  // namespace facet::python
