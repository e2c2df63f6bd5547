// The airfield's pieces (see objects.hpp): runway, apron, hangar, windsock.
#include <algorithm>

#include "facet/procedural.hpp"
#include "worlds/islands/objects.hpp"

namespace facet::islands {
namespace {

constexpr float kRunwayRepeat = 30.0f;  // metres of runway per repeat of its texture

// A flat strip from x0 to x1 (x0 < x1) across `width`, facing up; its texture runs across in u
// and along in v, from v_at_x0 to v_at_x1.
Mesh strip(float x0, float x1, float width, float v_at_x0, float v_at_x1) {
  const float z = 0.5f * width;
  Mesh m = quad({x0, 0, z}, {x1, 0, z}, {x1, 0, -z}, {x0, 0, -z});
  m.texcoords = {{0, v_at_x0}, {0, v_at_x1}, {1, v_at_x1}, {1, v_at_x0}};
  return m;
}

}  // namespace

Model runway(float length, float width) {
  const float end = std::min(20.0f, 0.25f * length), half = 0.5f * length;
  Model m;
  // Threshold markings at both ends (v = 0 at the runway's end), plain runway between; the
  // pieces meet edge to edge, so nothing overlaps and nothing fights over depth.
  m.add_keeping_uv(Surface::threshold, strip(-half, -half + end, width, 0.0f, 1.0f));
  m.add_keeping_uv(Surface::threshold, strip(half - end, half, width, 1.0f, 0.0f));
  m.add_keeping_uv(Surface::runway,
                   strip(-half + end, half - end, width, 0.0f, (length - 2 * end) / kRunwayRepeat));
  return m;
}

Model apron(float length, float width) {
  Model m;
  m.add(Surface::concrete, strip(-0.5f * length, 0.5f * length, width, 0, 1));
  return m;
}

Model hangar(float length, float width) {
  const float radius = 0.5f * width;
  Model m;
  // A dodecagonal prism lying along X, half sunk: its upper half is the arched roof and walls,
  // its end caps the gable walls (a vertex sits at the top, and the sides meet the ground
  // vertically).
  m.add(Surface::metal, prism(12, radius, length), at({-0.5f * length, 0, 0}) * rot_z(-90.0f));
  const float door_height = 0.65f * radius, door_width = 1.3f * radius;
  m.add(Surface::paint, box({0.3f, door_height, door_width}),
        at({0.5f * length + 0.1f, 0.5f * door_height, 0}), srgb(0.16f, 0.17f, 0.18f));
  // Door rails and a painted band make the arch read at a distance.
  m.add(Surface::paint, box({0.4f, 0.25f, door_width + 1.0f}),
        at({0.5f * length + 0.15f, door_height + 0.1f, 0}), srgb(0.75f, 0.2f, 0.15f));
  for (float x : {-0.25f * length, 0.0f, 0.25f * length}) {
    m.add(Surface::paint, prism(12, radius + 0.08f, 0.35f), at({x, 0, 0}) * rot_z(-90.0f),
          srgb(0.55f, 0.57f, 0.6f));
  }
  return m;
}

Model windsock() {
  Model m;
  m.add(Surface::paint, prism(6, 0.07f, 5.0f), at({0, -0.3f, 0}), srgb(0.9f, 0.9f, 0.9f));
  m.add(Surface::paint, cone(0.35f, 2.2f, 8), at({0.1f, 4.4f, 0}) * rot_z(-80.0f),
        srgb(1.0f, 0.45f, 0.1f));
  return m;
}

Model control_tower() {
  Model m;
  m.add(Surface::concrete, box({4.0f, 11.0f, 4.0f}), at({0, 5.2f, 0}));
  m.add(Surface::paint, box({5.4f, 0.3f, 5.4f}), at({0, 10.8f, 0}), srgb(0.85f, 0.85f, 0.82f));
  m.add(Surface::glass, box({5.0f, 2.4f, 5.0f}), at({0, 12.15f, 0}));
  m.add(Surface::paint, box({5.8f, 0.35f, 5.8f}), at({0, 13.5f, 0}), srgb(0.85f, 0.2f, 0.15f));
  m.add(Surface::paint, prism(6, 0.05f, 2.5f), at({1.5f, 13.6f, 1.5f}), srgb(0.9f, 0.9f, 0.9f));
  return m;
}

}  // namespace facet::islands
