// SoundScene: looping positional sources and the listener, on an OpenAL Soft context opened by
// openal_device.cpp. Public functions check their arguments (facet::Error) and do nothing more
// when the scene is silent; the OpenAL calls below them assume valid input.
#include <AL/al.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "facet/sound.hpp"
#include "sound/openal_device.hpp"

namespace facet {

struct SoundScene::Impl {
  audio::OpenAlDevice al;
  bool loopback = false;
  bool muted = false;
  int source_count = 0;         // ids 0 .. source_count-1 were handed out (also while silent)
  std::vector<ALuint> sources;  // by id; empty while silent
  std::vector<ALuint> buffers;  // by id: each source owns the copy of its samples

  ~Impl() {
    if (available()) {
      make_current();
      for (ALuint source : sources) alSourceStop(source);
      alDeleteSources(static_cast<ALsizei>(sources.size()), sources.data());
      alDeleteBuffers(static_cast<ALsizei>(buffers.size()), buffers.data());
    }
    audio::close_device(al);
  }

  bool available() const { return al.context != nullptr; }

  // The OpenAL source of `id`, or 0 (never a valid source name) while silent.
  ALuint source(int id) const {
    if (id < 0 || id >= source_count) {
      throw Error("SoundScene: no source with id " + std::to_string(id));
    }
    return available() ? sources[static_cast<std::size_t>(id)] : 0;
  }

  // The current context is process-wide in OpenAL; with more than one scene alive, each call
  // must first make its own current.
  void make_current() const {
    if (alcGetCurrentContext() != al.context) alcMakeContextCurrent(al.context);
  }
};

namespace {

// Distance and Doppler rules for every scene. Inverse-distance-clamped gain is
// reference / (reference + rolloff * (distance - reference)) with the distance clamped to at least
// the reference (OpenAL 1.1 specification §3.4): full level inside the reference distance, and
// with rolloff 1 the 1/r amplitude fall-off of a point source in free air beyond it.
constexpr ALfloat kRolloffFactor = 1.0f;
constexpr ALfloat kSpeedOfSound = 343.0f;  // m/s in air at 20 °C; world units are metres
constexpr ALfloat kDopplerFactor = 1.0f;   // physical Doppler, neither exaggerated nor damped

void check_finite(glm::vec3 v, const char* what) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
    throw Error(std::string("SoundScene: ") + what + " is not finite");
  }
}

}  // namespace

SoundScene::SoundScene(const SoundSceneDesc& desc) : impl_(std::make_unique<Impl>()) {
  impl_->loopback = desc.output == SoundOutput::loopback;
  if (impl_->loopback) {
    if (desc.loopback_sample_rate < 8000 || desc.loopback_sample_rate > 192000) {
      throw Error("SoundScene: loopback_sample_rate must be 8000..192000 Hz, got " +
                  std::to_string(desc.loopback_sample_rate));
    }
    impl_->al = audio::open_loopback_device(desc.loopback_sample_rate);
  } else {
    impl_->al = audio::open_output_device(desc.device_name);
  }
  if (!impl_->available()) {
    std::fprintf(stderr, "facet: %s; running silently\n", impl_->al.failure.c_str());
    return;
  }
  impl_->make_current();
  alDistanceModel(AL_INVERSE_DISTANCE_CLAMPED);
  alDopplerFactor(kDopplerFactor);
  alSpeedOfSound(kSpeedOfSound);
  // The listener starts as OpenAL's default: at the origin, looking down -Z with +Y up.
}

SoundScene::~SoundScene() = default;
SoundScene::SoundScene(SoundScene&&) noexcept = default;
SoundScene& SoundScene::operator=(SoundScene&&) noexcept = default;

SoundScene::Impl& SoundScene::impl() const {
  if (impl_ == nullptr) throw Error("SoundScene: used after being moved from");
  return *impl_;
}

bool SoundScene::available() const { return impl_ != nullptr && impl_->available(); }

