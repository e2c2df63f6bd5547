// Positional sound: looping mono sources in world space heard by one listener (the camera)
// through OpenAL Soft, and synthesizers for the built-in world's sounds (no sound files needed).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

namespace facet {

// Mono 16-bit PCM. Positional sources must be mono: OpenAL plays multi-channel buffers
// unspatialized, so there is deliberately no channel count here.
struct SoundBuffer {
  int sample_rate = 44100;
  std::vector<std::int16_t> samples;
};

// Synthesizers for the islands world. Deterministic (same call, same samples), 44100 Hz, and each
// is a seamless loop: every periodic part has a whole number of cycles in the buffer and filtered
// noise is filtered circularly, so the last sample runs into the first like any other pair.
// `seconds` must be in (0, 60]; the length is round(seconds * 44100) samples.
SoundBuffer waterfall_noise(double seconds);  // band-limited noise with a slow swell
SoundBuffer engine_hum(double seconds);       // ~50 Hz tone with harmonics and a putt-putt pulse
SoundBuffer propeller_buzz(double seconds);   // ~100 Hz sawtooth with blade-rate modulation

enum class SoundOutput {
  default_device,  // the system's default output (PulseAudio, ALSA, ...)
  loopback,        // no hardware: the caller pulls stereo samples with render_loopback (tests)
};

struct SoundSceneDesc {
  SoundOutput output = SoundOutput::default_device;
  std::string device_name;           // default_device only: a named device; empty = the default
  int loopback_sample_rate = 44100;  // loopback only
};

// One OpenAL device and context with its sources. Sources loop, are placed by position (metres,
// world space) and velocity, fade with distance (inverse distance, clamped below the source's
// reference distance) and are Doppler shifted (speed of sound 343 m/s).
//
// The API is position-based on purpose: following a scene node is the caller's job (the viewer
// copies each node's world position into set_source every frame), so this stays independent of
// the scene graph and of any window or input library.
//
// With no audio device (servers, CI) construction prints one warning line to stderr and
// available() is false; every call then does nothing (add_source still hands out ids), so a
// program needs no separate silent path. Invalid arguments throw facet::Error either way.
// OpenAL's and ALSA's own messages while a device opens are held back; set FACET_SOUND_DEBUG=1
// in the environment to see them.
class SoundScene {
 public:
  explicit SoundScene(const SoundSceneDesc& desc = {});
  ~SoundScene();
  SoundScene(SoundScene&&) noexcept;  // a moved-from scene may only be destroyed or assigned
  SoundScene& operator=(SoundScene&&) noexcept;
  SoundScene(const SoundScene&) = delete;
  SoundScene& operator=(const SoundScene&) = delete;

  bool available() const;

  // Uploads a copy of `buffer` as a new looping source, stopped. The gain is the source's level
  // at or inside `reference_distance`; beyond it the level falls as reference / distance.
  int add_source(const SoundBuffer& buffer, glm::vec3 position, float gain = 1.0f,
                 float reference_distance = 4.0f);
  void set_source(int id, glm::vec3 position, glm::vec3 velocity = glm::vec3(0.0f));
  void play(int id);
  void stop(int id);

  // `forward` and `up` need not be unit length but must not be zero or parallel.
  void set_listener(glm::vec3 position, glm::vec3 forward, glm::vec3 up,
                    glm::vec3 velocity = glm::vec3(0.0f));

  void set_muted(bool muted);  // the listener's master gain: 0 or 1
  bool muted() const;

  // Loopback scenes only: mixes the next `frames` frames and returns them as interleaved stereo
  // floats (left, right, left, ...), 2 * frames values. A silent scene returns zeros.
  std::vector<float> render_loopback(int frames);

 private:
  struct Impl;
  Impl& impl() const;  // throws facet::Error on a moved-from scene
  std::unique_ptr<Impl> impl_;
};

}  // namespace facet
