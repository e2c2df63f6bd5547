// Opening and closing the OpenAL Soft device and context behind a SoundScene: the system's
// default output, or a loopback device whose mix the caller pulls (ALC_SOFT_loopback, for tests).
#pragma once

#include <AL/alc.h>
#include <AL/alext.h>

#include <string>

namespace facet::audio {

struct OpenAlDevice {
  ALCdevice* device = nullptr;
  ALCcontext* context = nullptr;                    // null: no device, the scene is silent
  LPALCRENDERSAMPLESSOFT render_samples = nullptr;  // loopback devices only
  std::string failure;                              // why context is null, for the warning line
};

// `name` empty: the default device. Never throws; a failure is reported in OpenAlDevice::failure.
OpenAlDevice open_output_device(const std::string& name);
// Stereo float at `sample_rate` Hz.
OpenAlDevice open_loopback_device(int sample_rate);
void close_device(OpenAlDevice& al);

}  // namespace facet::audio
