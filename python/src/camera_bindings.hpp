// The camera a frame is rendered with (python/src/camera_bindings.cpp): facet.Camera's fields
// with the aspect of the image being made, checked.
#pragma once

#include "facet/camera.hpp"

namespace facet::python {

// `camera` with aspect width / height; throws facet::Error ("render: camera: ...") if it
// cannot project.
Camera camera_for_image(Camera camera, int width, int height);

}  // namespace facet::python
