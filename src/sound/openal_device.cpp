// OpenAL Soft devices for SoundScene (sound_scene.cpp): the default output or a loopback device.
//
// On a machine without a sound card (servers, CI) OpenAL Soft 1.19 tries its backends in turn:
// PulseAudio finds no server and ALSA fails to open "default". alcOpenDevice then returns null,
// but not quietly: libasound prints about ten lines of configuration errors to stderr and
// OpenAL adds an "(EE)" line. SoundScene promises one warning line instead, so stderr points at
// /dev/null while a device opens (QuietStderr). FACET_SOUND_DEBUG=1 in the environment keeps
// those messages, for finding out why a machine that has a sound card stays silent.
#include "sound/openal_device.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace facet::audio {
namespace {

// Points file descriptor 2 at /dev/null for its lifetime. Anything another thread writes to
// stderr meanwhile is lost too; devices open once, at start-up, so that is acceptable.
class QuietStderr {
 public:
  QuietStderr() {
    if (std::getenv("FACET_SOUND_DEBUG") != nullptr) return;
    std::fflush(stderr);
    const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null_fd < 0) return;
    saved_fd_ = ::dup(STDERR_FILENO);
    if (saved_fd_ >= 0) ::dup2(null_fd, STDERR_FILENO);
    ::close(null_fd);
  }
  ~QuietStderr() {
    if (saved_fd_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_fd_, STDERR_FILENO);
    ::close(saved_fd_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_fd_ = -1;
};

// Extension entry points come as void*; memcpy converts to the function pointer type without the
// object-to-function pointer cast that ISO C++ only conditionally supports.
template <class Function>
Function extension_function(const char* name) {
  void* address = alcGetProcAddress(nullptr, name);
  Function function = nullptr;
  static_assert(sizeof(function) == sizeof(address));
  std::memcpy(&function, &address, sizeof(function));
  return function;
}

OpenAlDevice failed(OpenAlDevice& al, std::string why) {
  close_device(al);
  al.failure = std::move(why);
  return std::move(al);
}

}  // namespace

OpenAlDevice open_output_device(const std::string& name) {
  OpenAlDevice al;
  {
    QuietStderr quiet;
    al.device = alcOpenDevice(name.empty() ? nullptr : name.c_str());
    if (al.device != nullptr) al.context = alcCreateContext(al.device, nullptr);
  }
  const std::string which = name.empty() ? "" : " \"" + name + "\"";
  if (al.device == nullptr) return failed(al, "no audio device" + which);
  if (al.context == nullptr) return failed(al, "audio device" + which + " has no context");
  alcMakeContextCurrent(al.context);
  return al;
}

OpenAlDevice open_loopback_device(int sample_rate) {
  OpenAlDevice al;
  QuietStderr quiet;
  if (alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback") != ALC_TRUE) {
    return failed(al, "OpenAL has no loopback device (ALC_SOFT_loopback)");
  }
  const auto open_loopback =
      extension_function<LPALCLOOPBACKOPENDEVICESOFT>("alcLoopbackOpenDeviceSOFT");
  const auto format_supported =
      extension_function<LPALCISRENDERFORMATSUPPORTEDSOFT>("alcIsRenderFormatSupportedSOFT");
  al.render_samples = extension_function<LPALCRENDERSAMPLESSOFT>("alcRenderSamplesSOFT");
  if (open_loopback == nullptr || format_supported == nullptr || al.render_samples == nullptr) {
    return failed(al, "OpenAL lists ALC_SOFT_loopback but lacks its functions");
  }
  al.device = open_loopback(nullptr);
  if (al.device == nullptr) return failed(al, "OpenAL could not open a loopback device");
  if (format_supported(al.device, sample_rate, ALC_STEREO_SOFT, ALC_FLOAT_SOFT) != ALC_TRUE) {
    return failed(
        al, "OpenAL loopback cannot render stereo float at " + std::to_string(sample_rate) + " Hz");
  }
  const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT,
                               ALC_STEREO_SOFT,
                               ALC_FORMAT_TYPE_SOFT,
                               ALC_FLOAT_SOFT,
                               ALC_FREQUENCY,
                               sample_rate,
                               0};
  al.context = alcCreateContext(al.device, attributes);
  if (al.context == nullptr) return failed(al, "OpenAL loopback device has no context");
  alcMakeContextCurrent(al.context);
  return al;
}

void close_device(OpenAlDevice& al) {
  if (al.context != nullptr) {
    if (alcGetCurrentContext() == al.context) alcMakeContextCurrent(nullptr);
    alcDestroyContext(al.context);
    al.context = nullptr;
  }
  if (al.device != nullptr) {
    alcCloseDevice(al.device);
    al.device = nullptr;
  }
  al.render_samples = nullptr;
}

}  // namespace facet::audio
