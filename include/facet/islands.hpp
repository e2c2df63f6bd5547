// The islands world: two islands in an ocean (mountains, canyon, waterfall, river, village and an
// airport), built from procedural shapes and textures as a plain Scene and animated by time.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "facet/scene.hpp"

namespace facet {

struct IslandsWorld {
  Scene scene;

  // Poses the moving parts for time `seconds` since the start. Only the time matters, never
  // the calls before: the same t always gives the same scene, so frames can be rendered in
  // any order (or on different machines).
  void animate(double seconds);

  // Nodes that animate() moves (indices into scene.nodes).
  int flying_airplane = -1;              // flies a circle over both islands
  int flying_propeller = -1;             // child of flying_airplane
  int parked_airplane = -1;              // stands on the apron
  int parked_propeller = -1;             // child of parked_airplane, spins
  int boat = -1;                         // crosses between the islands and back
  std::vector<int> clouds;               // drift with the wind
  std::vector<glm::vec3> cloud_origins;  // where each cloud is at t = 0
  // Materials whose texture scrolls (indices into scene.materials).
  int waterfall_material = -1;
  int river_material = -1;
  int ocean_material = -1;

  glm::vec3 waterfall_centre{0.0f};  // the middle of the falling sheet, for sound
  glm::vec3 waterfall_position() const { return waterfall_centre; }
  glm::vec3 boat_position() const;              // the boat's deck centre, world space
  glm::vec3 airplane_position() const;          // the flying airplane's centre
  glm::vec3 parked_propeller_position() const;  // the hub of the parked airplane's propeller
};

// The world at t = 0 with its start camera: standing on the first island at eye height,
// looking across the water at the second. Textures are generated here (no files are read).
IslandsWorld make_islands_world();
// make_islands_world().scene: the world as a built-in scene ("islands").
Scene make_islands_scene();

}  // namespace facet