int SoundScene::add_source(const SoundBuffer& buffer, glm::vec3 position, float gain,
                           float reference_distance) {
  if (buffer.sample_rate <= 0 || buffer.samples.empty()) {
    throw Error("SoundScene::add_source: the buffer needs samples and a positive sample rate");
  }
  if (buffer.samples.size() > static_cast<std::size_t>(std::numeric_limits<ALsizei>::max() / 2)) {
    throw Error("SoundScene::add_source: the buffer is too long for OpenAL");
  }
  if (!(gain >= 0.0f && std::isfinite(gain))) {
    throw Error("SoundScene::add_source: gain must be finite and >= 0");
  }
  if (!(reference_distance > 0.0f && std::isfinite(reference_distance))) {
    throw Error("SoundScene::add_source: reference_distance must be finite and > 0");
  }
  check_finite(position, "source position");
  Impl& scene = impl();
  if (!scene.available()) return scene.source_count++;

  scene.make_current();
  alGetError();  // clear anything left over, so the check below sees this call's own failure
  ALuint al_buffer = 0;
  alGenBuffers(1, &al_buffer);
  alBufferData(al_buffer, AL_FORMAT_MONO16, buffer.samples.data(),
               static_cast<ALsizei>(buffer.samples.size() * sizeof(std::int16_t)),
               buffer.sample_rate);
  ALuint source = 0;
  alGenSources(1, &source);
  alSourcei(source, AL_BUFFER, static_cast<ALint>(al_buffer));
  alSourcei(source, AL_LOOPING, AL_TRUE);
  alSourcef(source, AL_GAIN, gain);
  alSourcef(source, AL_REFERENCE_DISTANCE, reference_distance);
  alSourcef(source, AL_ROLLOFF_FACTOR, kRolloffFactor);
  alSource3f(source, AL_POSITION, position.x, position.y, position.z);
  if (alGetError() != AL_NO_ERROR) {  // e.g. out of sources: OpenAL Soft mixes at most 256
    alDeleteSources(1, &source);
    alDeleteBuffers(1, &al_buffer);
    throw Error("SoundScene::add_source: OpenAL could not create source " +
                std::to_string(scene.source_count));
  }
  scene.sources.push_back(source);
  scene.buffers.push_back(al_buffer);
  return scene.source_count++;
}

void SoundScene::set_source(int id, glm::vec3 position, glm::vec3 velocity) {
  check_finite(position, "source position");
  check_finite(velocity, "source velocity");
  const Impl& scene = impl();
  const ALuint source = scene.source(id);
  if (source == 0) return;
  scene.make_current();
  alSource3f(source, AL_POSITION, position.x, position.y, position.z);
  alSource3f(source, AL_VELOCITY, velocity.x, velocity.y, velocity.z);
}

void SoundScene::play(int id) {
  const Impl& scene = impl();
  const ALuint source = scene.source(id);
  if (source == 0) return;
  scene.make_current();
  ALint state = AL_STOPPED;
  alGetSourcei(source, AL_SOURCE_STATE, &state);
  if (state != AL_PLAYING) alSourcePlay(source);  // playing again would restart the loop
}

void SoundScene::stop(int id) {
  const Impl& scene = impl();
  const ALuint source = scene.source(id);
  if (source == 0) return;
  scene.make_current();
  alSourceStop(source);
}

void SoundScene::set_listener(glm::vec3 position, glm::vec3 forward, glm::vec3 up,
                              glm::vec3 velocity) {
  check_finite(position, "listener position");
  check_finite(forward, "listener forward");
  check_finite(up, "listener up");
  check_finite(velocity, "listener velocity");
  // OpenAL leaves a degenerate orientation undefined; the viewer's camera never has one.
  const glm::vec3 side = glm::cross(forward, up);
  if (glm::dot(side, side) <= 1e-12f * glm::dot(forward, forward) * glm::dot(up, up)) {
    throw Error("SoundScene::set_listener: forward and up must be non-zero and not parallel");
  }
  const Impl& scene = impl();
  if (!scene.available()) return;
  scene.make_current();
  const ALfloat orientation[] = {forward.x, forward.y, forward.z, up.x, up.y, up.z};
  alListener3f(AL_POSITION, position.x, position.y, position.z);
  alListener3f(AL_VELOCITY, velocity.x, velocity.y, velocity.z);
  alListenerfv(AL_ORIENTATION, orientation);
}

void SoundScene::set_muted(bool muted) {
  Impl& scene = impl();
  scene.muted = muted;
  if (!scene.available()) return;
  scene.make_current();
  alListenerf(AL_GAIN, muted ? 0.0f : 1.0f);
}

bool SoundScene::muted() const { return impl().muted; }

std::vector<float> SoundScene::render_loopback(int frames) {
  const Impl& scene = impl();
  if (!scene.loopback) {
    throw Error("SoundScene::render_loopback: the scene was not opened with SoundOutput::loopback");
  }
  if (frames < 0) throw Error("SoundScene::render_loopback: frames must be >= 0");
  std::vector<float> samples(static_cast<std::size_t>(frames) * 2, 0.0f);
  if (scene.available() && frames > 0) {
    scene.al.render_samples(scene.al.device, samples.data(), frames);
  }
  return samples;
}

}  // namespace facet
