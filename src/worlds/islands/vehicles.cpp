// The airplane and the boat (see objects.hpp).
#include "facet/procedural.hpp"
#include "worlds/islands/objects.hpp"

namespace facet::islands {
namespace {

// Turns a shape built around +Y so that its axis points along +X (or -X).
glm::mat4 along_x() { return rot_z(-90.0f); }
glm::mat4 along_minus_x() { return rot_z(90.0f); }

}  // namespace

Airplane airplane(glm::vec4 body_color, glm::vec4 wing_color, bool wheels) {
  constexpr float kRadius = 0.65f;
  Airplane plane;
  Model& m = plane.body;
  // Fuselage: an octagonal prism from the tail cone to the engine, a blunt nose cone.
  m.add(Surface::metal, prism(8, kRadius, 5.5f), at({-3.0f, 0, 0}) * along_x(), body_color);
  m.add_keeping_uv(Surface::paint, cone(kRadius, 0.9f, 8), at({2.5f, 0, 0}) * along_x(),
                   body_color);
  m.add_keeping_uv(Surface::paint, cone(kRadius, 2.8f, 8),
                   at({-3.0f, 0.12f, 0}) * along_minus_x() * scale({1.0f, 1.0f, 0.85f}),
                   body_color);
  m.add(Surface::glass, uv_sphere(0.5f, 10, 6), at({0.7f, 0.5f, 0}) * scale({2.0f, 0.9f, 1.1f}));
  // Wings, tailplane and fin in the trim color.
  m.add(Surface::paint, box({1.7f, 0.16f, 11.0f}), at({0.5f, -0.25f, 0}), wing_color);
  m.add(Surface::paint, box({1.0f, 0.1f, 3.8f}), at({-5.2f, 0.2f, 0}), wing_color);
  m.add(Surface::paint, box({1.3f, 1.7f, 0.1f}), at({-5.3f, 1.0f, 0}) * rot_z(18.0f), wing_color);
  if (wheels) {
    for (float z : {-1.3f, 1.3f}) {
      m.add(Surface::paint, box({0.12f, 1.1f, 0.12f}), at({1.0f, -1.0f, z}),
            srgb(0.3f, 0.3f, 0.32f));
      m.add(Surface::paint, prism(8, 0.32f, 0.22f), at({1.0f, -1.55f, z - 0.11f}) * rot_x(90.0f),
            srgb(0.12f, 0.12f, 0.12f));
    }
    m.add(Surface::paint, prism(8, 0.16f, 0.12f), at({-5.0f, -0.55f, -0.06f}) * rot_x(90.0f),
          srgb(0.12f, 0.12f, 0.12f));
  }
  // Propeller: a hub and one long blade through it, turning about +X at the nose.
  plane.hub = {3.45f, 0, 0};
  plane.propeller.add(Surface::metal, cone(0.24f, 0.5f, 8), along_x());
  plane.propeller.add(Surface::paint, box({0.08f, 2.5f, 0.22f}), glm::mat4(1.0f),
                      srgb(0.15f, 0.14f, 0.13f));
  return plane;
}

Model boat() {
  Model m;
  // The hull: a hexagonal prism turned so corners point fore and aft, then stretched into a
  // pointed hull; its bottom sits under the waterline.
  const glm::mat4 hull_shape = scale({4.0f, 1.0f, 1.4f}) * rot_y(30.0f);
  m.add(Surface::paint, prism(6, 1.0f, kBoatDeck + 0.5f), at({0, -0.5f, 0}) * hull_shape,
        srgb(0.12f, 0.28f, 0.55f));
  m.add(Surface::wood, prism(6, 0.94f, 0.06f), at({0, kBoatDeck, 0}) * hull_shape);
  // Cabin with a red roof and dark windows.
  m.add(Surface::paint, box({2.4f, 1.3f, 1.8f}), at({-0.7f, kBoatDeck + 0.65f, 0}),
        srgb(0.95f, 0.95f, 0.92f));
  m.add(Surface::paint, box({2.8f, 0.15f, 2.1f}), at({-0.7f, kBoatDeck + 1.37f, 0}),
        srgb(0.8f, 0.18f, 0.14f));
  for (float z : {-0.92f, 0.92f}) {
    m.add(Surface::glass, box({1.6f, 0.5f, 0.06f}), at({-0.7f, kBoatDeck + 0.9f, z}));
  }
  m.add(Surface::glass, box({0.06f, 0.5f, 1.3f}), at({0.52f, kBoatDeck + 0.9f, 0}));
  m.add(Surface::paint, prism(6, 0.06f, 2.4f), at({-1.2f, kBoatDeck + 1.4f, 0}),
        srgb(0.9f, 0.9f, 0.9f));
  // Foam at the bow and a wake at the stern.
  m.add(Surface::foam, uv_sphere(1.0f, 10, 5), at({3.7f, 0, 0}) * scale({1.0f, 0.25f, 1.0f}));
  m.add(Surface::foam, uv_sphere(1.0f, 10, 5), at({-4.5f, 0, 0}) * scale({2.2f, 0.2f, 1.5f}));
  return m;
}

}  // namespace facet::islands
