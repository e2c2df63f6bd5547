// The islands world's sound in the viewer: a SoundScene with looping sources at the waterfall,
// on the boat, on the flying airplane and at the parked propeller, moved with the world every
// frame, heard from the camera. With no audio device it runs silently (one warning line).
#pragma once

#include "facet/camera.hpp"
#include "facet/islands.hpp"
#include "facet/sound.hpp"

namespace facet::cli {

class IslandsSound {
 public:
  // Adds the sources where `world` has them now and starts them. The viewer plays through the
  // default device; tests pass a loopback desc and listen through scene().
  explicit IslandsSound(const IslandsWorld& world, const SoundSceneDesc& output = {});

  // Moves the sources to where the world's parts are now and the listener to the camera;
  // velocities are the change in position over `dt` seconds (Doppler shift).
  void update(const IslandsWorld& world, const Camera& camera, double dt);

  void set_muted(bool muted) { sound_.set_muted(muted); }
  bool muted() const { return sound_.muted(); }
  bool available() const { return sound_.available(); }
  SoundScene& scene() { return sound_; }

 private:
  struct Source {
    int id = -1;
    glm::vec3 position{0.0f};
  };
  void step(Source& source, glm::vec3 position, double dt);

  SoundScene sound_;
  Source waterfall_, boat_, airplane_, propeller_;
  glm::vec3 listener_{0.0f};
  bool first_update_ = true;
};

}  // namespace facet::cli
