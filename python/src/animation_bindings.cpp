// facet.AnimatedModel: a glTF model read once (facet::AnimatedModel) and handed out as a
// facet.Scene posed at any time, the camera and lights those facet.load gives the model.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "array_conversion.hpp"
#include "bindings.hpp"
#include "facet/import.hpp"

namespace facet::python {
namespace {

class PyAnimatedModel {
 public:
  PyAnimatedModel(py::handle path, py::handle animation, py::handle crease_angle,
                  bool allow_outside_paths) {
    ImportOptions options;
    options.crease_angle_degrees = number(crease_angle, {"AnimatedModel", "crease_angle"});
    options.animation = integer(animation, {"AnimatedModel", "animation"});
    options.allow_outside_paths = allow_outside_paths;
    options.time = 0.0;
    std::vector<std::string> warnings;
    options.warn = [&warnings](const std::string& warning) { warnings.push_back(warning); };
    const std::string file = py::str(py::module_::import("os").attr("fspath")(path));
    {
      py::gil_scoped_release release;
      // The camera and lights as facet.load gives them, from the pose at time 0; the poses
      // replace the meshes and nodes only.
      base_ = import_scene(file, options);
      options.warn = [](const std::string&) {};  // said once
      model_.emplace(file, options);
    }
    for (const std::string& warning : warnings) {
      if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
    }
  }

  double duration() const { return model_->duration(); }
  int animation_count() const { return model_->animation_count(); }

  std::unique_ptr<SceneHandle> scene(py::handle time) const {
    const double seconds = number(time, {"AnimatedModel.scene", "time"});
    auto handle = std::make_unique<SceneHandle>();
    {
      py::gil_scoped_release release;
      Scene posed = model_->pose(seconds);
      handle->scene = base_;
      handle->scene.meshes = std::move(posed.meshes);
      handle->scene.nodes = std::move(posed.nodes);
    }
    handle->default_lights = !handle->scene.has_file_lights;
    return handle;
  }

 private:
  Scene base_;
  std::optional<AnimatedModel> model_;
};

}  // namespace

void bind_animation(py::module_& m) {
  py::class_<PyAnimatedModel>(m, "AnimatedModel", R"doc(
A glTF model (.gltf, .glb) read once, to be posed at any time without reading or decoding the
file again: for the frames of an animation. animation: which of the file's animations
(0-based); crease_angle and allow_outside_paths as facet.load. Raises facet.Error for another
format or an animation the file does not have.)doc")
      .def(py::init<py::handle, py::handle, py::handle, bool>(), py::arg("path"),
           py::arg("animation") = 0, py::kw_only(), py::arg("crease_angle") = 80.0,
           py::arg("allow_outside_paths") = false)
      .def_property_readonly("duration", &PyAnimatedModel::duration,
                             "The animation's length in seconds (its last key); 0 without one.")
      .def_property_readonly("animation_count", &PyAnimatedModel::animation_count,
                             "How many animations the file has.")
      .def("scene", &PyAnimatedModel::scene, py::arg("time"), R"doc(
A new facet.Scene of the model posed at `time` seconds of the animation (clamped to its keys),
skins and morph targets applied; its camera and lights are facet.load's for the model.)doc");
}

}  // namespace facet::python
