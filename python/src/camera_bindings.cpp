// facet.Camera: where the eye is and how it projects (facet::Camera). The aspect is not the
// camera's: the renderer sets it from its image size at render time (camera_for_image), so
// one camera serves images of any shape.
#include "camera_bindings.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "array_conversion.hpp"
#include "bindings.hpp"
#include "facet/error.hpp"

namespace facet::python {
namespace {

// Throws facet::Error "<function>: camera: ..." unless the camera can project.
void check(const Camera& camera, const char* function) {
  try {
    camera.validate();
  } catch (const Error& e) {
    throw Error(std::string(function) + ": " + e.what());
  }
}

// A setter that keeps the camera valid: the change is made on a copy and kept only if the
// copy can project.
template <class Set>
void change(Camera& camera, const char* field, Set&& set) {
  Camera changed = camera;
  set(changed);
  check(changed, (std::string("Camera.") + field).c_str());
  camera = changed;
}

}  // namespace

Camera camera_for_image(Camera camera, int width, int height) {
  if (camera.calibrated_size != glm::ivec2(0)) {
    // A calibrated camera keeps its own aspect: it is right for its image size alone.
    if (camera.calibrated_size != glm::ivec2(width, height)) {
      throw Error("render: camera: calibrated for " + std::to_string(camera.calibrated_size.x) +
                  "x" + std::to_string(camera.calibrated_size.y) + " images, the renderer makes " +
                  std::to_string(width) + "x" + std::to_string(height) +
                  " (scale the intrinsics with the image)");
    }
  } else {
    camera.aspect = static_cast<float>(width) / static_cast<float>(height);
  }
  check(camera, "render");
  return camera;
}

void bind_camera(py::module_& m) {
  py::class_<Camera> camera(m, "Camera", R"doc(
A perspective camera: right-handed, looking down -Z in view space, y up, OpenGL-style
projection. The aspect ratio comes from the renderer's image size when a frame is rendered.
Make one with Camera.look_at; every field can be changed afterwards (a change that leaves a
camera unable to project raises facet.Error).)doc");
  camera.def_static(
      "look_at",
      [](py::handle eye, py::handle target, py::handle up, py::handle fov_y, py::handle near,
         py::handle far) {
        constexpr const char* kName = "Camera.look_at";
        Camera out = Camera::look_at(vec3(eye, {kName, "eye"}), vec3(target, {kName, "target"}),
                                     vec3(up, {kName, "up"}), number(fov_y, {kName, "fov_y"}), 1.0f,
                                     number(near, {kName, "near"}), number(far, {kName, "far"}));
        check(out, kName);
        return out;
      },
      py::arg("eye"), py::arg("target"), py::arg("up") = py::make_tuple(0.0, 1.0, 0.0),
      py::arg("fov_y") = 60.0, py::arg("near") = 0.1, py::arg("far") = 100.0,
      "A camera at eye looking at target, up pointing up; fov_y is the vertical field of view in "
      "degrees; near and far are the clip distances in scene units.");
  camera.def_static(
      "orthographic",
      [](py::handle eye, py::handle target, py::handle up, py::handle height, py::handle near,
         py::handle far) {
        constexpr const char* kName = "Camera.orthographic";
        const float view_height = number(height, {kName, "height"});
        if (!(view_height > 0.0f) || !std::isfinite(view_height)) {
          throw Error(std::string(kName) + ": height must be a positive number of scene units");
        }
        Camera out = Camera::orthographic(
            vec3(eye, {kName, "eye"}), vec3(target, {kName, "target"}), vec3(up, {kName, "up"}),
            view_height, 1.0f, number(near, {kName, "near"}), number(far, {kName, "far"}));
        check(out, kName);
        return out;
      },
      py::arg("eye"), py::arg("target"), py::arg("up") = py::make_tuple(0.0, 1.0, 0.0),
      py::arg("height") = 2.0, py::arg("near") = 0.1, py::arg("far") = 100.0,
      "A parallel projection from eye toward target, up pointing up, whose view is height scene "
      "units tall at every distance (and height x the image's aspect wide).");
  camera.def_static(
      "from_intrinsics",
      [](py::handle k, py::handle width, py::handle height, py::handle near, py::handle far,
         py::handle pose, const std::string& convention) {
        constexpr const char* kName = "Camera.from_intrinsics";
        const glm::mat3 K = matrix3(k, {kName, "K"});  // K[column][row]
        if (K[0][1] != 0.0f || K[1][0] != 0.0f || K[0][2] != 0.0f || K[1][2] != 0.0f ||
            K[2][2] != 1.0f) {
          throw Error(std::string(kName) +
                      ": K must be [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] (no skew)");
        }
        Intrinsics intrinsics;
        intrinsics.fx = K[0][0], intrinsics.fy = K[1][1];
        intrinsics.cx = K[2][0], intrinsics.cy = K[2][1];
        intrinsics.width = integer(width, {kName, "width"});
        intrinsics.height = integer(height, {kName, "height"});
        CameraConvention axes;
        if (convention == "opencv") {
          axes = CameraConvention::opencv;
        } else if (convention == "opengl") {
          axes = CameraConvention::opengl;
        } else {
          throw Error(std::string(kName) + ": convention must be 'opencv' or 'opengl', got '" +
                      convention + "'");
        }
        const glm::mat4 to_world =
            pose.is_none() ? glm::mat4(1.0f) : matrix4(pose, {kName, "pose"});
        try {
          return Camera::from_intrinsics(intrinsics, to_world, axes, number(near, {kName, "near"}),
                                         number(far, {kName, "far"}));
        } catch (const Error& e) {
          throw Error(std::string(kName) + ": " + e.what());
        }
      },
      py::arg("K"), py::arg("width"), py::arg("height"), py::arg("near") = 0.1,
      py::arg("far") = 100.0, py::arg("pose") = py::none(), py::arg("convention") = "opencv",
      R"doc(
A calibrated pinhole camera for width x height images. K = [[fx, 0, cx], [0, fy, cy], [0, 0, 1]]
in pixels, OpenCV's pixel-centre convention: a camera-frame point (X, Y, Z) is drawn in pixel
(round(fx X / Z + cx), round(fy Y / Z + cy)), u right and v down from the top-left. pose: the
4x4 camera-to-world rigid transform (default: identity, the camera at the origin); convention
says how its axes read: "opencv" (x right, y down, z forward) or "opengl" (x right, y up,
looking down -z). Render it with a renderer of width x height (docs/cameras.md).)doc");
  camera
      .def_property(
          "eye", [](const Camera& c) { return to_tuple(c.eye); },
          [](Camera& c, py::handle v) {
            change(c, "eye", [&](Camera& x) { x.eye = vec3(v, {"Camera", "eye"}); });
          })
      .def_property(
          "target", [](const Camera& c) { return to_tuple(c.target); },
          [](Camera& c, py::handle v) {
            change(c, "target", [&](Camera& x) { x.target = vec3(v, {"Camera", "target"}); });
          })
      .def_property(
          "up", [](const Camera& c) { return to_tuple(c.up); },
          [](Camera& c, py::handle v) {
            change(c, "up", [&](Camera& x) { x.up = vec3(v, {"Camera", "up"}); });
          })
      .def_property(
          "fov_y", [](const Camera& c) { return to_python(c.fov_y_degrees); },
          [](Camera& c, py::handle v) {
            change(c, "fov_y", [&](Camera& x) {
              x.fov_y_degrees = number(v, {"Camera", "fov_y"});
            });
          })
      .def_property(
          "near", [](const Camera& c) { return to_python(c.near_plane); },
          [](Camera& c, py::handle v) {
            change(c, "near", [&](Camera& x) { x.near_plane = number(v, {"Camera", "near"}); });
          })
      .def_property(
          "far", [](const Camera& c) { return to_python(c.far_plane); },
          [](Camera& c, py::handle v) {
            change(c, "far", [&](Camera& x) { x.far_plane = number(v, {"Camera", "far"}); });
          })
      .def(
          "view_matrix", [](const Camera& c) { return to_numpy(c.view()); },
          "The 4x4 world-to-camera matrix (float64, row-major: points are columns, p_view = M @ "
          "p_world); the camera looks down -Z, y up.")
      .def(
          "projection_matrix",
          [](Camera c, py::handle aspect) {
            c.aspect = number(aspect, {"Camera.projection_matrix", "aspect"});
            check(c, "Camera.projection_matrix");
            return to_numpy(c.projection());
          },
          py::arg("aspect"),
          "The 4x4 OpenGL projection (camera space to clip space, z in [-w, w]) for an image of "
          "this width / height.")
      .def("__repr__", [](const Camera& c) {
        std::ostringstream out;
        out << "facet.Camera.look_at(eye=" << to_text(c.eye) << ", target=" << to_text(c.target)
            << ", up=" << to_text(c.up) << ", fov_y=" << c.fov_y_degrees
            << ", near=" << c.near_plane << ", far=" << c.far_plane << ")";
        return out.str();
      });
}

}  // namespace facet::python
