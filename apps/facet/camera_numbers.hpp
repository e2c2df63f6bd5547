// The camera values given on the command line (--eye, --target, --near, --far) held against
// what 32-bit float rendering can turn into an image: build_camera (scene_options.cpp) calls
// it before Camera::validate, so a value that would draw nothing, or overflow on the way, is
// named with its flag instead.
#pragma once

#include "facet/camera.hpp"
#include "facet/scene.hpp"
#include "scene_options.hpp"

namespace facet::cli {

// The largest far/near ratio of a perspective camera. Window depth is 1 - near/z (glm's
// OpenGL projection, in float) for far >> near; the largest float below 1 is 1 - 2^-24, so
// from about 2^24 (1.7e7) near-plane distances on every depth rounds to 1, the cleared depth,
// and nothing there passes the depth test. 1e7 keeps the far plane two float steps below 1.
inline constexpr double kMaxFarNearRatio = 1e7;
// The largest distance from the eye to its target: the camera squares it (normalizing the view
// direction, validating it), and the square must stay a finite float (below 3.4e38).
inline constexpr double kMaxEyeTargetDistance = 1e18;
// How far the eye may stand from the scene, in scene radii: beyond it the scene's depth range
// (3.5 radii between the near and far planes fitted to it) is less than about 16 float steps of
// the distance, and the whole scene is far smaller than a pixel.
inline constexpr double kMaxEyeDistanceInRadii = 1e6;

// Throws facet::Error naming the flag(s) at fault when the options' values would give no image.
void check_camera_numbers(const SceneOptions& options, const Scene& scene, const Camera& camera);

}  // namespace facet::cli
