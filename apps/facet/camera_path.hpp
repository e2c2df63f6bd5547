// Camera paths for `facet view --camera-path FILE`: timed first-person camera keys read from a
// small text file and interpolated, so a fly-through is scripted and repeatable.
//
// The format, one key per line:
//
//   # comment (from '#' to the end of the line); blank lines are ignored
//   # t     x     y     z     yaw   pitch
//   0       0     1.7   10    0     0
//   4.5     5     3     2     45    -10
//
//   t      seconds, strictly increasing from line to line (the animation clock: --time or the
//          real clock since the start)
//   x y z  the eye, world units
//   yaw    degrees; 0 looks down -Z, positive turns left. Not wrapped: 350 then 370 turns 20
//          degrees left, 350 then 10 turns 340 degrees right
//   pitch  degrees, positive looks up, inside (-90, 90)
//
// Between keys the eye and the angles follow a Catmull-Rom spline through the keys (smooth
// through every key); before the first key the camera holds the first, after the last the last.
#pragma once

#include <string>
#include <vector>

#include "facet/camera.hpp"

namespace facet::cli {

struct CameraKey {
  double time = 0.0;
  FirstPersonCamera pose;
};

class CameraPath {
 public:
  // Reads and checks a path file. Throws facet::Error as "FILE:LINE: problem" (or "FILE:
  // problem" for a missing, unreadable or empty file).
  static CameraPath load(const std::string& path);
  // The same from text; `name` stands for the file in messages.
  static CameraPath parse(const std::string& text, const std::string& name);

  // The pose at `seconds`.
  FirstPersonCamera at(double seconds) const;
  const std::vector<CameraKey>& keys() const { return keys_; }

 private:
  std::vector<CameraKey> keys_;  // at least one, times strictly increasing
};

}  // namespace facet::cli
