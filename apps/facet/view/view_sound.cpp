// The islands world's sound in the viewer (see view_sound.hpp).
#include "view_sound.hpp"

#include <glm/glm.hpp>

namespace facet::cli {
namespace {

constexpr double kLoopSeconds = 4.0;  // each synthesized loop; they are seamless
// Reference distances (metres): full level inside, falling as reference / distance beyond.
constexpr float kWaterfallReach = 25.0f;
constexpr float kBoatReach = 8.0f;
constexpr float kAirplaneReach = 30.0f;
constexpr float kPropellerReach = 6.0f;

}  // namespace

IslandsSound::IslandsSound(const IslandsWorld& world, const SoundSceneDesc& output)
    : sound_(output) {
  waterfall_.position = world.waterfall_position();
  boat_.position = world.boat_position();
  airplane_.position = world.airplane_position();
  propeller_.position = world.parked_propeller_position();
  waterfall_.id =
      sound_.add_source(waterfall_noise(kLoopSeconds), waterfall_.position, 1.0f, kWaterfallReach);
  boat_.id = sound_.add_source(engine_hum(kLoopSeconds), boat_.position, 0.8f, kBoatReach);
  SoundBuffer buzz = propeller_buzz(kLoopSeconds);
  airplane_.id = sound_.add_source(buzz, airplane_.position, 1.0f, kAirplaneReach);
  propeller_.id = sound_.add_source(buzz, propeller_.position, 0.7f, kPropellerReach);
  for (int id : {waterfall_.id, boat_.id, airplane_.id, propeller_.id}) sound_.play(id);
}

void IslandsSound::step(Source& source, glm::vec3 position, double dt) {
  glm::vec3 velocity(0.0f);
  if (!first_update_ && dt > 0.0) velocity = (position - source.position) / static_cast<float>(dt);
  source.position = position;
  sound_.set_source(source.id, position, velocity);
}

void IslandsSound::update(const IslandsWorld& world, const Camera& camera, double dt) {
  step(waterfall_, world.waterfall_position(), dt);
  step(boat_, world.boat_position(), dt);
  step(airplane_, world.airplane_position(), dt);
  step(propeller_, world.parked_propeller_position(), dt);
  glm::vec3 velocity(0.0f);
  if (!first_update_ && dt > 0.0) velocity = (camera.eye - listener_) / static_cast<float>(dt);
  listener_ = camera.eye;
  sound_.set_listener(camera.eye, camera.forward(), camera.up, velocity);
  first_update_ = false;
}

}  // namespace facet::cli
