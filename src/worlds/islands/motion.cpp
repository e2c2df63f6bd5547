// The islands world's animation (see include/facet/islands.hpp): every pose is a function of
// the time alone. Angles and offsets are reduced in double precision before they become floats,
// so an hour into the animation moves as smoothly as the first second.
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/islands.hpp"
#include "worlds/islands/kit.hpp"
#include "worlds/islands/map.hpp"
#include "worlds/islands/objects.hpp"

namespace facet {
namespace {

using glm::vec2;
using glm::vec3;
using islands::at;
using islands::rot_x;
namespace map = islands::map;

constexpr double kTau = 6.283185307179586;
constexpr double kDegrees = 360.0 / kTau;

// The fraction of `cycles` past its last whole cycle, in [0, 1).
double fraction(double cycles) { return cycles - std::floor(cycles); }

// A pose for something whose nose points along +X in its own space, heading along `velocity`.
glm::mat4 heading(vec3 position, vec2 velocity_xz) {
  return at(position, static_cast<float>(std::atan2(-velocity_xz.y, velocity_xz.x) * kDegrees));
}

glm::mat4 flight_pose(double t) {
  const double period = kTau * map::kFlightRadius / map::kFlightSpeed;
  const double angle = map::kFlightStartDegrees / kDegrees + kTau * fraction(t / period);
  const vec2 out(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
  const vec2 p = map::kFlightCentre + map::kFlightRadius * out;
  const float swell = 4.0f * static_cast<float>(std::sin(kTau * fraction(t / 37.0)));
  // Flying with the angle growing keeps the centre on the right: bank right, into the turn.
  return heading({p.x, map::kFlightAltitude + swell, p.y}, {-out.y, out.x}) * rot_x(20.0f);
}

glm::mat4 boat_pose(double t) {
  const double angle = kTau * fraction(t / map::kBoatLapSeconds);
  const float c = static_cast<float>(std::cos(angle)), s = static_cast<float>(std::sin(angle));
  const vec2 radii = map::kBoatLoopRadii;
  const vec2 p = map::kBoatLoopCentre + vec2(radii.x * c, radii.y * s);
  // A gentle swell: the boat heaves and rolls a little, never deep enough to ship water.
  const float heave = 0.06f * static_cast<float>(std::sin(kTau * fraction(t / 2.7)));
  const float roll = 2.0f * static_cast<float>(std::sin(kTau * fraction(t / 3.3)));
  return heading({p.x, heave, p.y}, {-radii.x * s, radii.y * c}) * rot_x(roll);
}

glm::mat4 spin(const glm::mat4& current, double t) {
  const vec3 hub(current[3]);  // the hub stays where the builder put it
  const double turns = fraction(t * map::kPropellerTurnsPerSecond);
  return at(hub) * rot_x(static_cast<float>(turns * 360.0));
}

glm::mat3 scroll(double offset_u, double offset_v) {
  glm::mat3 m(1.0f);
  m[2] = vec3(static_cast<float>(fraction(offset_u)), static_cast<float>(fraction(offset_v)), 1.0f);
  return m;
}

}  // namespace

void IslandsWorld::animate(double seconds) {
  const double t = seconds;
  std::vector<SceneNode>& nodes = scene.nodes;
  nodes[flying_airplane].transform = flight_pose(t);
  nodes[flying_propeller].transform = spin(nodes[flying_propeller].transform, t);
  nodes[parked_propeller].transform = spin(nodes[parked_propeller].transform, t);
  nodes[boat].transform = boat_pose(t);
  for (std::size_t k = 0; k < clouds.size(); ++k) {
    const vec3 origin = cloud_origins[k];
    const double east = fraction((origin.x - map::kCloudsWest + map::kWind * t) / map::kCloudsSpan);
    nodes[clouds[k]].transform =
        at({map::kCloudsWest + static_cast<float>(east) * map::kCloudsSpan, origin.y, origin.z});
  }
  // A growing v offset moves the pattern down the falls and down the river (see terrain_mesh.cpp).
  scene.materials[waterfall_material].base_color_map.transform = scroll(0.0, map::kFallsScroll * t);
  scene.materials[river_material].base_color_map.transform = scroll(0.0, map::kRiverScroll * t);
  scene.materials[ocean_material].base_color_map.transform =
      scroll(map::kOceanDrift.x * t, map::kOceanDrift.y * t);
}

glm::vec3 IslandsWorld::boat_position() const {
  return vec3(scene.world_transform(boat) * glm::vec4(0.0f, islands::kBoatDeck, 0.0f, 1.0f));
}

glm::vec3 IslandsWorld::airplane_position() const {
  return vec3(scene.world_transform(flying_airplane)[3]);
}

glm::vec3 IslandsWorld::parked_propeller_position() const {
  return vec3(scene.world_transform(parked_propeller)[3]);
}

}  // namespace facet
