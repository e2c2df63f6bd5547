// The things of the islands world, one small function each, composed from procedural shapes.
// Every model stands on its own origin (y = 0 is the ground it stands on, or the waterline for
// the boat) and faces +X where it has a front; parts meant to sink into uneven ground reach
// below y = 0.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "worlds/islands/kit.hpp"

namespace facet::islands {

// How finely a thing is made: `far` for a stand-in seen from afar (fewer facets on its round
// parts, no small parts), with the same outline and colors.
enum class Detail { full, far };

// Trees; `seed` varies their proportions and shade.
Model conifer(float height, std::uint32_t seed, Detail detail = Detail::full);    // stacked cones
Model broadleaf(float height, std::uint32_t seed, Detail detail = Detail::full);  // a few spheres
Model palm(float height, std::uint32_t seed, Detail detail = Detail::full);   // fronds on a trunk
Model bush(float size, std::uint32_t seed, Detail detail = Detail::full);     // a clump of leaves
Model boulder(float size, std::uint32_t seed, Detail detail = Detail::full);  // a rough stone

// Brick walls, a tiled gable roof (ridge along X), a door and windows on the +Z front.
Model house(float width, float depth, float wall_height);
// A wooden deck spanning X with railings, stone abutments and piers; the deck's top is y = 0.
Model bridge(float span, float width);

// A runway along X with threshold markings at both ends; its surface is at y = 0.
Model runway(float length, float width);
// A concrete apron (parking area) of the given size at y = 0.
Model apron(float length, float width);
// An arched metal hangar along X, its door on the +X end.
Model hangar(float length, float width);
// A windsock on a pole, for the airfield.
Model windsock();
// A concrete tower with a glazed cab on top.
Model control_tower();

Model cloud(std::uint32_t seed);

// An airplane with its nose along +X. The propeller is separate so it can spin: it turns about
// +X, around its own origin, which sits at `hub` in the airplane's space.
struct Airplane {
  Model body;
  Model propeller;
  glm::vec3 hub{0.0f};
};
Airplane airplane(glm::vec4 body_color, glm::vec4 wing_color, bool wheels);
// How far the wheels reach below the airplane's origin.
inline constexpr float kAirplaneWheelDrop = 1.87f;

// A motor boat along X (bow at +X); y = 0 is the waterline, the deck is at kBoatDeck.
inline constexpr float kBoatDeck = 0.6f;
Model boat();

}  // namespace facet::islands
