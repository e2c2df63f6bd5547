// Stage: output, cleared rows into the framebuffer (see framebuffer_rows.hpp).
#include "pipeline/output/framebuffer_rows.hpp"

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facet::pipeline {

#if defined(__SSE2__)
namespace {

// Copies the row with streaming stores. Only whole cache lines are streamed: a part of a line
// written around the caches costs a read of the rest in memory. The values before the first whole
// line and after the last go through the caches.
void stream_row(void* out, const void* row, std::size_t bytes) {
  auto* to = static_cast<std::uint8_t*>(out);
  const auto* from = static_cast<const std::uint8_t*>(row);
  std::size_t b = 0;
  for (; b < bytes && reinterpret_cast<std::uintptr_t>(to + b) % 64 != 0; b += 4) {
    std::memcpy(to + b, from + b, 4);
  }
  for (; b + 64 <= bytes; b += 64) {
    for (std::size_t part = b; part < b + 64; part += 16) {
      _mm_stream_si128(reinterpret_cast<__m128i*>(to + part),
                       _mm_loadu_si128(reinterpret_cast<const __m128i*>(from + part)));
    }
  }
  std::memcpy(to + b, from + b, bytes - b);
}

}  // namespace
#endif

bool streams_cleared_rows(std::size_t image_bytes) {
#if defined(__SSE2__)
  return image_bytes >= kStreamedImageBytes;
#else
  static_cast<void>(image_bytes);
  return false;
#endif
}

void write_cleared_row(void* out, const void* row, std::size_t bytes, bool streaming) {
#if defined(__SSE2__)
  if (streaming) {
    stream_row(out, row, bytes);
    return;
  }
#else
  static_cast<void>(streaming);  // streams_cleared_rows() is false without streaming stores
#endif
  if (std::memcmp(out, row, bytes) != 0) std::memcpy(out, row, bytes);
}

void end_streamed_rows() {
#if defined(__SSE2__)
  _mm_sfence();
#endif
}

}  // namespace facet::pipeline
