// A cheap steady count of time for timings that only enter as shares of a measured whole (the
// tiles' resolve time over their whole time, FrameStats::ms_resolve): the CPU's time-stamp
// counter where there is one, read in a few cycles, where the clock is a call. Any unit does.
#pragma once

#include <chrono>
#include <cstdint>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace facet {

inline std::uint64_t tick_count() {
#if defined(__x86_64__) || defined(__i386__)
  return __rdtsc();
#else
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

// The ticks from `start` to now; 0 if the count went back (a counter not kept in step across
// cores).
inline std::uint64_t ticks_since(std::uint64_t start) {
  const std::uint64_t now = tick_count();
  return now > start ? now - start : 0;
}

}  // namespace facet
